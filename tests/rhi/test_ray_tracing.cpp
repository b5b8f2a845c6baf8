// RHI conformance on the default device: BLAS over triangles and AABBs, TLAS
// instances with transforms, masks and hit-group offsets, a shader table with
// two miss shaders and three hit groups carrying local data, readback.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cstring>

#include "penumbra/util/error.h"
#include "penumbra_test_shaders.h"
#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Approx;

namespace {

struct ProbeRay {
  float origin[3];
  float tMax;
  float direction[3];
  float missIndex;
};
struct ProbeResult {
  uint32_t tag, instanceId, primitiveId, hitKind;
  float hitT, objectPosition[3];
};
static_assert(sizeof(ProbeRay) == 32 && sizeof(ProbeResult) == 32);

ShaderDesc testShader(ShaderStage stage, const char* file) {
  ShaderDesc d = test_shaders::shaderDesc(file);
  REQUIRE(d.stage == stage);
  return d;
}

rt::AffineTransform translateScale(float x, float y, float z, float s) {
  return {s, 0, 0, x, 0, s, 0, y, 0, 0, s, z};
}

template <class T>
BufferHandle upload(IDevice& device, ICommandList& cmd, const std::vector<T>& data, BufferUsage usage,
                    const char* name) {
  BufferDesc desc;
  desc.byteSize = data.size() * sizeof(T);
  desc.usage = usage;
  desc.debugName = name;
  auto buffer = device.createBuffer(desc);
  cmd.writeBuffer(buffer.get(), data.data(), desc.byteSize);
  return buffer;
}

enum Tags : uint32_t { kMissTag = 1, kMissAltTag = 2, kQuadATag = 100, kQuadBTag = 200, kSphereTag = 300 };

}  // namespace

