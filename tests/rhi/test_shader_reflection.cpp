#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <iterator>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/rhi/shader_reflection.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"
#include "penumbra_test_shaders.h"

using namespace penumbra;
using namespace penumbra::rhi;

namespace {
// Every shader a path tracer pipeline can hold (implicit hit groups included).
const char* const kPathTracerShaders[] = {
    "path_trace.rgen",   "whitted.rgen",         "probe.rgen",
    "path_trace.rmiss",  "triangle.rchit",       "triangle_alpha.rahit",
    "implicit.rchit",    "implicit_sphere.rint", "implicit_plane_box.rint",
    "implicit_sdf.rint", "implicit_fractal.rint"};

PipelineBindingLayout reflectPathTracer() {
  PipelineBindingLayout layout;
  for (const char* name : kPathTracerShaders) reflectSpirv(shaders::find(name), name, layout);
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
  REQUIRE(layout.spaces[0].items.size() == 27);
  REQUIRE(layout.pushConstantBytes == sizeof(gpu::FrameConstants));

  REQUIRE(slot(layout, PT_SLOT_SCENE).type == ResourceType::AccelStruct);
  REQUIRE(slot(layout, PT_SLOT_VERTICES).type == ResourceType::StorageBuffer);
  REQUIRE_FALSE(slot(layout, PT_SLOT_VERTICES).writable);
  REQUIRE(slot(layout, PT_SLOT_ACCUMULATION).type == ResourceType::StorageTexture);
  REQUIRE(slot(layout, PT_SLOT_ACCUMULATION).writable);
  REQUIRE(slot(layout, PT_SLOT_RAY_COUNTER).writable);
  REQUIRE_FALSE(slot(layout, PT_SLOT_EMISSIVE_TRIANGLES).writable);
  // Vertex attributes: read-only float4 arrays (D3D12 needs the 16-byte stride).
  for (uint32_t s : {uint32_t(PT_SLOT_NORMALS), uint32_t(PT_SLOT_TANGENTS),
                     uint32_t(PT_SLOT_TEXCOORDS), uint32_t(PT_SLOT_COLORS)}) {
    REQUIRE(slot(layout, s).type == ResourceType::StorageBuffer);
    REQUIRE_FALSE(slot(layout, s).writable);
    REQUIRE(slot(layout, s).structureStride == 16u);
  }
  REQUIRE_FALSE(slot(layout, PT_SLOT_IMPLICITS).writable);
  // The environment: its placement, its texels (float4) and its CDF (float).
  REQUIRE(slot(layout, PT_SLOT_ENVIRONMENT_INFO).structureStride == sizeof(gpu::EnvironmentData));
  REQUIRE(slot(layout, PT_SLOT_ENVIRONMENT).structureStride == 16u);
  REQUIRE(slot(layout, PT_SLOT_ENVIRONMENT_CDF).structureStride == 4u);
  REQUIRE_FALSE(slot(layout, PT_SLOT_ENVIRONMENT_CDF).writable);
  // The glTF sheen's albedo table (float).
  REQUIRE(slot(layout, PT_SLOT_SHEEN_ALBEDO).structureStride == 4u);
  REQUIRE_FALSE(slot(layout, PT_SLOT_SHEEN_ALBEDO).writable);
  REQUIRE_FALSE(slot(layout, PT_SLOT_PROBE_RAYS).writable);
  REQUIRE(slot(layout, PT_SLOT_PROBE_HITS).writable);
  // The denoiser's guide buffers: writable storage images.
  for (uint32_t s : {uint32_t(PT_SLOT_GUIDE_ALBEDO), uint32_t(PT_SLOT_GUIDE_NORMAL_DEPTH),
                     uint32_t(PT_SLOT_GUIDE_EMISSION), uint32_t(PT_SLOT_GUIDE_MOMENTS)}) {
    REQUIRE(slot(layout, s).type == ResourceType::StorageTexture);
    REQUIRE(slot(layout, s).writable);
  }
  // Material textures: bindless (unbounded) texture and sampler arrays.
  REQUIRE(slot(layout, PT_SLOT_TEXTURES).type == ResourceType::SampledTexture);
  REQUIRE(slot(layout, PT_SLOT_TEXTURES).arraySize == 0u);
  REQUIRE(slot(layout, PT_SLOT_SAMPLERS).type == ResourceType::Sampler);
  REQUIRE(slot(layout, PT_SLOT_SAMPLERS).arraySize == 0u);
  REQUIRE_FALSE(slot(layout, PT_SLOT_TEXTURE_REFS).writable);
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

TEST_CASE("the HLSL-front-end build of the core uses the shared register shifts",
          "[rhi][reflection]") {
  PipelineBindingLayout layout;
  reflectSpirv(test_shaders::find("core_check.hlsl"), "core_check.hlsl", layout);
  REQUIRE(layout.spaces.size() == 1);
  REQUIRE(layout.spaces[0].items.size() == 2);
  // register(t0) -> PENUMBRA_T(0) = 32, register(u0) -> PENUMBRA_U(0) = 64.
  REQUIRE(layout.spaces[0].items[0].slot == PENUMBRA_T(0));
  REQUIRE_FALSE(layout.spaces[0].items[0].writable);
  REQUIRE(layout.spaces[0].items[1].slot == PENUMBRA_U(0));
  REQUIRE(layout.spaces[0].items[1].writable);
}

namespace {
bool sameLayout(const PipelineBindingLayout& a, const PipelineBindingLayout& b) {
  if (a.pushConstantBytes != b.pushConstantBytes || a.spaces.size() != b.spaces.size())
    return false;
  for (size_t s = 0; s < a.spaces.size(); ++s) {
    const auto &x = a.spaces[s].items, &y = b.spaces[s].items;
    if (a.spaces[s].space != b.spaces[s].space || x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (x[i].slot != y[i].slot || x[i].type != y[i].type || x[i].arraySize != y[i].arraySize ||
          x[i].writable != y[i].writable || x[i].structureStride != y[i].structureStride ||
          x[i].name != y[i].name)
        return false;
  }
  return true;
}
}  // namespace

TEST_CASE("the build-time layouts equal run-time reflection of the embedded SPIR-V",
          "[rhi][reflection]") {
  std::vector<const char*> names(std::begin(kPathTracerShaders), std::end(kPathTracerShaders));
  names.insert(names.end(), {"tonemap.comp", "display.comp", "denoise.comp"});
  for (const char* name : names) {
    INFO(name);
    const ShaderDesc desc = shaders::shaderDesc(name);
    const ShaderReflection runtime = reflectSpirvModule(desc.spirv, name);
    CHECK(sameLayout(desc.bindingLayout, runtime.layout));
    CHECK(desc.shaderRecordBytes == runtime.shaderRecordBytes);
  }
  for (const char* name : {"probe.rgen", "probe.rmiss", "probe_alternate.rmiss", "probe.rchit",
                           "sphere.rint", "texture_sample.comp", "core_check.hlsl"}) {
    INFO(name);
    const ShaderDesc desc = test_shaders::shaderDesc(name);
    const ShaderReflection runtime = reflectSpirvModule(desc.spirv, name);
    CHECK(sameLayout(desc.bindingLayout, runtime.layout));
    CHECK(desc.shaderRecordBytes == runtime.shaderRecordBytes);
  }
  CHECK(test_shaders::shaderDesc("probe.rchit").shaderRecordBytes == 4);  // { uint gTag; }
  CHECK(shaders::shaderDesc("triangle.rchit").shaderRecordBytes == 0);
}

TEST_CASE("reflection derives separate textures and samplers, runtime arrays as unbounded",
          "[rhi][reflection][textures]") {
  PipelineBindingLayout layout;
  reflectSpirv(test_shaders::find("texture_sample.comp"), "texture_sample.comp", layout);
  REQUIRE(layout.spaces.size() == 1);
  REQUIRE(layout.spaces[0].items.size() == 4);
  const auto& textures = slot(layout, PENUMBRA_T(12));
  CHECK(textures.type == ResourceType::SampledTexture);
  CHECK(textures.arraySize == 0);
  CHECK(textures.name == "gTextures");
  CHECK_FALSE(textures.writable);
  const auto& samplers = slot(layout, PENUMBRA_S(0));
  CHECK(samplers.type == ResourceType::Sampler);
  CHECK(samplers.arraySize == 0);
  CHECK(samplers.name == "gSamplers");
  CHECK(slot(layout, PENUMBRA_T(0)).type == ResourceType::StorageBuffer);
  CHECK(slot(layout, PENUMBRA_T(0)).arraySize == 1);
  CHECK(layout.pushConstantBytes == 4);
}

TEST_CASE("reflection records each storage buffer's structure stride for D3D12 views",
          "[rhi][reflection]") {
  auto layout = reflectPathTracer();
  CHECK(slot(layout, PT_SLOT_VERTICES).structureStride == 16);  // float4[]
  CHECK(slot(layout, PT_SLOT_INDICES).structureStride == 4);    // uint[]
  CHECK(slot(layout, PT_SLOT_INSTANCES).structureStride == sizeof(gpu::InstanceData));
  CHECK(slot(layout, PT_SLOT_EMISSIVE_TRIANGLES).structureStride == sizeof(gpu::EmissiveTriangle));
  CHECK(slot(layout, PT_SLOT_IMPLICITS).structureStride == sizeof(gpu::ImplicitData));
  CHECK(slot(layout, PT_SLOT_PROBE_RAYS).structureStride == sizeof(gpu::ProbeRay));
  CHECK(slot(layout, PT_SLOT_PROBE_HITS).structureStride == sizeof(gpu::ProbeHit));
  CHECK(slot(layout, PT_SLOT_RAY_COUNTER).structureStride == 4);  // { uint gRayCount; }
  CHECK(slot(layout, PT_SLOT_SCENE).structureStride == 0);
}

TEST_CASE("embedded shaders say whether this build has their DXIL", "[rhi][reflection]") {
  // Only builds with the D3D12 backend and DXC embed DXIL (cmake/Shaders.cmake).
  for (const char* name : {"path_trace.rgen", "triangle.rchit", "tonemap.comp"}) {
    const ShaderDesc desc = shaders::shaderDesc(name);
    CHECK_FALSE(desc.spirv.empty());
#ifndef PENUMBRA_HAVE_DXIL
    CHECK(desc.dxil.empty());
#else
    CHECK_FALSE(desc.dxil.empty());
#endif
  }
  REQUIRE_THROWS_WITH(shaders::shaderDesc("nope.rgen"),
                      Catch::Matchers::ContainsSubstring("not embedded"));
}
