// The RHI validation layer (engine/penumbra/rhi/validation.h): one test per rule, on
// the Vulkan backend. Each wrong call must throw before the backend records
// anything -- so the Khronos validation layer sees nothing -- with an error
// that names the call and the objects. The rules are the layer's, so they hold
// for D3D12 by construction.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "display_shared.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"
#include "penumbra_test_shaders.h"
#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

namespace {

// A wrong call is rejected with every listed fragment in its message, and
// nothing reached the API's own validation.
#define REQUIRE_REJECTED(call, ...)         \
  do {                                      \
    REQUIRE_THROWS_WITH(call, __VA_ARGS__); \
    REQUIRE_NO_VALIDATION_MESSAGES(device); \
  } while (0)

struct Fixture {
  DeviceHandle device = test::makeTestDevice();
  CommandListHandle cmd = device->createCommandList("test list");

  BufferHandle buffer(uint64_t bytes, BufferUsage usage, const char* name,
                      MemoryLocation memory = MemoryLocation::DeviceLocal) {
    BufferDesc desc;
    desc.byteSize = bytes;
    desc.usage = usage;
    desc.memory = memory;
    desc.debugName = name;
    return device->createBuffer(desc);
  }
  TextureHandle texture(TextureUsage usage, const char* name, uint32_t size = 4) {
    TextureDesc desc;
    desc.width = desc.height = size;
    desc.usage = usage;
    desc.debugName = name;
    return device->createTexture(desc);
  }
  // The RHI conformance test's pipeline (tests/rhi/test_ray_tracing.cpp).
  static RayTracingPipelineDesc probeDesc() {
    RayTracingPipelineDesc desc;
    desc.debugName = "probe pipeline";
    desc.shaders = {test_shaders::shaderDesc("probe.rgen"), test_shaders::shaderDesc("probe.rmiss"),
                    test_shaders::shaderDesc("probe.rchit"),
                    test_shaders::shaderDesc("sphere.rint")};
    desc.hitGroups = {{"quad", "probe.rchit", "", "", false},
                      {"sphere", "probe.rchit", "", "sphere.rint", true}};
    return desc;
  }
  rt::GeometryDesc triangles(IBuffer* vertices, uint32_t vertexCount) {
    rt::GeometryDesc g;
    g.triangles.vertexBuffer = vertices;
    g.triangles.vertexCount = vertexCount;
    return g;
  }
  rt::AccelStructHandle bottomLevel() {
    vertices_ = buffer(36, BufferUsage::AccelStructBuildInput, "triangle vertices");
    rt::AccelStructDesc desc;
    desc.debugName = "triangle BLAS";
    desc.bottomLevelGeometries = {triangles(vertices_.get(), 3)};
    return device->createAccelStruct(desc);
  }
  rt::AccelStructHandle topLevel(uint32_t maxInstances = 1) {
    rt::AccelStructDesc desc;
    desc.isTopLevel = true;
    desc.topLevelMaxInstances = maxInstances;
    desc.debugName = "scene TLAS";
    return device->createAccelStruct(desc);
  }
  // A complete binding set for the probe pipeline.
  BindingSetHandle probeBindings(const IPipeline& pipeline) {
    tlas_ = topLevel();
    rays_ = buffer(64, BufferUsage::StorageBuffer, "probe rays");
    results_ = buffer(64, BufferUsage::StorageBuffer, "probe results");
    BindingSetDesc set;
    set.debugName = "probe bindings";
    set.items = {BindingSetItem::accelStructure(32, tlas_),
                 BindingSetItem::storageBuffer(33, rays_),
                 BindingSetItem::storageBuffer(64, results_)};
    return device->createBindingSet(set, pipeline);
  }
  ComputePipelineHandle computePipeline(const char* shader, const char* name) {
    ComputePipelineDesc desc;
    desc.shader = shaders::shaderDesc(shader);
    desc.debugName = name;
    return device->createComputePipeline(desc);
  }
  // tonemap.comp's set: an RGBA32F storage texture in, a pixel buffer out.
  BindingSetHandle tonemapBindings(const IPipeline& pipeline) {
    hdr_ = texture(TextureUsage::Storage, "hdr");
    pixels_ = buffer(64, BufferUsage::StorageBuffer, "pixels");
    BindingSetDesc set;
    set.debugName = "tonemap bindings";
    set.items = {BindingSetItem::storageTexture(PENUMBRA_T(TM_T_INPUT), hdr_),
                 BindingSetItem::storageBuffer(PENUMBRA_U(TM_U_OUTPUT), pixels_)};
    return device->createBindingSet(set, pipeline);
  }

  BufferHandle vertices_, rays_, results_, pixels_;
  TextureHandle hdr_;
  rt::AccelStructHandle tlas_;
};

}  // namespace

// ---- Command-list state -------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: open() on an open command list", "[rhi][validation]") {
  cmd->open();
  REQUIRE_REJECTED(cmd->open(),
                   ContainsSubstring("open: command list 'test list' is already open"));
}

