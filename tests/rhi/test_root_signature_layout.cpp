// The binding-layout -> D3D12 root signature mapping (engine/rhi/
// root_signature_layout.h), which the D3D12 backend turns into
// D3D12_ROOT_PARAMETER1s. Runs anywhere: no D3D12 needed.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <fmt/format.h>

#include "path_tracer_shared.h"
#include "penumbra_shaders.h"
#include "rhi/binding_layout.h"
#include "rhi/register_shifts.h"
#include "rhi/root_signature_layout.h"
#include "util/error.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

namespace {
BindingLayoutItem item(uint32_t slot, ResourceType type, bool writable = false, uint32_t arraySize = 1) {
  BindingLayoutItem i;
  i.slot = slot;
  i.type = type;
  i.writable = writable;
  i.arraySize = arraySize;
  i.name = fmt::format("g{}", slot);
  return i;
}
}  // namespace

TEST_CASE("root signature: the path tracer's layout maps to root constants and one table",
          "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  for (const char* name :
       {"path_trace.rgen", "whitted.rgen", "path_trace.rmiss", "shadow.rmiss", "triangle.rchit"})
    mergeBindingLayout(layout, shaders::shaderDesc(name).bindingLayout, name);
  const RootSignatureLayout rs = computeRootSignatureLayout(layout);

  REQUIRE(rs.pushConstants);
  CHECK(rs.pushConstants->rootParameterIndex == 0);
  CHECK(rs.pushConstants->shaderRegister == 0);
  CHECK(rs.pushConstants->registerSpace == kPushConstantSpace);
  CHECK(rs.pushConstants->num32BitValues == sizeof(gpu::FrameConstants) / 4);
  REQUIRE(rs.tables.size() == 1);
  const auto& table = rs.tables[0];
  CHECK(table.space == 0);
  CHECK(table.rootParameterIndex == 1);
  CHECK(table.descriptorCount == 12);
  CHECK(rs.parameterCount() == 2);
  CHECK(rs.dwordCost == 32 + 1);  // 128 bytes of root constants + one table

  // t0..t9 are SRVs (TLAS + read-only structured buffers), u0/u1 UAVs, in slot order.
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
  const auto* accumulation = table.rangeForSlot(PT_SLOT_ACCUMULATION);
  REQUIRE(accumulation);
  CHECK(accumulation->type == DescriptorRangeType::UAV);
  CHECK(accumulation->baseRegister == 0);
  CHECK(accumulation->offsetInTable == 10);
  const auto* counter = table.rangeForSlot(PT_SLOT_RAY_COUNTER);
  REQUIRE(counter);
  CHECK(counter->type == DescriptorRangeType::UAV);
  CHECK(counter->baseRegister == 1);
  CHECK(counter->offsetInTable == 11);
}

TEST_CASE("root signature: spaces become tables in space order, arrays take several descriptors",
          "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  addBindingLayoutItem(layout, 2, item(PENUMBRA_B(3), ResourceType::ConstantBuffer), "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_T(1), ResourceType::StorageBuffer, false, 4), "test");
  addBindingLayoutItem(layout, 0, item(PENUMBRA_U(2), ResourceType::StorageTexture, true), "test");
  const RootSignatureLayout rs = computeRootSignatureLayout(layout);

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

TEST_CASE("root signature: bindings D3D12 cannot express are refused by name", "[rhi][root-signature]") {
  PipelineBindingLayout layout;
  SECTION("a written resource in the t registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::StorageBuffer, true), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout),
                        ContainsSubstring("g32") && ContainsSubstring("register t0"));
  }
  SECTION("a constant buffer outside the b registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::ConstantBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout), ContainsSubstring("constant buffer"));
  }
  SECTION("an acceleration structure in the u registers") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_U(0), ResourceType::AccelStruct), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout), ContainsSubstring("acceleration structure"));
  }
  SECTION("a sampler register") {
    addBindingLayoutItem(layout, 0, item(PENUMBRA_S(0), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout), ContainsSubstring("sampler"));
  }
  SECTION("the reserved root-constant space") {
    addBindingLayoutItem(layout, kPushConstantSpace, item(PENUMBRA_T(0), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout), ContainsSubstring("reserved"));
  }
  SECTION("more than 64 DWORDs") {
    layout.pushConstantBytes = 256;  // 64 DWORDs on their own
    addBindingLayoutItem(layout, 0, item(PENUMBRA_T(0), ResourceType::StorageBuffer), "test");
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout), ContainsSubstring("65 DWORDs"));
  }
  SECTION("push constants that are not whole DWORDs") {
    layout.pushConstantBytes = 6;
    REQUIRE_THROWS_WITH(computeRootSignatureLayout(layout), ContainsSubstring("whole DWORDs"));
  }
}

TEST_CASE("root signature: shader records become local root constants", "[rhi][root-signature]") {
  const RootConstantsLayout local = computeShaderRecordConstants(6);
  CHECK(local.num32BitValues == 2);
  CHECK(local.registerSpace == kShaderRecordSpace);
  CHECK(local.shaderRegister == 0);
  CHECK(kShaderRecordSpace != kPushConstantSpace);
}
