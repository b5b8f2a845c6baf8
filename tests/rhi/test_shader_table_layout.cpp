#include <catch2/catch_test_macros.hpp>
#include <cstring>
#include <memory>
#include <vector>

#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/rhi/shader_table_records.h"
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

namespace {
// Host memory at a chosen "device address", standing in for a backend's
// upload buffer.
class HostBuffer final : public IBuffer {
 public:
  HostBuffer(const BufferDesc& desc, uint64_t address)
      : desc_(desc), address_(address), bytes_(desc.byteSize) {}
  const BufferDesc& desc() const override { return desc_; }
  uint64_t deviceAddress() const override { return address_; }
  void* mappedData() override { return bytes_.data(); }
  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  BufferDesc desc_;
  uint64_t address_;
  std::vector<uint8_t> bytes_;
};

// ShaderTableRecords with upload() reachable, identifiers 32 bytes of the
// export name's first letter.
class TestTable final : public ShaderTableRecords {
 public:
  using ShaderTableRecords::uploadBuffer;
  int uploads = 0;
  std::shared_ptr<HostBuffer> last;
  const ShaderTableRanges& prepare(const ShaderTableAlignment& alignment) {
    return upload(
        alignment, "test table",
        [&](const BufferDesc& desc) {
          ++uploads;
          last = std::make_shared<HostBuffer>(desc, 0x100000 * uploads);
          return last;
        },
        [&](const std::string& name) {
          identifiers_.push_back(std::vector<uint8_t>(32, uint8_t(name[0])));
          return static_cast<const void*>(identifiers_.back().data());
        });
  }

 private:
  std::vector<std::vector<uint8_t>> identifiers_;
};
}  // namespace

TEST_CASE("shader table records: upload writes each record where its range says",
          "[rhi][shader-table]") {
  TestTable table;
  const uint32_t rayGenData = 0xabcd1234u;
  table.setRayGenerationShader("r", &rayGenData, sizeof(rayGenData));
  table.addMissShader("m", nullptr, 0);
  table.addMissShader("n", nullptr, 0);
  const uint32_t hitData[2] = {7, 9};
  table.addHitGroup("h", hitData, sizeof(hitData));

  const ShaderTableRanges ranges = table.prepare(kD3D12);
  REQUIRE(table.uploads == 1);
  const BufferDesc& desc = table.last->desc();
  CHECK(desc.usage == BufferUsage::ShaderTable);
  CHECK(desc.memory == MemoryLocation::Upload);
  // Ray generation: one 64-byte record (32 identifier + 4 data, rounded to 32).
  CHECK(ranges.rayGeneration.address == 0x100000);
  CHECK(ranges.rayGeneration.stride == 64);
  CHECK(ranges.rayGeneration.size == 64);
  // Miss: two 32-byte records from the next 64-byte boundary.
  CHECK(ranges.miss.address == 0x100000 + 64);
  CHECK(ranges.miss.stride == 32);
  CHECK(ranges.miss.size == 64);
  CHECK(ranges.hitGroup.address == 0x100000 + 128);
  CHECK(ranges.hitGroup.stride == 64);
  CHECK(ranges.hitGroup.size == 64);

  const std::vector<uint8_t>& bytes = table.last->bytes();
  auto at = [&](uint64_t address) { return bytes.at(size_t(address - 0x100000)); };
  CHECK(at(ranges.rayGeneration.address) == 'r');
  CHECK(at(ranges.rayGeneration.address + 31) == 'r');
  uint32_t readBack = 0;
  std::memcpy(&readBack, &bytes[32], 4);
  CHECK(readBack == rayGenData);
  CHECK(at(ranges.miss.address) == 'm');
  CHECK(at(ranges.miss.address + ranges.miss.stride) == 'n');
  CHECK(at(ranges.hitGroup.address) == 'h');
  uint32_t hit[2] = {};
  std::memcpy(hit, &bytes[size_t(ranges.hitGroup.address - 0x100000) + 32], sizeof(hit));
  CHECK(hit[0] == 7);
  CHECK(hit[1] == 9);

  // Unchanged: no new buffer, the same ranges.
  CHECK(table.prepare(kD3D12).miss.address == ranges.miss.address);
  CHECK(table.uploads == 1);
  // A change uploads a fresh buffer (a list in flight keeps the old one).
  table.clearMissShaders();
  const ShaderTableRanges after = table.prepare(kD3D12);
  CHECK(table.uploads == 2);
  CHECK(after.rayGeneration.address == 0x200000);
  CHECK(after.miss.address == 0);  // empty region: all zero
  CHECK(after.miss.size == 0);
  CHECK(table.uploadBuffer() == table.last);
}