TEST_CASE_METHOD(Fixture, "validation: recording on a closed command list", "[rhi][validation]") {
  auto b = buffer(16, BufferUsage::StorageBuffer, "data");
  const uint32_t value = 1;
  REQUIRE_REJECTED(cmd->writeBuffer(b.get(), &value, 4),
                   ContainsSubstring("writeBuffer: command list 'test list' is not open"));
  cmd->open();
  cmd->close();
  REQUIRE_REJECTED(cmd->close(), ContainsSubstring("close: command list 'test list' is not open"));
}

TEST_CASE_METHOD(Fixture, "validation: submitting an open command list", "[rhi][validation]") {
  cmd->open();
  REQUIRE_REJECTED(device->submit(cmd.get()),
                   ContainsSubstring("submit: command list 'test list' is still open"));
}

TEST_CASE_METHOD(Fixture, "validation: submitting another device's command list",
                 "[rhi][validation]") {
  auto other = test::makeTestDevice();
  auto foreign = other->createCommandList("foreign list");
  foreign->open();
  foreign->close();
  REQUIRE_REJECTED(device->submit(foreign.get()),
                   ContainsSubstring("submit: the command list was not created by this device"));
}

TEST_CASE_METHOD(Fixture, "validation: timer queries are begun and ended in pairs",
                 "[rhi][validation]") {
  auto query = device->createTimerQuery();
  cmd->open();
  REQUIRE_REJECTED(cmd->endTimerQuery(query.get()),
                   ContainsSubstring("endTimerQuery") && ContainsSubstring("not begun"));
  cmd->beginTimerQuery(query.get());
  REQUIRE_REJECTED(cmd->beginTimerQuery(query.get()),
                   ContainsSubstring("beginTimerQuery") && ContainsSubstring("not ended"));
  REQUIRE_REJECTED(cmd->close(), ContainsSubstring("close: command list 'test list' has 1 timer "
                                                   "query begun but not ended"));
}

// ---- Copies and clears ----------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: writeBuffer past the buffer's end", "[rhi][validation]") {
  auto b = buffer(16, BufferUsage::StorageBuffer, "small");
  const uint8_t data[16] = {};
  cmd->open();
  REQUIRE_REJECTED(cmd->writeBuffer(b.get(), data, 16, 4),
                   ContainsSubstring("writeBuffer: 16 bytes at offset 4 overflow buffer 'small'"));
  // An offset near 2^64 must not wrap around the check.
  REQUIRE_REJECTED(cmd->writeBuffer(b.get(), data, 16, ~uint64_t(0) - 8),
                   ContainsSubstring("overflow buffer 'small'"));
}

TEST_CASE_METHOD(Fixture, "validation: writeTexture with the wrong byte count",
                 "[rhi][validation]") {
  auto t = texture(TextureUsage::Sampled, "albedo");
  std::vector<uint8_t> data(100);
  cmd->open();
  REQUIRE_REJECTED(
      cmd->writeTexture(t.get(), data.data(), data.size()),
      ContainsSubstring("writeTexture: 100 bytes into texture 'albedo' (4x4, 256 bytes)"));
  // With mip levels, every level: 4x4 + 2x2 + 1x1 texels of 16 bytes.
  TextureDesc desc;
  desc.width = 4;
  desc.height = 4;
  desc.usage = TextureUsage::Sampled | TextureUsage::CopyDest;
  desc.mipLevels = 3;
  desc.debugName = "mipmapped";
  auto mipmapped = device->createTexture(desc);
  std::vector<uint8_t> level0(256);
  REQUIRE_REJECTED(cmd->writeTexture(mipmapped.get(), level0.data(), level0.size()),
                   ContainsSubstring("writeTexture: 256 bytes into texture 'mipmapped' (4x4 and 2 "
                                     "smaller mip levels, 336 bytes)"));
}

TEST_CASE_METHOD(Fixture, "validation: copyBuffer ranges lie inside both buffers",
                 "[rhi][validation]") {
  auto src = buffer(16, BufferUsage::StorageBuffer, "src");
  auto dst = buffer(64, BufferUsage::StorageBuffer, "dst");
  cmd->open();
  REQUIRE_REJECTED(cmd->copyBuffer(dst.get(), 0, src.get(), 8, 16),
                   ContainsSubstring("copyBuffer: 16 bytes at offset 8 overflow the source, "
                                     "buffer 'src'"));
  REQUIRE_REJECTED(cmd->copyBuffer(src.get(), 8, dst.get(), 0, 16),
                   ContainsSubstring("overflow the destination, buffer 'src'"));
  REQUIRE_REJECTED(cmd->copyBuffer(dst.get(), 8, dst.get(), 0, 16),
                   ContainsSubstring("ranges of buffer 'dst' overlap"));
}

