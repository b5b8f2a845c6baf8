// The path tracer on the Cornell box (tests/render mirrors engine/render).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstring>
#include <glm/glm.hpp>

#include "penumbra/scene/scene_loader.h"
#include "render_test_utils.h"

using namespace penumbra;

namespace {
constexpr uint32_t kSize = 64;

glm::vec2 project(const scene::Camera& c, glm::vec3 p, uint32_t w, uint32_t h) {
  return glm::vec2(test::projectToFilm(c, p, w, h));
}
}  // namespace

TEST_CASE("path tracer: Cornell box is finite, deterministic and converges", "[render][gpu]") {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box");
  render::PathTracerSettings settings;
  settings.seed = 7;

  const auto a = test::renderScene(*device, scene, kSize, kSize, 16, settings);
  const auto b = test::renderScene(*device, scene, kSize, kSize, 16, settings);
  // The reference from a seed of its own: with seed 7 its first 16 samples
  // would be `a` itself, and the means below would agree by construction.
  render::PathTracerSettings referenceSettings = settings;
  referenceSettings.seed = 1007;
  const auto reference = test::renderScene(*device, scene, kSize, kSize, 256, referenceSettings);

  // No NaN/Inf, no negative radiance.
  REQUIRE(image::countNonFinite(a) == 0);
  REQUIRE(image::countNonFinite(reference) == 0);
  for (float v : reference.rgba) REQUIRE(v >= 0.0f);

  // Bit-identical for the same seed on one device.
  REQUIRE(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0);
  // A different seed gives a different image.
  settings.seed = 8;
  const auto other = test::renderScene(*device, scene, kSize, kSize, 16, settings);
  REQUIRE(std::memcmp(a.rgba.data(), other.rgba.data(), a.rgba.size() * sizeof(float)) != 0);

  // 16 spp and an independent 256 spp agree on the image mean within 2 %
  // per channel: the 16-spp mean of 65536 samples carries about 0.6 % of
  // noise (3 standard errors), so a bias of a few percent (a light counted
  // twice is 100 %) fails.
  const auto m16 = image::meanRgb(a), m256 = image::meanRgb(reference);
  INFO("mean 16 spp " << m16.r << " " << m16.g << " " << m16.b << "; 256 spp " << m256.r << " "
                      << m256.g << " " << m256.b);
  REQUIRE(std::abs(m16.r - m256.r) <= 0.02 * m256.r);
  REQUIRE(std::abs(m16.g - m256.g) <= 0.02 * m256.g);
  REQUIRE(std::abs(m16.b - m256.b) <= 0.02 * m256.b);

  // Walls: the red wall (x ~ 556 mm) is on the left of the image, the green one
  // (x = 0) on the right; sample a band at mid-height just inside each wall.
  auto band = [&](glm::vec3 p) {
    glm::vec2 px = project(scene.camera, p, kSize, kSize);
    uint32_t x = uint32_t(px.x), y = uint32_t(px.y);
    return image::meanRgb(reference, x - 1, y - 2, x + 2, y + 3);
  };
  const auto red = band({0.550f, 0.40f, 0.45f});
  const auto green = band({0.003f, 0.40f, 0.45f});
  const auto back = band({0.150f, 0.40f, 0.559f});
  INFO("red wall " << red.r << " " << red.g << " " << red.b);
  INFO("green wall " << green.r << " " << green.g << " " << green.b);
  INFO("back wall " << back.r << " " << back.g << " " << back.b);
  REQUIRE(red.r > 3.0 * red.g);
  REQUIRE(red.r > 3.0 * red.b);
  REQUIRE(green.g > 1.5 * green.r);
  REQUIRE(green.g > 1.5 * green.b);
  // The white back wall takes the colour of the light times its albedo:
  // r/g ~ (17 * 0.725) / (12 * 0.71) = 1.45, r/b ~ (17 * 0.725) / (4 * 0.68) = 4.5,
  // shifted a little by light from the coloured walls.
  REQUIRE(back.r / back.g > 1.2);
  REQUIRE(back.r / back.g < 1.7);
  REQUIRE(back.r / back.b > 3.5);
  REQUIRE(back.r / back.b < 5.5);

  // Pixels wholly on the light read its radiance (17, 12, 4): the camera ray
  // hits the emitter and the light's surface reflects nothing.
  glm::vec2 centre = project(scene.camera, {0.278f, 0.5487f, 0.2795f}, kSize, kSize);
  for (int dx = -2; dx <= 2; ++dx) {
    const float* p = reference.pixel(uint32_t(centre.x) + dx, uint32_t(centre.y));
    INFO("light pixel " << dx << ": " << p[0] << " " << p[1] << " " << p[2]);
    REQUIRE(std::abs(p[0] - 17.0f) < 1e-3f);
    REQUIRE(std::abs(p[1] - 12.0f) < 1e-3f);
    REQUIRE(std::abs(p[2] - 4.0f) < 1e-3f);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("path tracer: the untimed first dispatch changes no pixel and no count",
          "[render][gpu]") {
  // A pipeline's first frame traces one pixel untimed before the frame (so
  // that lavapipe's shader compilation is not timed as tracing). The frame
  // must rewrite that pixel: the first frame of a fresh tracer equals the
  // same frame rendered again, bit for bit, guides and ray count included.
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box");
  render::PathTracer tracer(*device, scene, 8, 8);
  render::PathTracerSettings settings;
  settings.writeGuides = true;
  const auto first = tracer.renderFrame(settings, 2);
  const auto image = tracer.readback();
  const auto albedo = tracer.readback(tracer.guides().albedo);
  tracer.resetAccumulation();
  const auto again = tracer.renderFrame(settings, 2);
  CHECK(first.rays == again.rays);
  CHECK(image.rgba == tracer.readback().rgba);
  CHECK(albedo.rgba == tracer.readback(tracer.guides().albedo).rgba);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("path tracer: accumulation equals one long frame sequence", "[render][gpu]") {
  // 4 frames of 4 spp and 1 frame of 16 spp sum the same samples (same sample
  // indices, same RNG streams); only the stratification pattern differs, so
  // the images agree statistically, and each frame's stats are counted.
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box");
  render::PathTracer tracer(*device, scene, 32, 32);
  render::PathTracerSettings settings;
  uint64_t rays = 0;
  for (int i = 0; i < 4; ++i) {
    auto stats = tracer.renderFrame(settings, 4);
    REQUIRE(stats.samples == 4u);
    // At least one camera ray per sample per pixel.
    REQUIRE(stats.rays >= 32u * 32u * 4u);
    REQUIRE(stats.gpuSeconds > 0.0);
    rays += stats.rays;
  }
  REQUIRE(tracer.accumulatedSamples() == 16u);
  auto accumulated = tracer.readback();
  tracer.resetAccumulation();
  tracer.renderFrame(settings, 16);
  auto single = tracer.readback();
  const auto m1 = image::meanRgb(accumulated), m2 = image::meanRgb(single);
  REQUIRE(std::abs(m1.r - m2.r) <= 0.05 * m2.r);
  REQUIRE(std::abs(m1.g - m2.g) <= 0.05 * m2.g);
  REQUIRE_THROWS(tracer.renderFrame(settings, 17));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
