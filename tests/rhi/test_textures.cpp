// Sampled textures, samplers and bindless arrays on the default device: a
// compute shader (texture_sample.comp) and a ray-generation shader
// (texture_sample.rgen) sample an unbounded texture array
// with an unbounded sampler array, indices chosen per invocation, and the
// results are checked against a host model of nearest/linear filtering, the
// address modes and the sRGB decode.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstring>
#include <random>

#include "bindings.hlsli"
#include "penumbra/util/error.h"
#include "penumbra_test_shaders.h"
#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

namespace {

// texture_sample.comp's t0, u0, t12[] and s0[].
constexpr uint32_t kQueriesSlot = PENUMBRA_T(0);
constexpr uint32_t kResultsSlot = PENUMBRA_U(0);
constexpr uint32_t kTexturesSlot = PENUMBRA_T(12);
constexpr uint32_t kSamplersSlot = PENUMBRA_S(0);

struct TextureQuery {
  float u, v;
  uint32_t textureIndex, samplerIndex;
};
static_assert(sizeof(TextureQuery) == 16);
using Color = std::array<float, 4>;

// A texture as the host models it: RGBA8 texels, sRGB-encoded colour (not
// alpha) when `srgb`.
struct HostTexture {
  uint32_t width, height;
  bool srgb;
  std::vector<uint8_t> texels;

  static float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  }
  // The texel as a shader reads it: UNORM to [0, 1], then the sRGB decode.
  Color fetch(uint32_t x, uint32_t y) const {
    Color c;
    for (int i = 0; i < 4; ++i) {
      const float v = texels[(size_t(y) * width + x) * 4 + i] / 255.0f;
      c[i] = srgb && i < 3 ? srgbToLinear(v) : v;
    }
    return c;
  }
};

// Integer texel coordinate after the address mode (Vulkan spec, "Wrapping
// Operation"; D3D12 WRAP/MIRROR/CLAMP agree).
uint32_t wrap(int i, uint32_t size, AddressMode mode) {
  const int n = int(size);
  switch (mode) {
    case AddressMode::Repeat:
      return uint32_t(((i % n) + n) % n);
    case AddressMode::MirroredRepeat: {
      const int t = ((i % (2 * n)) + 2 * n) % (2 * n);
      return uint32_t(t < n ? t : 2 * n - 1 - t);
    }
    case AddressMode::ClampToEdge:
      return uint32_t(std::clamp(i, 0, n - 1));
  }
  return 0;
}

// textureLod(..., 0): magnification, so magFilter decides. Nearest takes the
// texel holding uv; linear blends the four texels around uv - half a texel
// with weights from the texel centres.
Color sampleHost(const HostTexture& t, const SamplerDesc& s, float u, float v) {
  const float x = u * float(t.width), y = v * float(t.height);
  if (s.magFilter == Filter::Nearest)
    return t.fetch(wrap(int(std::floor(x)), t.width, s.addressU),
                   wrap(int(std::floor(y)), t.height, s.addressV));
  const float fx = x - 0.5f, fy = y - 0.5f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float a = fx - float(x0), b = fy - float(y0);
  const Color c00 = t.fetch(wrap(x0, t.width, s.addressU), wrap(y0, t.height, s.addressV));
  const Color c10 = t.fetch(wrap(x0 + 1, t.width, s.addressU), wrap(y0, t.height, s.addressV));
  const Color c01 = t.fetch(wrap(x0, t.width, s.addressU), wrap(y0 + 1, t.height, s.addressV));
  const Color c11 = t.fetch(wrap(x0 + 1, t.width, s.addressU), wrap(y0 + 1, t.height, s.addressV));
  Color c;
  for (int i = 0; i < 4; ++i)
    c[i] =
        (1 - a) * (1 - b) * c00[i] + a * (1 - b) * c10[i] + (1 - a) * b * c01[i] + a * b * c11[i];
  return c;
}

// 4x4 UNORM with sixteen distinct texels in every channel, and 2x2 sRGB.
std::vector<HostTexture> makeHostTextures() {
  HostTexture unorm{4, 4, false, {}};
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      const uint8_t k = uint8_t(y * 4 + x);
      unorm.texels.insert(unorm.texels.end(),
                          {uint8_t(8 + 16 * k), uint8_t(247 - 16 * k),
                           uint8_t(8 + 16 * ((k * 5) % 16)), uint8_t(128 + 8 * k)});
    }
  HostTexture srgb{2, 2, true, {}};
  srgb.texels = {20, 200, 90, 255, 240, 30, 160, 100, 130, 250, 10, 40, 60, 110, 230, 180};
  return {unorm, srgb};
}