TEST_CASE_METHOD(Fixture, "validation: copies never write upload or read readback memory",
                 "[rhi][validation]") {
  auto device_local = buffer(16, BufferUsage::StorageBuffer, "device");
  auto upload = buffer(16, BufferUsage::CopySource, "staging", MemoryLocation::Upload);
  auto readback = buffer(16, BufferUsage::CopyDest, "readback", MemoryLocation::Readback);
  cmd->open();
  REQUIRE_REJECTED(cmd->copyBuffer(upload.get(), 0, device_local.get(), 0, 16),
                   ContainsSubstring("the destination, buffer 'staging', is an upload buffer"));
  REQUIRE_REJECTED(cmd->copyBuffer(device_local.get(), 0, readback.get(), 0, 16),
                   ContainsSubstring("the source, buffer 'readback', is a readback buffer"));
}

TEST_CASE_METHOD(Fixture, "validation: copyTextureToBuffer needs room for the whole texture",
                 "[rhi][validation]") {
  auto t = texture(TextureUsage::Storage, "image");
  auto b = buffer(256, BufferUsage::CopyDest, "readback", MemoryLocation::Readback);
  cmd->open();
  REQUIRE_REJECTED(cmd->copyTextureToBuffer(t.get(), b.get(), 16),
                   ContainsSubstring("copyTextureToBuffer: texture 'image' (256 bytes) does not "
                                     "fit in buffer 'readback' (256 bytes) at offset 16"));
}

TEST_CASE_METHOD(Fixture, "validation: copyTexture between equal sizes", "[rhi][validation]") {
  auto a = texture(TextureUsage::Storage, "a", 4);
  auto b = texture(TextureUsage::Storage, "b", 8);
  cmd->open();
  REQUIRE_REJECTED(cmd->copyTexture(b.get(), a.get()),
                   ContainsSubstring("copyTexture: from texture 'a' (4x4) to texture 'b' (8x8)"));
}

TEST_CASE_METHOD(Fixture, "validation: clearTextureFloat needs a storage texture",
                 "[rhi][validation]") {
  auto t = texture(TextureUsage::Sampled, "sampled only");
  cmd->open();
  REQUIRE_REJECTED(cmd->clearTextureFloat(t.get(), 0, 0, 0, 0),
                   ContainsSubstring("clearTextureFloat: texture 'sampled only' lacks "
                                     "TextureUsage::Storage"));
}

TEST_CASE_METHOD(Fixture, "validation: clearBufferUint needs a device-local storage buffer",
                 "[rhi][validation]") {
  auto readback = buffer(16, BufferUsage::CopyDest, "readback", MemoryLocation::Readback);
  auto plain = buffer(16, BufferUsage::CopyDest, "plain");
  cmd->open();
  REQUIRE_REJECTED(cmd->clearBufferUint(readback.get(), 0),
                   ContainsSubstring("clearBufferUint: buffer 'readback' is not device-local"));
  REQUIRE_REJECTED(cmd->clearBufferUint(plain.get(), 0),
                   ContainsSubstring("buffer 'plain' lacks BufferUsage::StorageBuffer"));
}

// ---- Barrier states -------------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: a texture's state needs the matching usage",
                 "[rhi][validation]") {
  auto storage = texture(TextureUsage::Storage, "storage only");
  auto sampled = texture(TextureUsage::Sampled, "sampled only");
  cmd->open();
  REQUIRE_REJECTED(cmd->setTextureState(storage.get(), ResourceState::ShaderResource),
                   ContainsSubstring("setTextureState: texture 'storage only' to ShaderResource: "
                                     "it lacks TextureUsage::Sampled"));
  REQUIRE_REJECTED(cmd->setTextureState(sampled.get(), ResourceState::UnorderedAccess),
                   ContainsSubstring("it lacks TextureUsage::Storage"));
  REQUIRE_REJECTED(cmd->setTextureState(sampled.get(), ResourceState::RenderTarget),
                   ContainsSubstring("it lacks TextureUsage::RenderTarget"));
  REQUIRE_REJECTED(cmd->setTextureState(sampled.get(), ResourceState::ConstantBuffer),
                   ContainsSubstring("cannot be put in a buffer's"));
}

TEST_CASE_METHOD(Fixture, "validation: a buffer's state needs the matching usage and memory",
                 "[rhi][validation]") {
  auto upload = buffer(16, BufferUsage::StorageBuffer, "upload", MemoryLocation::Upload);
  auto storage = buffer(16, BufferUsage::StorageBuffer, "storage");
  cmd->open();
  REQUIRE_REJECTED(cmd->setBufferState(upload.get(), ResourceState::UnorderedAccess),
                   ContainsSubstring("setBufferState: buffer 'upload' to UnorderedAccess: it is "
                                     "not device-local"));
  REQUIRE_REJECTED(cmd->setBufferState(storage.get(), ResourceState::ConstantBuffer),
                   ContainsSubstring("it lacks BufferUsage::ConstantBuffer"));
  REQUIRE_REJECTED(cmd->setBufferState(storage.get(), ResourceState::AccelStructBuildInput),
                   ContainsSubstring("it lacks BufferUsage::AccelStructBuildInput"));
  REQUIRE_REJECTED(cmd->setBufferState(storage.get(), ResourceState::HostRead),
                   ContainsSubstring("it is not a readback buffer"));
  REQUIRE_REJECTED(cmd->setBufferState(storage.get(), ResourceState::AccelStructRead),
                   ContainsSubstring("cannot be put in a texture's or acceleration structure's"));
}

