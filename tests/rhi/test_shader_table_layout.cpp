#include <catch2/catch_test_macros.hpp>

#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using namespace penumbra::rhi;

namespace {
// The alignment rules of each API as the backends report them.
constexpr ShaderTableAlignment kD3D12{32, 32, 64, 4096};       // D3D12_* constants
constexpr ShaderTableAlignment kLavapipe{32, 16, 32, 4096};    // llvmpipe's properties
constexpr ShaderTableAlignment kNvidia{32, 32, 64, 4096};      // typical NVIDIA properties

void requireWellFormed(const ShaderTableLayout& l, const ShaderTableAlignment& a) {
  for (const auto* r : {&l.rayGeneration, &l.miss, &l.hitGroup}) {
    REQUIRE(r->offset % a.tableAlignment == 0);
    REQUIRE(r->stride % a.recordAlignment == 0);
    REQUIRE(r->stride >= a.handleSize);
    REQUIRE(r->size == r->stride * r->count);
    REQUIRE(r->offset + r->size <= l.totalBytes);
  }
  // Regions never overlap.
  if (l.miss.count) REQUIRE(l.rayGeneration.offset + l.rayGeneration.size <= l.miss.offset);
  if (l.miss.count && l.hitGroup.count) REQUIRE(l.miss.offset + l.miss.size <= l.hitGroup.offset);
  REQUIRE(l.totalBytes % a.tableAlignment == 0);
}
}  // namespace

TEST_CASE("shader table layout: identifiers only", "[rhi][shader-table]") {
  for (const auto& a : {kD3D12, kLavapipe, kNvidia}) {
    auto l = computeShaderTableLayout(a, 0, 2, 0, 3, 0);
    requireWellFormed(l, a);
    REQUIRE(l.rayGeneration.offset == 0);
    REQUIRE(l.rayGeneration.stride == 32);
    REQUIRE(l.rayGeneration.size == 32);  // Vulkan: raygen size must equal its stride
    REQUIRE(l.miss.stride == 32);
    REQUIRE(l.miss.offset == alignUp(32, a.tableAlignment));
    REQUIRE(l.hitGroup.offset == alignUp(l.miss.offset + 64, a.tableAlignment));
  }
}

TEST_CASE("shader table layout: local data rounds records up per API", "[rhi][shader-table]") {
  // 32-byte identifier + 4 bytes of local constants.
  auto d3d = computeShaderTableLayout(kD3D12, 0, 1, 4, 5, 4);
  requireWellFormed(d3d, kD3D12);
  REQUIRE(d3d.hitGroup.stride == 64);  // 36 rounded to D3D12's 32-byte record alignment
  REQUIRE(d3d.miss.offset == 64);
  REQUIRE(d3d.hitGroup.offset == 128);
  REQUIRE(d3d.totalBytes == alignUp(128 + 5 * 64, 64));

  auto lvp = computeShaderTableLayout(kLavapipe, 0, 1, 4, 5, 4);
  requireWellFormed(lvp, kLavapipe);
  REQUIRE(lvp.hitGroup.stride == 48);  // 36 rounded to 16
  REQUIRE(lvp.miss.offset == 32);
  REQUIRE(lvp.hitGroup.offset == 96);  // 32 + 48 = 80, aligned to 32
}

TEST_CASE("shader table layout: empty regions take no space", "[rhi][shader-table]") {
  auto l = computeShaderTableLayout(kD3D12, 0, 0, 0, 0, 0);
  REQUIRE(l.miss.size == 0);
  REQUIRE(l.hitGroup.size == 0);
  REQUIRE(l.totalBytes == 64);
}

TEST_CASE("shader table layout: oversized records are an error", "[rhi][shader-table]") {
  REQUIRE_THROWS_AS(computeShaderTableLayout(kD3D12, 0, 1, 0, 1, 5000), Error);
}
