// The binding-layout -> D3D12 root signature mapping (engine/penumbra/rhi/
// root_signature_layout.h), which the D3D12 backend turns into
// D3D12_ROOT_PARAMETER1s. Runs anywhere: no D3D12 needed.
#include <fmt/format.h>

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "path_tracer_shared.h"
#include "penumbra/render/shader_binding_offsets.h"
#include "penumbra/rhi/binding_layout.h"
#include "penumbra/rhi/root_signature_layout.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"
#include "penumbra_test_shaders.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

namespace {
// The shaders' offsets: the cases below name registers by bindings.hlsli's
// macros, as the shaders do.
constexpr BindingOffsets kOffsets = render::kShaderBindingOffsets;

BindingLayoutItem item(uint32_t slot, ResourceType type, bool writable = false,
                       uint32_t arraySize = 1) {
  BindingLayoutItem i;
  i.slot = slot;
  i.type = type;
  i.writable = writable;
  i.arraySize = arraySize;
  i.name = fmt::format("g{}", slot);
  return i;
}
}  // namespace

TEST_CASE(
    "root signature: the path tracer's layout maps to root constants, one table and the bindless "
    "tables",
    "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  for (const char* name :
       {"path_trace.rgen", "whitted.rgen", "probe.rgen", "path_trace.rmiss", "triangle.rchit",
        "triangle_alpha.rahit", "implicit.rchit", "implicit_sphere.rint", "implicit_plane_box.rint",
        "implicit_sdf.rint", "implicit_fractal.rint"})
    mergeBindingLayout(layout, shaders::shaderDesc(name).bindingLayout, name);
  const RootSignatureLayout rs = computeRootSignatureLayout(layout, kOffsets);

  REQUIRE(rs.pushConstants);
  CHECK(rs.pushConstants->rootParameterIndex == 0);
  CHECK(rs.pushConstants->shaderRegister == 0);
  CHECK(rs.pushConstants->registerSpace == kOffsets.pushConstantSpace);
  CHECK(rs.pushConstants->num32BitValues == sizeof(gpu::FrameConstants) / 4);
  // The bounded views, then the bindless textures (t18[], the highest t
  // register: an unbounded range covers every register above it) and the
  // bindless samplers, each in a table of its own.
  REQUIRE(rs.tables.size() == 3);
  const auto& table = rs.tables[0];
  CHECK(table.space == 0);
  CHECK(table.rootParameterIndex == 1);
  CHECK(table.descriptorCount == 25);
  CHECK(rs.parameterCount() == 4);
  CHECK(rs.dwordCost == 32 + 3);  // 128 bytes of root constants + three tables
  const auto* textures = rs.tableForSlot(0, PT_SLOT_TEXTURES);
  REQUIRE(textures);
  CHECK(textures->unbounded);
  CHECK(textures->heap == DescriptorHeapKind::CbvSrvUav);
  const auto* samplers = rs.tableForSlot(0, PT_SLOT_SAMPLERS);
  REQUIRE(samplers);
  CHECK(samplers->unbounded);
  CHECK(samplers->heap == DescriptorHeapKind::Sampler);

  // t0..t17 are SRVs (TLAS + read-only structured buffers), u0..u6 UAVs, in slot order.
  const auto* scene = table.rangeForSlot(PT_SLOT_SCENE);
  REQUIRE(scene);
  CHECK(scene->type == DescriptorRangeType::SRV);
  CHECK(scene->baseRegister == 0);
  CHECK(scene->offsetInTable == 0);
  const auto* emissive = table.rangeForSlot(PT_SLOT_EMISSIVE_TRIANGLES);
  REQUIRE(emissive);
  CHECK(emissive->type == DescriptorRangeType::SRV);
  CHECK(emissive->baseRegister == 5);
  CHECK(emissive->offsetInTable == 5);
  const auto* pointLights = table.rangeForSlot(PT_SLOT_POINT_LIGHTS);
  REQUIRE(pointLights);
  CHECK(pointLights->type == DescriptorRangeType::SRV);
  CHECK(pointLights->baseRegister == 6);
  CHECK(pointLights->offsetInTable == 6);
  const auto* texcoords = table.rangeForSlot(PT_SLOT_TEXCOORDS);
  REQUIRE(texcoords);
  CHECK(texcoords->type == DescriptorRangeType::SRV);
  CHECK(texcoords->baseRegister == 9);
  CHECK(texcoords->offsetInTable == 9);
  const auto* implicits = table.rangeForSlot(PT_SLOT_IMPLICITS);
  REQUIRE(implicits);
  CHECK(implicits->type == DescriptorRangeType::SRV);
  CHECK(implicits->baseRegister == 10);
  CHECK(implicits->offsetInTable == 10);
  const auto* probeRays = table.rangeForSlot(PT_SLOT_PROBE_RAYS);
  REQUIRE(probeRays);
  CHECK(probeRays->type == DescriptorRangeType::SRV);
  CHECK(probeRays->baseRegister == 11);
  CHECK(probeRays->offsetInTable == 11);
  const auto* textureRefs = table.rangeForSlot(PT_SLOT_TEXTURE_REFS);
  REQUIRE(textureRefs);
  CHECK(textureRefs->type == DescriptorRangeType::SRV);
  CHECK(textureRefs->baseRegister == 12);
  CHECK(textureRefs->offsetInTable == 12);
  const auto* environmentCdf = table.rangeForSlot(PT_SLOT_ENVIRONMENT_CDF);
  REQUIRE(environmentCdf);
  CHECK(environmentCdf->type == DescriptorRangeType::SRV);
  CHECK(environmentCdf->baseRegister == 15);
  CHECK(environmentCdf->offsetInTable == 15);
  const auto* colors = table.rangeForSlot(PT_SLOT_COLORS);
  REQUIRE(colors);
  CHECK(colors->type == DescriptorRangeType::SRV);
  CHECK(colors->baseRegister == 16);
  CHECK(colors->offsetInTable == 16);
  const auto* sheenAlbedo = table.rangeForSlot(PT_SLOT_SHEEN_ALBEDO);
  REQUIRE(sheenAlbedo);
  CHECK(sheenAlbedo->type == DescriptorRangeType::SRV);
  CHECK(sheenAlbedo->baseRegister == 17);
  CHECK(sheenAlbedo->offsetInTable == 17);
  const auto* accumulation = table.rangeForSlot(PT_SLOT_ACCUMULATION);
  REQUIRE(accumulation);
  CHECK(accumulation->type == DescriptorRangeType::UAV);
  CHECK(accumulation->baseRegister == 0);
  CHECK(accumulation->offsetInTable == 18);
  const auto* counter = table.rangeForSlot(PT_SLOT_RAY_COUNTER);
  REQUIRE(counter);
  CHECK(counter->type == DescriptorRangeType::UAV);
  CHECK(counter->baseRegister == 1);
  CHECK(counter->offsetInTable == 19);
  const auto* probeHits = table.rangeForSlot(PT_SLOT_PROBE_HITS);
  REQUIRE(probeHits);
  CHECK(probeHits->type == DescriptorRangeType::UAV);
  CHECK(probeHits->baseRegister == 2);
  CHECK(probeHits->offsetInTable == 20);
  // The denoiser's guide buffers, u3..u6.
  uint32_t offset = 21;
  for (uint32_t guide : {uint32_t(PT_SLOT_GUIDE_ALBEDO), uint32_t(PT_SLOT_GUIDE_NORMAL_DEPTH),
                         uint32_t(PT_SLOT_GUIDE_EMISSION), uint32_t(PT_SLOT_GUIDE_MOMENTS)}) {
    const auto* range = table.rangeForSlot(guide);
    REQUIRE(range);
    CHECK(range->type == DescriptorRangeType::UAV);
    CHECK(range->baseRegister == offset - 18);
    CHECK(range->offsetInTable == offset);
    offset += 1;
  }
}