std::vector<SamplerDesc> makeSamplerDescs() {
  std::vector<SamplerDesc> descs;
  for (Filter f : {Filter::Nearest, Filter::Linear})
    for (AddressMode m :
         {AddressMode::Repeat, AddressMode::MirroredRepeat, AddressMode::ClampToEdge}) {
      SamplerDesc d;
      d.minFilter = d.magFilter = f;
      d.addressU = d.addressV = m;
      d.debugName =
          fmt::format("{} sampler {}", f == Filter::Nearest ? "nearest" : "linear", int(m));
      descs.push_back(d);
    }
  SamplerDesc mixed;  // U and V address modes apart
  mixed.addressU = AddressMode::MirroredRepeat;
  mixed.addressV = AddressMode::ClampToEdge;
  mixed.debugName = "linear mirrored/clamp sampler";
  descs.push_back(mixed);
  return descs;
}

TextureHandle createSampledTexture(IDevice& device, const HostTexture& t, const char* name) {
  TextureDesc desc;
  desc.width = t.width;
  desc.height = t.height;
  desc.format = t.srgb ? Format::RGBA8_SRGB : Format::RGBA8_UNORM;
  desc.usage = TextureUsage::Sampled | TextureUsage::CopyDest;
  desc.debugName = name;
  return device.createTexture(desc);
}

ComputePipelineHandle createSamplePipeline(IDevice& device) {
  ComputePipelineDesc desc;
  desc.shader = test_shaders::shaderDesc("texture_sample.comp");
  desc.debugName = "texture sample";
  return device.createComputePipeline(desc);
}

BufferHandle createStorageBuffer(IDevice& device, uint64_t bytes, const char* name) {
  BufferDesc desc;
  desc.byteSize = bytes;
  desc.usage = BufferUsage::StorageBuffer;
  desc.debugName = name;
  return device.createBuffer(desc);
}

}  // namespace