TEST_CASE_METHOD(Fixture, "validation: acceleration structures take only their two states",
                 "[rhi][validation]") {
  auto tlas = topLevel();
  cmd->open();
  REQUIRE_REJECTED(cmd->setAccelStructState(tlas.get(), ResourceState::ShaderResource),
                   ContainsSubstring("setAccelStructState: 'scene TLAS' to ShaderResource"));
}

// ---- Resources --------------------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: buffers and textures have a size", "[rhi][validation]") {
  REQUIRE_REJECTED(buffer(0, BufferUsage::StorageBuffer, "empty"),
                   ContainsSubstring("createBuffer: buffer 'empty' has zero size"));
  TextureDesc desc;
  desc.width = 0;
  desc.debugName = "flat";
  REQUIRE_REJECTED(device->createTexture(desc),
                   ContainsSubstring("createTexture: texture 'flat' is 0x1"));
}

TEST_CASE_METHOD(Fixture,
                 "validation: mip levels run from 1 to the full chain, sampled textures only",
                 "[rhi][validation]") {
  TextureDesc desc;
  desc.width = 5;
  desc.height = 3;
  desc.usage = TextureUsage::Sampled | TextureUsage::CopyDest;
  desc.debugName = "odd";
  desc.mipLevels = 0;
  REQUIRE_REJECTED(
      device->createTexture(desc),
      ContainsSubstring("createTexture: texture 'odd' (5x3) has 0 mip levels; it can have 1 to 3"));
  desc.mipLevels = 4;  // 5x3, 2x1, 1x1 is the whole chain
  REQUIRE_REJECTED(
      device->createTexture(desc),
      ContainsSubstring("createTexture: texture 'odd' (5x3) has 4 mip levels; it can have 1 to 3"));
  desc.mipLevels = 3;
  REQUIRE(device->createTexture(desc));
  desc.usage = TextureUsage::Storage;
  REQUIRE_REJECTED(
      device->createTexture(desc),
      ContainsSubstring("createTexture: texture 'odd': a texture with mip levels is sampled "
                        "only, not storage or a render target"));
}

TEST_CASE_METHOD(Fixture, "validation: acceleration-structure storage is device-local",
                 "[rhi][validation]") {
  REQUIRE_REJECTED(buffer(256, BufferUsage::AccelStructStorage, "as", MemoryLocation::Upload),
                   ContainsSubstring("createBuffer: buffer 'as': acceleration-structure storage "
                                     "must be device-local"));
}

TEST_CASE_METHOD(Fixture, "validation: sRGB textures are not storage textures",
                 "[rhi][validation]") {
  TextureDesc desc;
  desc.format = Format::RGBA8_SRGB;
  desc.usage = TextureUsage::Storage;
  desc.debugName = "colour";
  REQUIRE_REJECTED(device->createTexture(desc),
                   ContainsSubstring("createTexture: texture 'colour': RGBA8_SRGB cannot have "
                                     "TextureUsage::Storage"));
}

// ---- Acceleration-structure build inputs --------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: a top level holds at least one instance",
                 "[rhi][validation]") {
  REQUIRE_REJECTED(topLevel(0), ContainsSubstring("createAccelStruct: top level 'scene TLAS' has "
                                                  "topLevelMaxInstances = 0"));
}

TEST_CASE_METHOD(Fixture, "validation: a bottom level has geometry", "[rhi][validation]") {
  rt::AccelStructDesc desc;
  desc.debugName = "empty BLAS";
  REQUIRE_REJECTED(
      device->createAccelStruct(desc),
      ContainsSubstring("createAccelStruct: bottom level 'empty BLAS' has no geometry"));
}

TEST_CASE_METHOD(Fixture, "validation: triangle geometry has vertices in a build-input buffer",
                 "[rhi][validation]") {
  auto plain = buffer(36, BufferUsage::StorageBuffer, "plain vertices");
  rt::AccelStructDesc desc;
  desc.debugName = "mesh";
  desc.bottomLevelGeometries = {triangles(nullptr, 3)};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("'mesh' has a triangle geometry without vertices"));
  desc.bottomLevelGeometries = {triangles(plain.get(), 3)};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("the vertex data buffer 'plain vertices' lacks "
                                     "BufferUsage::AccelStructBuildInput"));
}

