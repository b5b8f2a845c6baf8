// The tone curves of PNG output and the viewer's display (shaders/shared/tonemap.hlsli)
// against their published formulas, evaluated here on the CPU.
#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <glm/glm.hpp>

#include "penumbra/batch/render_settings.h"
#include "penumbra/render/display_pass.h"
#include "penumbra/render/tonemapper.h"
#include "test_device.h"

using namespace penumbra;

namespace {

double srgb(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

// Stephen Hill's ACES fit (BakingLab ACES.hlsl): input matrix, RRT+ODT
// rational fit, output matrix.
glm::dvec3 acesFitted(glm::dvec3 c) {
  const double in[3][3] = {
      {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
  const double out[3][3] = {
      {1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
  glm::dvec3 v, r;
  for (int i = 0; i < 3; ++i) v[i] = in[i][0] * c.x + in[i][1] * c.y + in[i][2] * c.z;
  for (int i = 0; i < 3; ++i)
    v[i] = (v[i] * (v[i] + 0.0245786) - 0.000090537) /
           (v[i] * (0.983729 * v[i] + 0.4329510) + 0.238081);
  for (int i = 0; i < 3; ++i) r[i] = out[i][0] * v.x + out[i][1] * v.y + out[i][2] * v.z;
  return r;
}

rhi::TextureHandle uniformHdr(rhi::IDevice& device, glm::vec3 value) {
  rhi::TextureDesc desc;
  desc.width = 8;
  desc.height = 8;
  desc.usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource;
  desc.debugName = "hdr";
  auto texture = device.createTexture(desc);
  auto list = device.createCommandList();
  list->open();
  list->clearTextureFloat(texture.get(), value.x, value.y, value.z, 1.0f);
  list->close();
  device.submit(list.get());
  device.waitForIdle();
  return texture;
}

int byte(double display) {
  return int(display * 255.0 + 0.5);
}

}  // namespace

TEST_CASE("tone mapping: clamp, Reinhard and ACES follow their formulas", "[render][gpu]") {
  auto device = test::makeTestDevice();
  const glm::vec3 hdr(0.25f, 1.0f, 4.0f);
  const float exposure = 0.5f;
  auto texture = uniformHdr(*device, hdr);
  render::Tonemapper tonemapper(*device);
  const glm::dvec3 exposed = glm::dvec3(hdr) * double(exposure);
  const glm::dvec3 aces = acesFitted(exposed);
  struct Case {
    render::ToneMapOperator op;
    glm::dvec3 curve;
  } cases[] = {{render::ToneMapOperator::Clamp, exposed},
               {render::ToneMapOperator::Reinhard, exposed / (exposed + 1.0)},
               {render::ToneMapOperator::AcesFitted, aces}};
  for (const auto& c : cases) {
    INFO("operator " << render::toneMapOperatorName(c.op));
    const auto image = tonemapper.run(texture, exposure, c.op);
    // Single-precision GPU math against double here: within one 8-bit step.
    for (int channel = 0; channel < 3; ++channel)
      CHECK(std::abs(int(image.rgba[size_t(channel)]) - byte(srgb(c.curve[channel]))) <= 1);
    CHECK(image.rgba[3] == 255);
  }
  // The curves differ where they should: 2.0 clips under clamp, not under the others.
  CHECK(byte(srgb(exposed.z)) == 255);
  CHECK(byte(srgb(exposed.z / (exposed.z + 1.0))) < 255);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("display pass: fills a target of another size with the tone-mapped image",
          "[render][gpu]") {
  auto device = test::makeTestDevice();
  // An 8x8 source shown at 6x3 (an uneven downscale): every target texel written.
  render::DisplayPass pass(*device);
  rhi::TextureDesc desc;
  desc.width = 6;
  desc.height = 3;
  desc.format = rhi::Format::RGBA8_UNORM;
  desc.usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource;
  desc.debugName = "display";
  auto target = device->createTexture(desc);
  rhi::BufferDesc readback;
  readback.byteSize = 6 * 3 * 4;
  readback.usage = rhi::BufferUsage::CopyDest;
  readback.memory = rhi::MemoryLocation::Readback;
  readback.debugName = "display readback";
  auto buffer = device->createBuffer(readback);
  for (double value : {0.2, 0.8}) {
    auto source = uniformHdr(*device, glm::vec3(float(value)));
    auto list = device->createCommandList();
    list->open();
    pass.record(*list, source, target, {1.0f, render::ToneMapOperator::Clamp});
    list->copyTextureToBuffer(target.get(), buffer.get());
    list->close();
    device->submit(list.get());
    device->waitForIdle();
    const auto* pixels = static_cast<const uint8_t*>(buffer->mappedData());
    for (int i = 0; i < 6 * 3; ++i) {
      CHECK(std::abs(int(pixels[i * 4]) - byte(srgb(value))) <= 1);
      CHECK(pixels[i * 4 + 3] == 255);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