TEST_CASE("ray tracing: BLAS/TLAS, instances, shader table selection, readback",
          "[rhi][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  auto cmd = device->createCommandList();
  cmd->open();

  // Object-space unit square at z = 0 (two triangles) and the AABB of a unit sphere.
  std::vector<float> quad = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  std::vector<uint32_t> quadIndices = {0, 1, 2, 0, 2, 3};
  std::vector<float> aabb = {-1, -1, -1, 1, 1, 1};
  const auto inputUsage = BufferUsage::AccelStructBuildInput | BufferUsage::StorageBuffer;
  auto vertices = upload(*device, *cmd, quad, inputUsage, "quad vertices");
  auto indices = upload(*device, *cmd, quadIndices, inputUsage, "quad indices");
  auto aabbs = upload(*device, *cmd, aabb, inputUsage, "sphere aabb");

  rt::AccelStructDesc quadDesc;
  quadDesc.debugName = "quad BLAS";
  rt::GeometryDesc tri;
  tri.type = rt::GeometryType::Triangles;
  tri.triangles.vertexBuffer = vertices.get();
  tri.triangles.vertexStride = 12;
  tri.triangles.vertexCount = 4;
  tri.triangles.indexBuffer = indices.get();
  tri.triangles.indexCount = 6;
  quadDesc.bottomLevelGeometries = {tri};
  auto quadBlas = device->createAccelStruct(quadDesc);

  rt::AccelStructDesc sphereDesc;
  sphereDesc.debugName = "sphere BLAS";
  rt::GeometryDesc box;
  box.type = rt::GeometryType::AABBs;
  box.aabbs.buffer = aabbs.get();
  box.aabbs.count = 1;
  sphereDesc.bottomLevelGeometries = {box};
  auto sphereBlas = device->createAccelStruct(sphereDesc);

  cmd->buildBottomLevelAccelStruct(quadBlas.get());
  cmd->buildBottomLevelAccelStruct(sphereBlas.get());

  std::vector<rt::InstanceDesc> instances(4);
  instances[0].transform = translateScale(0, 0, 5, 1);
  instances[0].instanceID = 10;
  instances[0].instanceContributionToHitGroupIndex = 0;
  instances[0].bottomLevelAddress = quadBlas->deviceAddress();
  instances[1].transform = translateScale(3, 0, 5, 0.5f);
  instances[1].instanceID = 11;
  instances[1].instanceContributionToHitGroupIndex = 1;
  instances[1].bottomLevelAddress = quadBlas->deviceAddress();
  instances[2].transform = translateScale(-3, 0, 5, 1);
  instances[2].instanceID = 12;
  instances[2].instanceContributionToHitGroupIndex = 2;
  instances[2].bottomLevelAddress = sphereBlas->deviceAddress();
  instances[3].transform = translateScale(0, 3, 5, 1);
  instances[3].instanceID = 13;
  instances[3].instanceMask = 0x00;  // never matches a ray's cull mask
  instances[3].bottomLevelAddress = quadBlas->deviceAddress();

  rt::AccelStructDesc tlasDesc;
  tlasDesc.isTopLevel = true;
  tlasDesc.topLevelMaxInstances = 4;
  tlasDesc.debugName = "probe TLAS";
  auto tlas = device->createAccelStruct(tlasDesc);
  cmd->buildTopLevelAccelStruct(tlas.get(), instances.data(), 4);

  // origin, tMax, direction, miss index
  std::vector<ProbeRay> rays = {
      {{0, 0, 0}, 100, {0, 0, 1}, 0},      // 0: instance 10, hit group 0
      {{3, 0, 0}, 100, {0, 0, 1}, 0},      // 1: instance 11, hit group 1
      {{3, 0.4f, 0}, 100, {0, 0, 1}, 0},   // 2: inside the half-size quad
      {{3, 0.6f, 0}, 100, {0, 0, 1}, 0},   // 3: outside it -> miss 0
      {{-3, 0, 0}, 100, {0, 0, 1}, 0},     // 4: sphere front pole
      {{-3, 0.6f, 0}, 100, {0, 0, 1}, 0},  // 5: sphere off-centre
      {{10, 10, 0}, 100, {0, 0, 1}, 1},    // 6: nothing -> miss 1
      {{0, 0, 10}, 100, {0, 0, -1}, 0},    // 7: quad from behind
      {{0, 0, 0}, 4, {0, 0, 1}, 0},        // 8: tMax before the quad -> miss
      {{0, 3, 0}, 100, {0, 0, 1}, 0},      // 9: masked-out instance -> miss
      {{0, 0.5f, 0}, 100, {0, 0, 1}, 0},   // 10: upper-left triangle (primitive 1)
      {{0.5f, -0.5f, 0}, 100, {0, 0, 1}, 0}, // 11: lower-right triangle (primitive 0)
  };
  auto rayBuffer = upload(*device, *cmd, rays, BufferUsage::StorageBuffer, "probe rays");
  BufferDesc resultDesc;
  resultDesc.byteSize = rays.size() * sizeof(ProbeResult);
  resultDesc.usage = BufferUsage::StorageBuffer;
  resultDesc.debugName = "probe results";
  auto results = device->createBuffer(resultDesc);
  resultDesc.usage = BufferUsage::CopyDest;
  resultDesc.memory = MemoryLocation::Readback;
  resultDesc.debugName = "probe readback";
  auto readback = device->createBuffer(resultDesc);

  RayTracingPipelineDesc pipelineDesc;
  pipelineDesc.debugName = "probe pipeline";
  pipelineDesc.shaders = {testShader(ShaderStage::RayGeneration, "probe.rgen"),
                          testShader(ShaderStage::Miss, "probe.rmiss"),
                          testShader(ShaderStage::Miss, "probe_alternate.rmiss"),
                          testShader(ShaderStage::ClosestHit, "probe.rchit"),
                          testShader(ShaderStage::Intersection, "sphere.rint")};
  pipelineDesc.hitGroups = {{"quad", "probe.rchit", "", "", false},
                            {"sphere", "probe.rchit", "", "sphere.rint", true}};
  pipelineDesc.maxPayloadBytes = 32;
  auto pipeline = device->createRayTracingPipeline(pipelineDesc);

  auto table = pipeline->createShaderTable("probe table");
  table->setRayGenerationShader("probe.rgen");
  const uint32_t missTags[] = {kMissTag, kMissAltTag};
  const uint32_t hitTags[] = {kQuadATag, kQuadBTag, kSphereTag};
  REQUIRE(table->addMissShader("probe.rmiss", &missTags[0], 4) == 0);
  REQUIRE(table->addMissShader("probe_alternate.rmiss", &missTags[1], 4) == 1);
  REQUIRE(table->addHitGroup("quad", &hitTags[0], 4) == 0);
  REQUIRE(table->addHitGroup("quad", &hitTags[1], 4) == 1);
  REQUIRE(table->addHitGroup("sphere", &hitTags[2], 4) == 2);

  BindingSetDesc set;
  set.debugName = "probe bindings";
  set.items = {BindingSetItem::accelStructure(32, tlas), BindingSetItem::storageBuffer(33, rayBuffer),
               BindingSetItem::storageBuffer(64, results)};
  auto bindings = device->createBindingSet(set, *pipeline);

  cmd->setRayTracingState({pipeline.get(), table.get(), {bindings.get()}});
  cmd->dispatchRays(uint32_t(rays.size()), 1);
  cmd->copyBuffer(readback.get(), 0, results.get(), 0, resultDesc.byteSize);
  cmd->close();
  device->submit(cmd.get());
  device->waitForIdle();

  std::vector<ProbeResult> r(rays.size());
  std::memcpy(r.data(), readback->mappedData(), resultDesc.byteSize);

  {  // triangle instances select their hit group by hit-group offset
    CHECK(r[0].tag == kQuadATag);
    CHECK(r[0].instanceId == 10);
    CHECK(r[0].hitT == Approx(5.0f));
    CHECK(r[1].tag == kQuadBTag);
    CHECK(r[1].instanceId == 11);
    CHECK(r[1].hitT == Approx(5.0f));
  }
  {  // instance transforms are honoured (object-space hit positions)
    CHECK(r[0].objectPosition[0] == Approx(0.0f).margin(1e-5));
    CHECK(r[2].tag == kQuadBTag);
    CHECK(r[2].objectPosition[1] == Approx(0.8f).margin(1e-5));  // 0.4 / scale 0.5
    CHECK(r[3].tag == kMissTag);
    CHECK(r[3].hitT == -1.0f);
  }
  {  // AABB geometry runs the intersection shader
    CHECK(r[4].tag == kSphereTag);
    CHECK(r[4].instanceId == 12);
    CHECK(r[4].hitKind == 7u);
    CHECK(r[4].hitT == Approx(4.0f));
    CHECK(r[4].objectPosition[2] == Approx(-1.0f).margin(1e-5));
    CHECK(r[5].tag == kSphereTag);
    CHECK(r[5].hitT == Approx(4.2f));
    CHECK(r[5].objectPosition[1] == Approx(0.6f).margin(1e-5));
    CHECK(r[5].objectPosition[2] == Approx(-0.8f).margin(1e-5));
  }
  {  // the miss index selects between two miss shaders
    CHECK(r[6].tag == (kMissAltTag | 0x10000u));
    CHECK(r[8].tag == kMissTag);  // tMax stops before the quad
    CHECK(r[9].tag == kMissTag);  // instance mask 0 is never hit
  }
  {  // both faces of a triangle are hit, with different hit kinds
    CHECK(r[7].tag == kQuadATag);
    CHECK(r[7].hitT == Approx(5.0f));
    CHECK((r[0].hitKind == 0xFEu || r[0].hitKind == 0xFFu));
    CHECK((r[7].hitKind == 0xFEu || r[7].hitKind == 0xFFu));
    CHECK(r[0].hitKind != r[7].hitKind);
  }
  {  // primitive indices follow the index buffer
    CHECK(r[10].primitiveId == 1u);
    CHECK(r[11].primitiveId == 0u);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("ray tracing: unknown shader names are clear errors", "[rhi][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  RayTracingPipelineDesc desc;
  desc.debugName = "broken";
  desc.shaders = {testShader(ShaderStage::RayGeneration, "probe.rgen"),
                  testShader(ShaderStage::Miss, "probe.rmiss")};
  desc.hitGroups = {{"quad", "missing.rchit", "", "", false}};
  REQUIRE_THROWS_AS(device->createRayTracingPipeline(desc), penumbra::Error);
  desc.hitGroups.clear();
  auto pipeline = device->createRayTracingPipeline(desc);
  auto table = pipeline->createShaderTable("t");
  REQUIRE_THROWS_AS(table->addHitGroup("nope"), penumbra::Error);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