TEST_CASE_METHOD(Fixture, "validation: vertex and index data lie inside their buffers",
                 "[rhi][validation]") {
  auto vertices = buffer(36, BufferUsage::AccelStructBuildInput, "vertices");
  auto indices = buffer(12, BufferUsage::AccelStructBuildInput, "indices");
  rt::AccelStructDesc desc;
  desc.debugName = "mesh";
  desc.bottomLevelGeometries = {triangles(vertices.get(), 6)};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("the vertex data (72 bytes at offset 0) overflows buffer "
                                     "'vertices' (36 bytes)"));
  auto g = triangles(vertices.get(), 3);
  g.triangles.indexBuffer = indices.get();
  g.triangles.indexCount = 6;
  desc.bottomLevelGeometries = {g};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("the index data (24 bytes at offset 0) overflows buffer "
                                     "'indices' (12 bytes)"));
}

TEST_CASE_METHOD(Fixture, "validation: triangle geometry is whole triangles", "[rhi][validation]") {
  auto vertices = buffer(48, BufferUsage::AccelStructBuildInput, "vertices");
  auto indices = buffer(16, BufferUsage::AccelStructBuildInput, "indices");
  rt::AccelStructDesc desc;
  desc.debugName = "mesh";
  desc.bottomLevelGeometries = {triangles(vertices.get(), 4)};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("'mesh': 4 non-indexed vertices are not whole triangles"));
  auto g = triangles(vertices.get(), 4);
  g.triangles.indexBuffer = indices.get();
  g.triangles.indexCount = 4;
  desc.bottomLevelGeometries = {g};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("'mesh': 4 indices are not whole triangles"));
}

TEST_CASE_METHOD(Fixture, "validation: AABB strides are multiples of 8", "[rhi][validation]") {
  auto boxes = buffer(64, BufferUsage::AccelStructBuildInput, "boxes");
  rt::AccelStructDesc desc;
  desc.debugName = "spheres";
  rt::GeometryDesc g;
  g.type = rt::GeometryType::AABBs;
  g.aabbs.buffer = boxes.get();
  g.aabbs.count = 2;
  g.aabbs.stride = 28;
  desc.bottomLevelGeometries = {g};
  REQUIRE_REJECTED(device->createAccelStruct(desc),
                   ContainsSubstring("'spheres': an AABB stride of 28 bytes"));
}

TEST_CASE_METHOD(Fixture, "validation: bottom and top levels are built by their own calls",
                 "[rhi][validation]") {
  auto blas = bottomLevel();
  auto tlas = topLevel();
  cmd->open();
  REQUIRE_REJECTED(cmd->buildBottomLevelAccelStruct(tlas.get()),
                   ContainsSubstring("buildBottomLevelAccelStruct: 'scene TLAS' is a top level"));
  REQUIRE_REJECTED(
      cmd->buildTopLevelAccelStruct(blas.get(), nullptr, 0),
      ContainsSubstring("buildTopLevelAccelStruct: 'triangle BLAS' is a bottom level"));
}

TEST_CASE_METHOD(Fixture, "validation: a top level takes at most its instances, each with a BLAS",
                 "[rhi][validation]") {
  auto blas = bottomLevel();
  auto tlas = topLevel(1);
  std::vector<rt::InstanceDesc> instances(2);
  instances[0].bottomLevelAddress = blas->deviceAddress();
  cmd->open();
  REQUIRE_REJECTED(cmd->buildTopLevelAccelStruct(tlas.get(), instances.data(), 2),
                   ContainsSubstring("2 instances exceed 'scene TLAS' topLevelMaxInstances = 1"));
  instances[0].bottomLevelAddress = 0;
  REQUIRE_REJECTED(cmd->buildTopLevelAccelStruct(tlas.get(), instances.data(), 1),
                   ContainsSubstring("instance 0 of 'scene TLAS' has no bottom level"));
}

// ---- Pipelines ----------------------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: recursion depth within the device's limit",
                 "[rhi][validation]") {
  auto desc = probeDesc();
  desc.maxRecursionDepth = device->adapter().maxRecursionDepth + 1;
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("createRayTracingPipeline: pipeline 'probe pipeline' asks for "
                                     "recursion depth"));
}

TEST_CASE_METHOD(Fixture, "validation: hit attributes within 32 bytes", "[rhi][validation]") {
  auto desc = probeDesc();
  desc.maxAttributeBytes = 36;
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("36 attribute bytes exceed the APIs' 32"));
}

TEST_CASE_METHOD(Fixture, "validation: a ray-tracing pipeline holds no compute shader",
                 "[rhi][validation]") {
  auto desc = probeDesc();
  desc.shaders.push_back(shaders::shaderDesc("tonemap.comp"));
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("'tonemap.comp' is a compute shader"));
}

