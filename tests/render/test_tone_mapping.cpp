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

// Khronos PBR Neutral as its specification writes it (KhronosGroup/
// ToneMapping, PBR_Neutral/README.md): F90 = 0.04, Ks = 0.8 - F90, Kd = 0.15.
glm::dvec3 pbrNeutral(glm::dvec3 c) {
  const double f90 = 0.04, ks = 0.8 - f90, kd = 0.15;
  const double x = std::min({c.r, c.g, c.b});
  const double f = x <= 2.0 * f90 ? x - x * x / (4.0 * f90) : f90;
  const double p = std::max({c.r - f, c.g - f, c.b - f});
  if (p <= ks) return c - f;
  const double pn = 1.0 - (1.0 - ks) * (1.0 - ks) / (p + 1.0 - 2.0 * ks);
  const double g = 1.0 / (kd * (p - pn) + 1.0);
  return (c - f) * (pn / p) * g + glm::dvec3(pn) * (1.0 - g);
}

// GLSL's mat3(a, b, c) times v: a, b, c are the columns (as three.js and
// Filament write their AgX matrices, which are transcribed so here).
glm::dvec3 columns(const double m[3][3], glm::dvec3 v) {
  glm::dvec3 r(0.0);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) r[row] += m[col][row] * v[col];
  return r;
}

// AgX as three.js's AgXToneMapping (after Filament) computes it.
glm::dvec3 agx(glm::dvec3 c) {
  const double toRec2020[3][3] = {
      {0.6274, 0.0691, 0.0164}, {0.3293, 0.9195, 0.0880}, {0.0433, 0.0113, 0.8956}};
  const double toRec709[3][3] = {
      {1.6605, -0.1246, -0.0182}, {-0.5876, 1.1329, -0.1006}, {-0.0728, -0.0083, 1.1187}};
  const double inset[3][3] = {{0.856627153315983, 0.137318972929847, 0.11189821299995},
                              {0.0951212405381588, 0.761241990602591, 0.0767994186031903},
                              {0.0482516061458583, 0.101439036467562, 0.811302368396859}};
  const double outset[3][3] = {{1.1271005818144368, -0.1413297634984383, -0.14132976349843826},
                               {-0.11060664309660323, 1.157823702216272, -0.11060664309660294},
                               {-0.016493938717834573, -0.016493938717834257, 1.2519364065950405}};
  // log2(2^-10 x 0.18) and log2(2^6.5 x 0.18).
  const double minEv = std::log2(std::pow(2.0, -10.0) * 0.18);
  const double maxEv = std::log2(std::pow(2.0, 6.5) * 0.18);
  c = columns(inset, columns(toRec2020, c));
  for (int i = 0; i < 3; ++i) {
    double x = std::clamp((std::log2(std::max(c[i], 1e-10)) - minEv) / (maxEv - minEv), 0.0, 1.0);
    x = 15.5 * std::pow(x, 6) - 40.14 * std::pow(x, 5) + 31.96 * std::pow(x, 4) -
        6.868 * std::pow(x, 3) + 0.4298 * x * x + 0.1191 * x - 0.00232;
    c[i] = x;
  }
  c = columns(outset, c);
  for (int i = 0; i < 3; ++i) c[i] = std::pow(std::max(c[i], 0.0), 2.2);
  c = columns(toRec709, c);
  return glm::clamp(c, 0.0, 1.0);
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

TEST_CASE("tone mapping: clamp, Reinhard, ACES, PBR Neutral and AgX follow their formulas",
          "[render][gpu]") {
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
               {render::ToneMapOperator::AcesFitted, aces},
               {render::ToneMapOperator::PbrNeutral, pbrNeutral(exposed)},
               {render::ToneMapOperator::AgX, agx(exposed)}};
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
  CHECK(byte(srgb(pbrNeutral(exposed).z)) < 255);
  // PBR Neutral's promise, by hand: a colour below its compression shows as
  // authored, less the 0.04 specular floor: (0.5, 0.3, 0.2) -> (0.46, 0.26, 0.16).
  {
    auto dim = uniformHdr(*device, glm::vec3(0.5f, 0.3f, 0.2f));
    const auto image = tonemapper.run(dim, 1.0f, render::ToneMapOperator::PbrNeutral);
    const double expected[3] = {0.46, 0.26, 0.16};
    for (int channel = 0; channel < 3; ++channel)
      CHECK(std::abs(int(image.rgba[size_t(channel)]) - byte(srgb(expected[channel]))) <= 1);
  }
  // AgX on the GPU keeps a grey grey (every matrix's rows sum to 1): middle
  // grey comes out with three equal channels, where a transposed matrix
  // would tint it.
  {
    auto grey = uniformHdr(*device, glm::vec3(0.18f));
    const auto image = tonemapper.run(grey, 1.0f, render::ToneMapOperator::AgX);
    CHECK(std::abs(int(image.rgba[0]) - int(image.rgba[1])) <= 1);
    CHECK(std::abs(int(image.rgba[1]) - int(image.rgba[2])) <= 1);
    CHECK(std::abs(int(image.rgba[1]) - byte(srgb(agx(glm::dvec3(0.18)).g))) <= 1);
  }
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