TEST_CASE("root signature: spaces become tables in space order, arrays take several descriptors",
          "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  addBindingLayoutItem(layout, 2, item(PENUMBRA_B(3), ResourceType::ConstantBuffer), "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_T(1), ResourceType::StorageBuffer, false, 4),
                       "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_U(2), ResourceType::StorageTexture, true), "test");
  const RootSignatureLayout rs = computeRootSignatureLayout(layout, kOffsets);

  CHECK_FALSE(rs.pushConstants);
  REQUIRE(rs.tables.size() == 2);  // space 1 is empty: no table
  CHECK(rs.tables[0].space == 0);
  CHECK(rs.tables[0].rootParameterIndex == 0);
  CHECK(rs.tables[0].descriptorCount == 5);
  CHECK(rs.tables[0].ranges[0].count == 4);
  CHECK(rs.tables[0].ranges[1].offsetInTable == 4);
  CHECK(rs.tables[0].ranges[1].type == DescriptorRangeType::UAV);
  CHECK(rs.tables[0].ranges[1].baseRegister == 2);
  CHECK(rs.tables[1].space == 2);
  CHECK(rs.tables[1].rootParameterIndex == 1);
  CHECK(rs.tables[1].ranges[0].type == DescriptorRangeType::CBV);
  CHECK(rs.tables[1].ranges[0].baseRegister == 3);
  CHECK(rs.tableForSpace(1) == nullptr);
  CHECK(rs.tableForSpace(2) == &rs.tables[1]);
}

