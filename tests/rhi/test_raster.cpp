// The RHI's raster subset (rhi/pipeline.h, ICommandList::beginRendering and
// friends): coverage, clip-space orientation, blending, scissor, index and
// vertex offsets against hand-worked pixels, and the validation layer's rules.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

#include "penumbra_test_shaders.h"
#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

namespace {

constexpr uint32_t kSize = 64;

struct Vertex {
  float x, y;          // clip space
  uint8_t r, g, b, a;  // RGBA8_UNORM
};

struct Rgba {
  int r, g, b, a;
};

Rgba pixel(const std::vector<uint8_t>& image, uint32_t x, uint32_t y) {
  const uint8_t* p = &image[(size_t(y) * kSize + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

bool near(Rgba a, Rgba b, int tolerance) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
         std::abs(a.b - b.b) <= tolerance && std::abs(a.a - b.a) <= tolerance;
}

// Counts the pixels that differ from expected(x, y) by more than `tolerance`
// per channel; expected returns false for pixels it does not judge.
size_t mismatches(const std::vector<uint8_t>& image, int tolerance,
                  const std::function<bool(uint32_t, uint32_t, Rgba&)>& expected) {
  size_t bad = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      Rgba want{};
      if (expected(x, y, want) && !near(pixel(image, x, y), want, tolerance)) ++bad;
    }
  return bad;
}

struct RasterRig {
  DeviceHandle device = test::makeTestDevice();
  TextureHandle target;
  BufferHandle readback;

  RasterRig() {
    TextureDesc t;
    t.width = t.height = kSize;
    t.format = Format::RGBA8_UNORM;
    t.usage = TextureUsage::RenderTarget | TextureUsage::CopySource;
    t.debugName = "raster target";
    target = device->createTexture(t);
    BufferDesc b;
    b.byteSize = kSize * kSize * 4;
    b.usage = BufferUsage::CopyDest;
    b.memory = MemoryLocation::Readback;
    b.debugName = "raster readback";
    readback = device->createBuffer(b);
  }

  GraphicsPipelineHandle pipeline(BlendMode blend) {
    GraphicsPipelineDesc desc;
    desc.vertexShader = test_shaders::shaderDesc("raster_color.vert");
    desc.pixelShader = test_shaders::shaderDesc("raster_color.frag");
    desc.vertexLayout.stride = sizeof(Vertex);
    desc.vertexLayout.attributes = {{0, Format::RG32_FLOAT, 0}, {1, Format::RGBA8_UNORM, 8}};
    desc.blend = blend;
    desc.debugName = "raster test";
    return device->createGraphicsPipeline(desc);
  }

  BufferHandle upload(const void* data, size_t bytes, BufferUsage usage, const char* name) {
    BufferDesc b;
    b.byteSize = bytes;
    b.usage = usage;
    b.memory = MemoryLocation::Upload;
    b.debugName = name;
    auto buffer = device->createBuffer(b);
    std::memcpy(buffer->mappedData(), data, bytes);
    return buffer;
  }

  // Clears the target, draws, reads it back.
  struct Draw {
    uint32_t indexCount = 0, firstIndex = 0;
    int32_t vertexOffset = 0;
    const ScissorRect* scissor = nullptr;
  };
  std::vector<uint8_t> render(IGraphicsPipeline& pipeline, const std::vector<Vertex>& vertices,
                              const std::vector<uint16_t>& indices, const float clear[4],
                              Draw draw) {
    auto vb = upload(vertices.data(), vertices.size() * sizeof(Vertex), BufferUsage::VertexBuffer,
                     "raster vertices");
    auto ib =
        upload(indices.data(), indices.size() * 2, BufferUsage::IndexBuffer, "raster indices");
    auto list = device->createCommandList("raster test");
    list->open();
    GraphicsState state;
    state.pipeline = &pipeline;
    state.vertexBuffer = vb.get();
    state.indexBuffer = ib.get();
    list->setGraphicsState(state);
    list->beginRendering(target.get(), clear);
    if (draw.scissor) list->setScissor(*draw.scissor);
    list->drawIndexed(draw.indexCount, draw.firstIndex, draw.vertexOffset);
    list->endRendering();
    list->copyTextureToBuffer(target.get(), readback.get());
    list->close();
    device->submit(list.get());
    device->waitForIdle();
    const auto* bytes = static_cast<const uint8_t*>(readback->mappedData());
    return std::vector<uint8_t>(bytes, bytes + kSize * kSize * 4);
  }
};

const std::vector<Vertex> kFullQuad(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  return {{-1, 1, r, g, b, a}, {1, 1, r, g, b, a}, {-1, -1, r, g, b, a}, {1, -1, r, g, b, a}};
}
const std::vector<uint16_t> kQuadIndices = {0, 1, 2, 2, 1, 3};
const float kBlack[4] = {0, 0, 0, 1};
const float kBlue[4] = {0, 0, 1, 1};

}  // namespace

// Clip-space (-1, 1) is the top-left corner on both backends (+y up, D3D12's
// convention; Vulkan's viewport is flipped), so this triangle covers the
// upper-left half: pixel (x, y), row y from the top, whose centre satisfies
// (x + 0.5) + (y + 0.5) < 64. The pixels on the diagonal itself belong to
// the fill rule and are not judged. A flipped y covers the lower-left half
// instead: half the pixels wrong.
TEST_CASE("raster: a triangle covers exactly the pixels whose centres it contains, +y up",
          "[rhi][raster][spirv-only]") {
  RasterRig rig;
  auto pipeline = rig.pipeline(BlendMode::Opaque);
  const std::vector<Vertex> triangle = {
      {-1, 1, 255, 0, 0, 255}, {1, 1, 255, 0, 0, 255}, {-1, -1, 255, 0, 0, 255}};
  auto image = rig.render(*pipeline, triangle, {0, 1, 2}, kBlack, {3});
  size_t covered = 0;
  const size_t bad = mismatches(image, 0, [&](uint32_t x, uint32_t y, Rgba& want) {
    if (x + y + 1 == kSize) return false;
    const bool inside = x + y + 1 < kSize;
    covered += inside;
    want = inside ? Rgba{255, 0, 0, 255} : Rgba{0, 0, 0, 255};
    return true;
  });
  CHECK(covered == kSize * (kSize - 1) / 2);
  CHECK(bad == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(rig.device);
}

// src = (1, 0, 0, a) with a = 128/255 over dst = (0, 0, 1, 1):
// colour = src * a + dst * (1 - a) = (128, 0, 127) in 8 bits, alpha =
// a + 1 * (1 - a) = 255. Opaque writes src as it is. One code of tolerance
// for the blend unit's rounding; a wrong factor (dst alpha, premultiplied,
// no blending) moves a channel by 127 or more.
TEST_CASE("raster: alpha blending and opaque writes give the hand-worked 8-bit values",
          "[rhi][raster][spirv-only]") {
  RasterRig rig;
  auto blended = rig.pipeline(BlendMode::AlphaBlend);
  auto image = rig.render(*blended, kFullQuad(255, 0, 0, 128), kQuadIndices, kBlue, {6});
  CHECK(mismatches(image, 1, [](uint32_t, uint32_t, Rgba& want) {
          want = {128, 0, 127, 255};
          return true;
        }) == 0);
  auto opaque = rig.pipeline(BlendMode::Opaque);
  image = rig.render(*opaque, kFullQuad(255, 0, 0, 128), kQuadIndices, kBlue, {6});
  CHECK(mismatches(image, 0, [](uint32_t, uint32_t, Rgba& want) {
          want = {255, 0, 0, 128};
          return true;
        }) == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(rig.device);
}

// Two quads in one buffer: a green one at vertices 0-3 and a white one at
// 4-7. Indices 0-2 draw one triangle, 3-8 a whole quad (relative to the
// vertex offset). drawIndexed(6, 3, 4) with a scissor must give white
// exactly inside the scissor: ignoring firstIndex leaves half of it black,
// ignoring vertexOffset paints it green, ignoring the scissor paints it all.
TEST_CASE("raster: scissor, first index and vertex offset select what is drawn where",
          "[rhi][raster][spirv-only]") {
  RasterRig rig;
  auto pipeline = rig.pipeline(BlendMode::Opaque);
  std::vector<Vertex> vertices = kFullQuad(0, 255, 0, 255);
  for (const auto& v : kFullQuad(255, 255, 255, 255)) vertices.push_back(v);
  const std::vector<uint16_t> indices = {0, 1, 2, 0, 1, 2, 2, 1, 3};
  const ScissorRect scissor{8, 4, 20, 10};
  auto image = rig.render(*pipeline, vertices, indices, kBlack, {6, 3, 4, &scissor});
  CHECK(mismatches(image, 0, [&](uint32_t x, uint32_t y, Rgba& want) {
          const bool inside = x >= 8 && x < 28 && y >= 4 && y < 14;
          want = inside ? Rgba{255, 255, 255, 255} : Rgba{0, 0, 0, 255};
          return true;
        }) == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(rig.device);
}

TEST_CASE("raster: the validation layer's rules for pipelines and rendering passes",
          "[rhi][raster][validation][spirv-only]") {
  RasterRig rig;
  auto& device = rig.device;
  auto pipeline = rig.pipeline(BlendMode::Opaque);
  const auto quad = kFullQuad(1, 2, 3, 4);
  auto vb = rig.upload(quad.data(), quad.size() * sizeof(Vertex), BufferUsage::VertexBuffer, "vb");
  auto ib =
      rig.upload(kQuadIndices.data(), kQuadIndices.size() * 2, BufferUsage::IndexBuffer, "ib");
  GraphicsState state;
  state.pipeline = pipeline.get();
  state.vertexBuffer = vb.get();
  state.indexBuffer = ib.get();
  auto list = device->createCommandList("rules");

  SECTION("pipelines") {
    GraphicsPipelineDesc desc = pipeline->desc();
    std::swap(desc.vertexShader, desc.pixelShader);
    REQUIRE_THROWS_WITH(device->createGraphicsPipeline(desc),
                        ContainsSubstring("createGraphicsPipeline: pipeline 'raster test': the "
                                          "vertex shader 'raster_color.frag' is a pixel shader"));
    desc = pipeline->desc();
    desc.vertexLayout.attributes[1].offset = 10;
    REQUIRE_THROWS_WITH(
        device->createGraphicsPipeline(desc),
        ContainsSubstring("attribute 1 (4 bytes at offset 10) overflows the 12-byte vertex"));
    desc = pipeline->desc();
    desc.renderTargetFormat = Format::RGBA32_FLOAT;
    REQUIRE_THROWS_WITH(device->createGraphicsPipeline(desc),
                        ContainsSubstring("render targets are RGBA8_UNORM or BGRA8_UNORM"));
  }
  SECTION("draws only inside a pass, copies and dispatches only outside") {
    list->open();
    list->setGraphicsState(state);
    REQUIRE_THROWS_WITH(list->drawIndexed(6),
                        ContainsSubstring("drawIndexed: command list 'rules': no beginRendering"));
    list->beginRendering(rig.target.get());
    REQUIRE_THROWS_WITH(
        list->copyTextureToBuffer(rig.target.get(), rig.readback.get(), 0),
        ContainsSubstring("copyTextureToBuffer: command list 'rules' is rendering into "
                          "texture 'raster target'; call endRendering first"));
    REQUIRE_THROWS_WITH(list->close(), ContainsSubstring("call endRendering first"));
    REQUIRE_THROWS_WITH(list->drawIndexed(7),
                        ContainsSubstring("drawIndexed: indices 0 .. 7 overflow"));
    REQUIRE_THROWS_WITH(list->setScissor({60, 0, 8, 8}),
                        ContainsSubstring("setScissor: scissor (60, 0) 8x8 leaves"));
    list->drawIndexed(6);
    list->endRendering();
    REQUIRE_THROWS_WITH(list->endRendering(),
                        ContainsSubstring("endRendering: command list 'rules': no beginRendering"));
    list->close();
  }
  SECTION("inside a pass, everything a draw reads must already be in its state") {
    auto fresh = rig.upload(quad.data(), quad.size() * sizeof(Vertex), BufferUsage::VertexBuffer,
                            "fresh vb");
    GraphicsState unprepared = state;
    unprepared.vertexBuffer = fresh.get();
    list->open();
    list->beginRendering(rig.target.get());
    REQUIRE_THROWS_WITH(
        list->setGraphicsState(unprepared),
        ContainsSubstring("inside beginRendering, buffer 'fresh vb' is in Undefined but the "
                          "draw needs VertexInput"));
    list->endRendering();
    list->close();
  }
  SECTION("vertex and index buffers need their usages") {
    auto plain =
        rig.upload(quad.data(), quad.size() * sizeof(Vertex), BufferUsage::CopySource, "plain");
    GraphicsState wrong = state;
    wrong.indexBuffer = plain.get();
    list->open();
    REQUIRE_THROWS_WITH(list->setGraphicsState(wrong),
                        ContainsSubstring("buffer 'plain' lacks BufferUsage::IndexBuffer"));
    list->close();
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
