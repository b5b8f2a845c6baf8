#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "path_tracer_shared.h"
#include "penumbra_shaders.h"
#include "rhi/shader_reflection.h"
#include "util/error.h"

using namespace penumbra;
using namespace penumbra::rhi;

namespace {
PipelineBindingLayout reflectPathTracer() {
  PipelineBindingLayout layout;
  for (const char* name :
       {"path_trace.rgen", "whitted.rgen", "path_trace.rmiss", "shadow.rmiss", "triangle.rchit"})
    reflectSpirv(shaders::find(name), name, layout);
  return layout;
}

const BindingLayoutItem& slot(const PipelineBindingLayout& layout, uint32_t s) {
  for (const auto& item : layout.spaces.at(0).items)
    if (item.slot == s) return item;
  FAIL("slot " << s << " not reflected");
  throw;
}
}  // namespace

TEST_CASE("reflection derives the path tracer's layout from SPIR-V", "[rhi][reflection]") {
  auto layout = reflectPathTracer();
  REQUIRE(layout.spaces.size() == 1);
  REQUIRE(layout.spaces[0].items.size() == 9);
  REQUIRE(layout.pushConstantBytes == sizeof(gpu::FrameConstants));

  REQUIRE(slot(layout, PT_SLOT_SCENE).type == ResourceType::AccelStruct);
  REQUIRE(slot(layout, PT_SLOT_VERTICES).type == ResourceType::StorageBuffer);
  REQUIRE_FALSE(slot(layout, PT_SLOT_VERTICES).writable);
  REQUIRE(slot(layout, PT_SLOT_ACCUMULATION).type == ResourceType::StorageTexture);
  REQUIRE(slot(layout, PT_SLOT_ACCUMULATION).writable);
  REQUIRE(slot(layout, PT_SLOT_RAY_COUNTER).writable);
  REQUIRE_FALSE(slot(layout, PT_SLOT_EMISSIVE_TRIANGLES).writable);
}

TEST_CASE("binding sets are checked against the reflected layout", "[rhi][reflection]") {
  auto layout = reflectPathTracer();
  BindingSetDesc set;
  set.debugName = "test set";
  SECTION("a missing slot names the shader variable") {
    REQUIRE_THROWS_WITH(validateBindingSet(set, layout),
                        Catch::Matchers::ContainsSubstring("gScene") &&
                            Catch::Matchers::ContainsSubstring("bound 0 times"));
  }
  SECTION("a slot the shaders do not declare") {
    set.items.push_back(BindingSetItem::storageBuffer(7, nullptr));
    REQUIRE_THROWS_WITH(validateBindingSet(set, layout),
                        Catch::Matchers::ContainsSubstring("slot 7 is not declared"));
  }
  SECTION("a resource of the wrong type") {
    set.items.push_back(BindingSetItem::storageBuffer(PT_SLOT_SCENE, nullptr));
    REQUIRE_THROWS_WITH(validateBindingSet(set, layout),
                        Catch::Matchers::ContainsSubstring("acceleration structure"));
  }
}

TEST_CASE("the HLSL-front-end build of the core uses the shared register shifts", "[rhi][reflection]") {
  PipelineBindingLayout layout;
  reflectSpirv(shaders::find("core_check.hlsl"), "core_check.hlsl", layout);
  REQUIRE(layout.spaces.size() == 1);
  REQUIRE(layout.spaces[0].items.size() == 2);
  // register(t0) -> PENUMBRA_T(0) = 32, register(u0) -> PENUMBRA_U(0) = 64.
  REQUIRE(layout.spaces[0].items[0].slot == PENUMBRA_T(0));
  REQUIRE_FALSE(layout.spaces[0].items[0].writable);
  REQUIRE(layout.spaces[0].items[1].slot == PENUMBRA_U(0));
  REQUIRE(layout.spaces[0].items[1].writable);
}