TEST_CASE("root signature: samplers get a table of their own, unbounded arrays one each",
          "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  layout.pushConstantBytes = 4;
  addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::StorageBuffer), "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_T(1), ResourceType::SampledTexture, false, 2),
                       "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_T(12), ResourceType::SampledTexture, false, 0),
                       "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_U(0), ResourceType::StorageBuffer, true), "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_S(0), ResourceType::Sampler, false, 0), "test");
  addBindingLayoutItem(layout, 1, item(PENUMBRA_S(2), ResourceType::Sampler, false, 3), "test");
  const RootSignatureLayout rs = computeRootSignatureLayout(layout, kOffsets);

  // Space 0: views (t0, t1[2], u0), then the unbounded t12[] and s0[]; space 1: samplers.
  REQUIRE(rs.tables.size() == 4);
  CHECK(rs.parameterCount() == 5);
  CHECK(rs.dwordCost == 1 + 4);
  const auto& views = rs.tables[0];
  CHECK(views.space == 0);
  CHECK(views.rootParameterIndex == 1);
  CHECK(views.heap == DescriptorHeapKind::CbvSrvUav);
  CHECK_FALSE(views.unbounded);
  CHECK(views.descriptorCount == 4);
  REQUIRE(views.ranges.size() == 3);
  CHECK(views.ranges[1].type == DescriptorRangeType::SRV);  // Texture2D gTextures[2] : register(t1)
  CHECK(views.ranges[1].count == 2);
  CHECK(views.ranges[2].offsetInTable == 3);
  CHECK(rs.tableForSpace(0) == &views);

  const auto& textures = rs.tables[1];
  CHECK(textures.space == 0);
  CHECK(textures.rootParameterIndex == 2);
  CHECK(textures.heap == DescriptorHeapKind::CbvSrvUav);
  CHECK(textures.unbounded);
  CHECK(textures.descriptorCount == 0);
  REQUIRE(textures.ranges.size() == 1);
  CHECK(textures.ranges[0].type == DescriptorRangeType::SRV);
  CHECK(textures.ranges[0].baseRegister == 12);
  CHECK(textures.ranges[0].count == kUnboundedDescriptors);
  CHECK(textures.ranges[0].offsetInTable == 0);
  CHECK(rs.tableForSlot(0, PENUMBRA_T(12)) == &textures);

  const auto& samplers = rs.tables[2];
  CHECK(samplers.rootParameterIndex == 3);
  CHECK(samplers.heap == DescriptorHeapKind::Sampler);
  CHECK(samplers.unbounded);
  CHECK(samplers.ranges[0].type == DescriptorRangeType::Sampler);
  CHECK(samplers.ranges[0].baseRegister == 0);
  CHECK(samplers.ranges[0].count == kUnboundedDescriptors);
  CHECK(rs.tableForSlot(0, PENUMBRA_S(0)) == &samplers);

  const auto& fixedSamplers = rs.tables[3];
  CHECK(fixedSamplers.space == 1);
  CHECK(fixedSamplers.rootParameterIndex == 4);
  CHECK(fixedSamplers.heap == DescriptorHeapKind::Sampler);
  CHECK_FALSE(fixedSamplers.unbounded);
  CHECK(fixedSamplers.descriptorCount == 3);
  CHECK(fixedSamplers.ranges[0].baseRegister == 2);
  CHECK(rs.tableForSpace(1) == nullptr);  // no views in space 1
  CHECK(rs.tableForSlot(1, PENUMBRA_S(2)) == &fixedSamplers);
  CHECK(rs.tableForSlot(1, PENUMBRA_S(0)) == nullptr);
}

TEST_CASE("root signature: the bindless texture shader's layout", "[rhi][root-signature]") {
  const RootSignatureLayout rs = computeRootSignatureLayout(
      test_shaders::shaderDesc("texture_sample.comp").bindingLayout, kOffsets);
  REQUIRE(rs.pushConstants);
  REQUIRE(rs.tables.size() == 3);  // t0 + u0; t12[]; s0[]
  CHECK(rs.tables[0].descriptorCount == 2);
  CHECK(rs.tables[1].ranges[0].baseRegister == 12);
  CHECK(rs.tables[1].ranges[0].count == kUnboundedDescriptors);
  CHECK(rs.tables[2].heap == DescriptorHeapKind::Sampler);
}