TEST_CASE("textures: bindless sampling matches the host model of filters, address modes and sRGB",
          "[rhi][gpu][textures][spirv-only]") {
  auto device = test::makeTestDevice();
  const auto hostTextures = makeHostTextures();
  const auto samplerDescs = makeSamplerDescs();

  // Texel-boundary-free coordinates (nearest is exact away from boundaries),
  // inside [0, 1] and up to two periods outside it on both sides.
  const float coords[] = {-1.3f, -0.6f, -0.1f, 0.05f, 0.3f, 0.55f, 0.8f, 0.97f, 1.2f, 1.7f, 2.4f};
  std::vector<TextureQuery> queries;
  for (float u : coords)
    for (float v : coords)
      for (uint32_t t = 0; t < hostTextures.size(); ++t)
        for (uint32_t s = 0; s < samplerDescs.size(); ++s) queries.push_back({u, v, t, s});
  // Shuffled, so neighbouring invocations use different textures and samplers
  // (non-uniform indexing) - checked below rather than assumed.
  std::shuffle(queries.begin(), queries.end(), std::mt19937(1234));
  size_t divergent = 0;
  for (size_t i = 1; i < queries.size(); ++i)
    divergent += queries[i].textureIndex != queries[i - 1].textureIndex ||
                 queries[i].samplerIndex != queries[i - 1].samplerIndex;
  REQUIRE(divergent > queries.size() * 3 / 4);

  auto cmd = device->createCommandList();
  cmd->open();
  std::vector<TextureHandle> textures;
  for (size_t i = 0; i < hostTextures.size(); ++i) {
    textures.push_back(
        createSampledTexture(*device, hostTextures[i], i == 0 ? "unorm 4x4" : "srgb 2x2"));
    cmd->writeTexture(textures.back().get(), hostTextures[i].texels.data(),
                      hostTextures[i].texels.size());
  }
  std::vector<SamplerHandle> samplers;
  for (const auto& d : samplerDescs) samplers.push_back(device->createSampler(d));
  REQUIRE(samplers[1]->desc().addressU == AddressMode::MirroredRepeat);

  const uint64_t queryBytes = queries.size() * sizeof(TextureQuery);
  const uint64_t resultBytes = queries.size() * sizeof(Color);
  auto queryBuffer = createStorageBuffer(*device, queryBytes, "texture queries");
  cmd->writeBuffer(queryBuffer.get(), queries.data(), queryBytes);
  auto results = createStorageBuffer(*device, resultBytes, "texture results");
  BufferDesc readbackDesc;
  readbackDesc.byteSize = resultBytes;
  readbackDesc.memory = MemoryLocation::Readback;
  readbackDesc.usage = BufferUsage::CopyDest;
  readbackDesc.debugName = "texture readback";
  auto readback = device->createBuffer(readbackDesc);

  BindingSetDesc set;
  set.debugName = "texture bindings";
  set.items = {BindingSetItem::storageBuffer(kQueriesSlot, queryBuffer),
               BindingSetItem::storageBuffer(kResultsSlot, results),
               BindingSetItem::sampledTextures(kTexturesSlot, textures),
               BindingSetItem::samplers(kSamplersSlot, samplers)};
  const uint32_t count = uint32_t(queries.size());
  // The same queries from a compute shader or a ray-generation shader.
  ComputePipelineHandle computePipeline;
  RayTracingPipelineHandle rayTracingPipeline;
  ShaderTableHandle shaderTable;
  BindingSetHandle bindings;
  SECTION("compute") {
    computePipeline = createSamplePipeline(*device);
    bindings = device->createBindingSet(set, *computePipeline);
    cmd->setComputeState({computePipeline.get(), {bindings.get()}});
    cmd->setPushConstants(&count, sizeof(count));
    cmd->dispatch((count + 63) / 64);
  }
  SECTION("ray generation") {
    RayTracingPipelineDesc desc;
    desc.shaders = {test_shaders::shaderDesc("texture_sample.rgen")};
    desc.debugName = "texture sample rgen";
    rayTracingPipeline = device->createRayTracingPipeline(desc);
    shaderTable = rayTracingPipeline->createShaderTable("texture sample table");
    shaderTable->setRayGenerationShader("texture_sample.rgen");
    bindings = device->createBindingSet(set, *rayTracingPipeline);
    cmd->setRayTracingState({rayTracingPipeline.get(), shaderTable.get(), {bindings.get()}});
    cmd->setPushConstants(&count, sizeof(count));
    cmd->dispatchRays(count, 1);
  }
  REQUIRE(textures[0]->state == ResourceState::ShaderResource);  // moved there by the binding set
  cmd->copyBuffer(readback.get(), 0, results.get(), 0, resultBytes);
  cmd->close();
  device->submit(cmd.get());
  device->waitForIdle();

  std::vector<Color> got(queries.size());
  std::memcpy(got.data(), readback->mappedData(), resultBytes);

  // Tolerances. Nearest: the texel itself, UNORM conversion exact up to float
  // rounding. sRGB decodes come from a polynomial approximation on some
  // implementations (lavapipe is off by up to ~0.15% of the value, 1.1e-3 at
  // 0.79), so 1e-3 plus 0.2% of the value. Linear: GPUs (lavapipe too)
  // quantize the bilinear weights to 8 fractional bits, an error of up to
  // 1/256 per lerp times a texel difference of at most 1, two lerps; UNORM
  // results may also be rounded to 8 bits (1/255).
  size_t failures = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    const auto& q = queries[i];
    const auto& t = hostTextures[q.textureIndex];
    const auto& s = samplerDescs[q.samplerIndex];
    const Color expected = sampleHost(t, s, q.u, q.v);
    const bool linear = s.magFilter == Filter::Linear;
    for (int c = 0; c < 4; ++c) {
      const float tolerance =
          (linear ? 2.0f / 256 : 0.0f) +
          (t.srgb ? 1e-3f + 2e-3f * expected[c] : (linear ? 1.0f / 255 : 1e-5f));
      if (std::abs(got[i][c] - expected[c]) <= tolerance) continue;
      if (++failures <= 10)
        UNSCOPED_INFO(fmt::format(
            "query {}: texture {} sampler '{}' uv ({}, {}) channel {}: got {} expected {} "
            "(tolerance {})",
            i, q.textureIndex, s.debugName, q.u, q.v, c, got[i][c], expected[c], tolerance));
    }
  }
  CHECK(failures == 0u);

  // The model itself must tell the filters and address modes apart on these
  // coordinates, or the comparison above would prove little.
  const auto& unorm = hostTextures[0];
  CHECK(sampleHost(unorm, samplerDescs[0], -0.1f, 0.3f)[0] !=
        sampleHost(unorm, samplerDescs[1], -0.1f, 0.3f)[0]);
  CHECK(sampleHost(unorm, samplerDescs[0], -0.1f, 0.3f)[0] !=
        sampleHost(unorm, samplerDescs[2], -0.1f, 0.3f)[0]);
  CHECK(std::abs(sampleHost(unorm, samplerDescs[0], 0.3f, 0.3f)[0] -
                 sampleHost(unorm, samplerDescs[3], 0.3f, 0.3f)[0]) > 0.02f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: binding sets with bad texture or sampler arrays are clear errors",
          "[rhi][gpu][textures][spirv-only]") {
  auto device = test::makeTestDevice();
  auto pipeline = createSamplePipeline(*device);
  auto texture = createSampledTexture(*device, makeHostTextures()[0], "unorm 4x4");
  auto sampler = device->createSampler(SamplerDesc{});
  auto queries = createStorageBuffer(*device, 16, "queries");
  auto results = createStorageBuffer(*device, 16, "results");

  BindingSetDesc set;
  set.debugName = "bad bindings";
  set.items = {BindingSetItem::storageBuffer(kQueriesSlot, queries),
               BindingSetItem::storageBuffer(kResultsSlot, results),
               BindingSetItem::sampledTextures(kTexturesSlot, {texture}),
               BindingSetItem::samplers(kSamplersSlot, {sampler})};
  REQUIRE_NOTHROW(device->createBindingSet(set, *pipeline));

  SECTION("more elements than an unbounded array takes") {
    set.items[2].textures.assign(kMaxBindlessDescriptors + 1, texture);
    REQUIRE_THROWS_WITH(device->createBindingSet(set, *pipeline),
                        ContainsSubstring("slot 44") && ContainsSubstring("gTextures") &&
                            ContainsSubstring("1 to 4096") && ContainsSubstring("4097"));
  }
  SECTION("an empty array") {
    set.items[3].samplerHandles.clear();
    REQUIRE_THROWS_WITH(device->createBindingSet(set, *pipeline),
                        ContainsSubstring("slot 96") && ContainsSubstring("0 were bound"));
  }
  SECTION("no sampler array at all") {
    set.items.pop_back();
    REQUIRE_THROWS_WITH(device->createBindingSet(set, *pipeline),
                        ContainsSubstring("slot 96") && ContainsSubstring("gSamplers") &&
                            ContainsSubstring("0 times"));
  }
  SECTION("samplers where the shaders declare textures") {
    set.items[2] = BindingSetItem::samplers(kTexturesSlot, {sampler});
    REQUIRE_THROWS_WITH(device->createBindingSet(set, *pipeline),
                        ContainsSubstring("slot 44") && ContainsSubstring("is a sampled texture") &&
                            ContainsSubstring("a sampler was bound"));
  }
  SECTION("a null element") {
    set.items[2].textures.push_back(nullptr);
    REQUIRE_THROWS_WITH(device->createBindingSet(set, *pipeline),
                        ContainsSubstring("slot 44") && ContainsSubstring("element 1"));
  }
  SECTION("a texture not created for sampling") {
    TextureDesc desc;
    desc.width = desc.height = 2;
    desc.format = Format::RGBA8_UNORM;
    desc.usage = TextureUsage::Storage;
    desc.debugName = "storage only";
    set.items[2].textures = {texture, device->createTexture(desc)};
    REQUIRE_THROWS_WITH(
        device->createBindingSet(set, *pipeline),
        ContainsSubstring("storage only") && ContainsSubstring("TextureUsage::Sampled"));
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: writeTexture sizes and sRGB storage textures are checked",
          "[rhi][gpu][textures]") {
  auto device = test::makeTestDevice();
  auto texture = createSampledTexture(*device, makeHostTextures()[0], "unorm 4x4");
  auto cmd = device->createCommandList();
  cmd->open();
  std::vector<uint8_t> data(4 * 4 * 4 - 4);
  REQUIRE_THROWS_WITH(cmd->writeTexture(texture.get(), data.data(), data.size()),
                      ContainsSubstring("unorm 4x4") && ContainsSubstring("64 bytes"));
  cmd->close();

  TextureDesc desc;
  desc.format = Format::RGBA8_SRGB;
  desc.usage = TextureUsage::Storage;
  desc.debugName = "srgb storage";
  REQUIRE_THROWS_WITH(device->createTexture(desc), ContainsSubstring("srgb storage"));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