TEST_CASE_METHOD(Fixture, "validation: export names are unique", "[rhi][validation]") {
  auto desc = probeDesc();
  desc.hitGroups.push_back({"probe.rmiss", "probe.rchit", "", "", false});
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("export name 'probe.rmiss' used twice (already a shader)"));
}

TEST_CASE_METHOD(Fixture, "validation: a ray-tracing pipeline has a ray generation shader",
                 "[rhi][validation]") {
  auto desc = probeDesc();
  desc.shaders.erase(desc.shaders.begin());
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("pipeline 'probe pipeline' has no ray generation shader"));
}

TEST_CASE_METHOD(Fixture, "validation: hit groups name shaders of the right stage",
                 "[rhi][validation]") {
  auto desc = probeDesc();
  desc.hitGroups[0].closestHit = "nope.rchit";
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("hit group 'quad' names unknown shader 'nope.rchit'"));
  desc = probeDesc();
  desc.hitGroups[0].closestHit = "probe.rmiss";
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("hit group 'quad' uses 'probe.rmiss', a miss shader, as its "
                                     "closest hit"));
}

TEST_CASE_METHOD(Fixture,
                 "validation: procedural hit groups have an intersection shader, "
                 "triangle ones none",
                 "[rhi][validation]") {
  auto desc = probeDesc();
  desc.hitGroups[1].intersection = "";
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("procedural hit group 'sphere' has no intersection shader"));
  desc = probeDesc();
  desc.hitGroups[0].intersection = "sphere.rint";
  REQUIRE_REJECTED(device->createRayTracingPipeline(desc),
                   ContainsSubstring("triangle hit group 'quad' has an intersection shader"));
}

TEST_CASE_METHOD(Fixture, "validation: a compute pipeline takes a compute shader",
                 "[rhi][validation]") {
  ComputePipelineDesc desc;
  desc.shader = test_shaders::shaderDesc("probe.rgen");
  desc.debugName = "not compute";
  REQUIRE_REJECTED(device->createComputePipeline(desc),
                   ContainsSubstring("createComputePipeline: pipeline 'not compute': 'probe.rgen' "
                                     "is a ray generation shader"));
}

// ---- Shader tables --------------------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: shader-table records name exports of their kind",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto table = pipeline->createShaderTable("probe table");
  REQUIRE_REJECTED(
      table->setRayGenerationShader("probe.rmiss"),
      ContainsSubstring("setRayGenerationShader: shader table 'probe table': pipeline "
                        "'probe pipeline' has no ray generation shader 'probe.rmiss'"));
  REQUIRE_REJECTED(
      table->addMissShader("probe.rgen"),
      ContainsSubstring("addMissShader") && ContainsSubstring("no miss shader 'probe.rgen'"));
  REQUIRE_REJECTED(
      table->addHitGroup("probe.rchit"),
      ContainsSubstring("addHitGroup") && ContainsSubstring("no hit group 'probe.rchit'"));
}

TEST_CASE_METHOD(Fixture, "validation: local data no larger than the shaders read",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto table = pipeline->createShaderTable("probe table");
  const uint32_t tags[2] = {1, 2};
  REQUIRE(table->addMissShader("probe.rmiss", tags, 4) == 0);  // gTag: one uint
  REQUIRE_REJECTED(
      table->addMissShader("probe.rmiss", tags, 8),
      ContainsSubstring("8 bytes of local data for 'probe.rmiss', whose shaders read 4"));
  REQUIRE_REJECTED(table->addHitGroup("quad", tags, 8),
                   ContainsSubstring("8 bytes of local data for 'quad', whose shaders read 4"));
  REQUIRE_REJECTED(table->setRayGenerationShader("probe.rgen", tags, 4),
                   ContainsSubstring("for 'probe.rgen', whose shaders read 0"));
}

TEST_CASE_METHOD(Fixture,
                 "validation: tracing needs a shader table of the pipeline with a ray "
                 "generation record",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto other = device->createRayTracingPipeline(probeDesc());
  auto bindings = probeBindings(*pipeline);
  auto table = pipeline->createShaderTable("probe table");
  auto foreign = other->createShaderTable("other table");
  foreign->setRayGenerationShader("probe.rgen");
  cmd->open();
  REQUIRE_REJECTED(cmd->setRayTracingState({pipeline.get(), table.get(), {bindings.get()}}),
                   ContainsSubstring("setRayTracingState: shader table 'probe table' has no ray "
                                     "generation shader"));
  REQUIRE_REJECTED(cmd->setRayTracingState({pipeline.get(), foreign.get(), {bindings.get()}}),
                   ContainsSubstring("shader table 'other table' belongs to pipeline 'probe "
                                     "pipeline', not 'probe pipeline'"));
  REQUIRE_REJECTED(cmd->setRayTracingState({pipeline.get(), nullptr, {bindings.get()}}),
                   ContainsSubstring("pipeline 'probe pipeline': no shader table"));
}