TEST_CASE("root signature: bindings D3D12 cannot express are refused by name",
          "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  SECTION("a written resource in the t registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::StorageBuffer, true), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("g32") && ContainsSubstring("register t0"));
  }
  SECTION("a constant buffer outside the b registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::ConstantBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("constant buffer"));
  }
  SECTION("an acceleration structure in the u registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_U(0), ResourceType::AccelStruct), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("acceleration structure"));
  }
  SECTION("a sampler register") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_S(0), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets), ContainsSubstring("sampler"));
  }
  SECTION("a sampler outside the s registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::Sampler), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("sampler outside the s registers"));
  }
  SECTION("a sampled texture outside the t registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_B(1), ResourceType::SampledTexture), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("sampled texture outside"));
  }
  SECTION("an unbounded array below another register of its class") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(4), ResourceType::SampledTexture, false, 0),
                         "test");
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(7), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(
        computeRootSignatureLayout(layout, kOffsets),
        ContainsSubstring("g36") && ContainsSubstring("overlap") && ContainsSubstring("g39"));
  }
  SECTION("the reserved root-constant space") {
    addBindingLayoutItem(layout, kOffsets.pushConstantSpace,
                         item(PENUMBRA_T(0), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("reserved"));
  }
  SECTION("more than 64 DWORDs") {
    layout.pushConstantBytes = 256;  // 64 DWORDs on their own
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("65 DWORDs"));
  }
  SECTION("push constants that are not whole DWORDs") {
    layout.pushConstantBytes = 6;
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout, kOffsets),
                        ContainsSubstring("whole DWORDs"));
  }
}

TEST_CASE("root signature: shader records become local root constants", "[rhi][root-signature]") {
  const RootConstantsLayout local = computeShaderRecordConstants(6, kOffsets);
  CHECK(local.num32BitValues == 2);
  CHECK(local.registerSpace == kOffsets.shaderRecordSpace);
  CHECK(local.shaderRegister == 0);
  CHECK(kOffsets.shaderRecordSpace != kOffsets.pushConstantSpace);
}

TEST_CASE("root signature: registers and spaces follow the device's binding offsets",
          "[rhi][root-signature]") {
  // Offsets unlike the shaders' (NVRHI's defaults, spaces 7 and 8): the same
  // binding numbers name other registers, so nothing in the RHI may assume
  // bindings.hlsli's numbers.
  constexpr BindingOffsets other{.constantBuffer = 0,
                                 .shaderResource = 128,
                                 .unorderedAccess = 256,
                                 .sampler = 384,
                                 .pushConstantSpace = 7,
                                 .shaderRecordSpace = 8};
  static_assert(other.valid());
  CHECK(other.registerForBinding(130).registerClass == RegisterClass::T);
  CHECK(other.registerForBinding(130).index == 2);
  CHECK(other.registerForBinding(100).registerClass == RegisterClass::B);
  CHECK(other.registerForBinding(100).index == 100);
  CHECK(other.registerForBinding(390).registerClass == RegisterClass::S);

  PipelineBindingLayout layout;
  layout.pushConstantBytes = 16;
  addBindingLayoutItem(layout, 0, item(130, ResourceType::StorageBuffer), "test");
  addBindingLayoutItem(layout, 0, item(257, ResourceType::StorageTexture, true), "test");
  const RootSignatureLayout rs = computeRootSignatureLayout(layout, other);
  REQUIRE(rs.pushConstants);
  CHECK(rs.pushConstants->registerSpace == 7);
  REQUIRE(rs.tables.size() == 1);
  REQUIRE(rs.tables[0].ranges.size() == 2);
  CHECK(rs.tables[0].ranges[0].type == DescriptorRangeType::SRV);
  CHECK(rs.tables[0].ranges[0].baseRegister == 2);
  CHECK(rs.tables[0].ranges[1].type == DescriptorRangeType::UAV);
  CHECK(rs.tables[0].ranges[1].baseRegister == 1);
  CHECK(computeShaderRecordConstants(4, other).registerSpace == 8);

  // Space 7 is now reserved; the shaders' 900 is an ordinary space.
  PipelineBindingLayout reserved;
  addBindingLayoutItem(reserved, 7, item(130, ResourceType::StorageBuffer), "test");
  REQUIRE_THROWS_WITH(computeRootSignatureLayout(reserved, other), ContainsSubstring("reserved"));
  PipelineBindingLayout ordinary;
  addBindingLayoutItem(ordinary, 900, item(130, ResourceType::StorageBuffer), "test");
  CHECK(computeRootSignatureLayout(ordinary, other).tables.size() == 1);

  // Out of order, or one space for both kinds of root constants: not valid,
  // and backends::createDevice refuses them (tests/rhi/test_device_lifetimes.cpp).
  CHECK_FALSE(BindingOffsets{}.valid());
  BindingOffsets sameSpace = other;
  sameSpace.shaderRecordSpace = sameSpace.pushConstantSpace;
  CHECK_FALSE(sameSpace.valid());
  BindingOffsets swapped = other;
  std::swap(swapped.unorderedAccess, swapped.sampler);
  CHECK_FALSE(swapped.valid());
}