// ---- Binding sets ---------------------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: a binding set fills every slot its space declares",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto rays = buffer(64, BufferUsage::StorageBuffer, "rays");
  BindingSetDesc set;
  set.debugName = "incomplete";
  set.items = {BindingSetItem::storageBuffer(33, rays)};
  REQUIRE_REJECTED(device->createBindingSet(set, *pipeline),
                   ContainsSubstring("createBindingSet: incomplete: slot 32 ('gScene') is bound 0 "
                                     "times"));
}

TEST_CASE_METHOD(Fixture, "validation: bound buffers carry the usage their slot needs",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto tlas = topLevel();
  auto plain = buffer(64, BufferUsage::CopyDest, "plain");
  auto storage = buffer(64, BufferUsage::StorageBuffer, "storage");
  BindingSetDesc set;
  set.debugName = "probe bindings";
  set.items = {BindingSetItem::accelStructure(32, tlas), BindingSetItem::storageBuffer(33, plain),
               BindingSetItem::storageBuffer(64, storage)};
  REQUIRE_REJECTED(device->createBindingSet(set, *pipeline),
                   ContainsSubstring("binding set 'probe bindings': buffer 'plain' at slot 33") &&
                       ContainsSubstring("lacks BufferUsage::StorageBuffer"));
}

TEST_CASE_METHOD(Fixture, "validation: buffers the shaders write are device-local",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto tlas = topLevel();
  auto rays = buffer(64, BufferUsage::StorageBuffer, "rays");
  auto results = buffer(64, BufferUsage::StorageBuffer, "results", MemoryLocation::Readback);
  BindingSetDesc set;
  set.debugName = "probe bindings";
  set.items = {BindingSetItem::accelStructure(32, tlas), BindingSetItem::storageBuffer(33, rays),
               BindingSetItem::storageBuffer(64, results)};
  REQUIRE_REJECTED(device->createBindingSet(set, *pipeline),
                   ContainsSubstring("buffer 'results' at slot 64") &&
                       ContainsSubstring("is written by shaders but is not device-local"));
}

TEST_CASE_METHOD(Fixture, "validation: a bound storage buffer holds a whole element",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto tlas = topLevel();
  auto rays = buffer(16, BufferUsage::StorageBuffer, "short rays");  // a ProbeRay is 32 bytes
  auto results = buffer(64, BufferUsage::StorageBuffer, "results");
  BindingSetDesc set;
  set.debugName = "probe bindings";
  set.items = {BindingSetItem::accelStructure(32, tlas), BindingSetItem::storageBuffer(33, rays),
               BindingSetItem::storageBuffer(64, results)};
  REQUIRE_REJECTED(device->createBindingSet(set, *pipeline),
                   ContainsSubstring("buffer 'short rays' (16 bytes) at slot 33") &&
                       ContainsSubstring("holds no whole 32-byte element"));
}

TEST_CASE_METHOD(Fixture, "validation: a bound storage texture has TextureUsage::Storage",
                 "[rhi][validation]") {
  auto pipeline = computePipeline("tonemap.comp", "tonemap");
  auto sampled = texture(TextureUsage::Sampled, "sampled hdr");
  auto pixels = buffer(64, BufferUsage::StorageBuffer, "pixels");
  BindingSetDesc set;
  set.debugName = "tonemap bindings";
  set.items = {BindingSetItem::storageTexture(PENUMBRA_T(TM_T_INPUT), sampled),
               BindingSetItem::storageBuffer(PENUMBRA_U(TM_U_OUTPUT), pixels)};
  REQUIRE_REJECTED(device->createBindingSet(set, *pipeline),
                   ContainsSubstring("texture 'sampled hdr' at slot 32") &&
                       ContainsSubstring("lacks TextureUsage::Storage"));
}

TEST_CASE_METHOD(Fixture, "validation: an acceleration-structure slot takes a top level",
                 "[rhi][validation][spirv-only]") {
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto blas = bottomLevel();
  auto rays = buffer(64, BufferUsage::StorageBuffer, "rays");
  auto results = buffer(64, BufferUsage::StorageBuffer, "results");
  BindingSetDesc set;
  set.debugName = "probe bindings";
  set.items = {BindingSetItem::accelStructure(32, blas), BindingSetItem::storageBuffer(33, rays),
               BindingSetItem::storageBuffer(64, results)};
  REQUIRE_REJECTED(device->createBindingSet(set, *pipeline),
                   ContainsSubstring("slot 32 ('gScene') takes a top level; 'triangle BLAS' is a "
                                     "bottom level"));
}

TEST_CASE_METHOD(Fixture, "validation: every space the pipeline uses gets its binding set",
                 "[rhi][validation]") {
  auto pipeline = computePipeline("tonemap.comp", "tonemap");
  cmd->open();
  REQUIRE_REJECTED(cmd->setComputeState({pipeline.get(), {}}),
                   ContainsSubstring("setComputeState: pipeline 'tonemap' uses space 0"));
  REQUIRE_REJECTED(cmd->setComputeState({pipeline.get(), {nullptr}}),
                   ContainsSubstring("pipeline 'tonemap': no binding set at index 0"));
}

TEST_CASE_METHOD(Fixture, "validation: a binding set sits at the index of its space",
                 "[rhi][validation]") {
  auto pipeline = computePipeline("tonemap.comp", "tonemap");
  auto set = tonemapBindings(*pipeline);
  cmd->open();
  REQUIRE_REJECTED(cmd->setComputeState({pipeline.get(), {set.get(), set.get()}}),
                   ContainsSubstring("binding set 'tonemap bindings' of space 0 given at index 1"));
}

TEST_CASE_METHOD(Fixture, "validation: a binding set is bound to a pipeline of its layout",
                 "[rhi][validation]") {
  auto tonemap = computePipeline("tonemap.comp", "tonemap");
  auto display = computePipeline("display.comp", "display");
  auto set = tonemapBindings(*tonemap);
  cmd->open();
  REQUIRE_REJECTED(cmd->setComputeState({display.get(), {set.get()}}),
                   ContainsSubstring("binding set 'tonemap bindings' was created for a pipeline "
                                     "whose space 0 differs from pipeline 'display's"));
}

// ---- Push constants and dispatches -------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: push constants need a bound pipeline that declares them",
                 "[rhi][validation][spirv-only]") {
  const uint32_t value[4] = {};
  cmd->open();
  REQUIRE_REJECTED(cmd->setPushConstants(value, 16),
                   ContainsSubstring("setPushConstants: command list 'test list': no pipeline is "
                                     "bound"));
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto bindings = probeBindings(*pipeline);
  auto table = pipeline->createShaderTable("probe table");
  table->setRayGenerationShader("probe.rgen");
  cmd->setRayTracingState({pipeline.get(), table.get(), {bindings.get()}});
  REQUIRE_REJECTED(cmd->setPushConstants(value, 16),
                   ContainsSubstring("pipeline 'probe pipeline' declares no push constants"));
}

TEST_CASE_METHOD(Fixture, "validation: push constants are the size the shaders declare",
                 "[rhi][validation]") {
  auto pipeline = computePipeline("tonemap.comp", "tonemap");
  auto set = tonemapBindings(*pipeline);
  const gpu::TonemapPush push{};
  cmd->open();
  cmd->setComputeState({pipeline.get(), {set.get()}});
  REQUIRE_REJECTED(
      cmd->setPushConstants(&push, 12),
      ContainsSubstring("setPushConstants: 12 bytes, but pipeline 'tonemap' declares 16"));
  cmd->setPushConstants(&push, sizeof(push));  // the right size passes
}

TEST_CASE_METHOD(Fixture, "validation: a dispatch needs the matching bound state",
                 "[rhi][validation]") {
  auto pipeline = computePipeline("tonemap.comp", "tonemap");
  auto set = tonemapBindings(*pipeline);
  cmd->open();
  REQUIRE_REJECTED(cmd->dispatch(1, 1, 1),
                   ContainsSubstring("dispatch: command list 'test list': no setComputeState"));
  cmd->setComputeState({pipeline.get(), {set.get()}});
  REQUIRE_REJECTED(cmd->dispatchRays(1, 1, 1),
                   ContainsSubstring("dispatchRays: command list 'test list': no "
                                     "setRayTracingState"));
}

TEST_CASE_METHOD(Fixture, "validation: dispatch sizes within both APIs' limits",
                 "[rhi][validation][spirv-only]") {
  auto compute = computePipeline("tonemap.comp", "tonemap");
  auto computeSet = tonemapBindings(*compute);
  cmd->open();
  cmd->setComputeState({compute.get(), {computeSet.get()}});
  REQUIRE_REJECTED(cmd->dispatch(65536, 1, 1),
                   ContainsSubstring("dispatch: 65536x1x1 thread groups; each dimension takes at "
                                     "most 65535"));
  auto pipeline = device->createRayTracingPipeline(probeDesc());
  auto bindings = probeBindings(*pipeline);
  auto table = pipeline->createShaderTable("probe table");
  table->setRayGenerationShader("probe.rgen");
  cmd->setRayTracingState({pipeline.get(), table.get(), {bindings.get()}});
  REQUIRE_REJECTED(cmd->dispatchRays(32768, 32769, 1),
                   ContainsSubstring("dispatchRays: 32768x32769x1 rays exceed the APIs' 2^30"));
}

// ---- Swapchains -----------------------------------------------------------------------

TEST_CASE_METHOD(Fixture, "validation: a swapchain keeps 1 to 4 frames in flight",
                 "[rhi][validation]") {
  SwapchainDesc desc;
  desc.framesInFlight = 5;
  desc.debugName = "window";
  REQUIRE_REJECTED(device->createSwapchain(desc),
                   ContainsSubstring("createSwapchain: swapchain 'window': 5 frames in flight"));
}
