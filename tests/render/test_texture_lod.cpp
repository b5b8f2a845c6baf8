// Texture level of detail through the renderer: a minified texture is read
// at the mip level of the ray cone's footprint (shaders/shared/textures.hlsli),
// so it neither aliases nor loses its mean, and a magnified one keeps its
// detail. The levels a footprint should read are computed here from the
// camera's geometry, not from the shaders' formula.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "render_test_utils.h"

using namespace penumbra;

namespace {

constexpr uint32_t kSize = 32;
constexpr uint32_t kTexels = 256;
constexpr uint32_t kStripe = 4;  // texels: white and black stripes, 8 texels a period
constexpr float kRepeat = 4.0f;  // KHR_texture_transform scale: 1024 texels across the quad
constexpr float kFovDegrees = 10.0f;

// Vertical stripes, kStripe texels wide, black and white (sRGB): their mean
// is 0.5 in linear light. Level log2(kStripe) has one texel a stripe; the
// levels above it are one uniform grey.
scene::Texture stripes() {
  scene::Texture t;
  t.name = "stripes";
  t.width = kTexels;
  t.height = kTexels;
  t.srgb = true;
  for (uint32_t y = 0; y < kTexels; ++y)
    for (uint32_t x = 0; x < kTexels; ++x) {
      const uint8_t v = (x / kStripe) % 2 == 0 ? 255 : 0;
      t.rgba8.insert(t.rgba8.end(), {v, v, v, 255});
    }
  return t;
}

// An unlit 2 x 2 quad showing the stripes, kRepeat times across, turned
// `tiltDegrees` about the vertical axis, seen from `distance` along +z: what
// every pixel shows is the texture's filtered value, with no light or noise.
scene::Scene stripedQuad(float distance, float tiltDegrees, scene::MipFilter mipFilter) {
  scene::Scene s;
  s.name = "striped quad";
  scene::Material m = scene::Material::lambert("unlit stripes", glm::vec3(1.0f));
  m.model = scene::MaterialModel::Unlit;
  m.baseColorTexture = 0;
  s.materials = {m};
  s.textures = {stripes()};
  scene::TextureRef ref;
  ref.texture = 0;
  ref.sampler.mipFilter = mipFilter;
  ref.transform0 = {kRepeat, 0.0f};
  ref.transform1 = {0.0f, kRepeat};
  s.textureRefs = {ref};
  scene::Mesh quad;
  quad.name = "quad";
  quad.material = 0;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  s.meshes = {quad};
  s.instances = {{0, glm::rotate(glm::mat4(1.0f), glm::radians(tiltDegrees), glm::vec3(0, 1, 0))}};
  s.camera.position = {0, 0, distance};
  s.camera.forward = {0, 0, -1};
  s.camera.up = {0, 1, 0};
  s.camera.verticalFovDegrees = kFovDegrees;
  return s;
}

// The distance at which a head-on pixel's footprint at the view's centre
// spans 2^level texels: a pixel subtends 2 tan(fov / 2) / kSize radians, and
// the quad's 2 units hold kRepeat x kTexels texels.
float distanceForLevel(float level) {
  const double pixelAngle = 2.0 * std::tan(kFovDegrees / 2.0 * std::numbers::pi / 180.0) / kSize;
  const double texelsPerUnit = kRepeat * kTexels / 2.0;
  return float(std::exp2(double(level)) / (pixelAngle * texelsPerUnit));
}

struct Stats {
  double mean = 0, deviation = 0, worst = 0;  // worst: largest |v - 0.5|
};

// The red channel over the middle 16 x 16 pixels, where the quad fills the
// view in every case (grey, so red stands for all three: checked).
Stats middleStats(const image::Image& img) {
  Stats s;
  double sum = 0, square = 0;
  int n = 0;
  for (uint32_t y = 8; y < 24; ++y)
    for (uint32_t x = 8; x < 24; ++x) {
      const float* p = img.pixel(x, y);
      REQUIRE(std::abs(p[0] - p[1]) < 1e-6f);
      REQUIRE(std::abs(p[0] - p[2]) < 1e-6f);
      sum += p[0];
      square += double(p[0]) * p[0];
      s.worst = std::max(s.worst, std::abs(double(p[0]) - 0.5));
      ++n;
    }
  s.mean = sum / n;
  s.deviation = std::sqrt(std::max(0.0, square / n - s.mean * s.mean));
  return s;
}

}  // namespace

TEST_CASE("texture level of detail: a minified texture reads the level its ray cone covers",
          "[render][gpu][textures]") {
  // Stripes 4 texels wide: levels 0-2 hold them, level 3 and above are
  // uniform grey (sRGB 188: linear 0.503, the stripes' mean 0.5 to 8 bits).
  // A footprint of 2^3.25 texels must read levels 3 and 4 only: every pixel
  // within 0.01 of 0.5. Mipmaps averaged in sRGB would give 0.21; none
  // would give 0 and 1. One level too fine reads level 2 at a quarter's
  // weight: stripes of deviation about 0.07 where 0.005 is allowed.
  // 2^1.75 texels reads levels 1 and 2, still striped (deviation about
  // 0.3; one level too coarse would be about 0.07 against the 0.2 required).
  // The 60-degree tilt doubles the footprint over the cosine (one level):
  // a head-on 2^2.25 becomes 2^3.25 at the centre and 2^3.04-2^3.48 over the
  // middle pixels, uniform again. Both integrators read textures the same way.
  auto device = test::makeTestDevice();
  for (auto integrator : {render::Integrator::Path, render::Integrator::Whitted}) {
    render::PathTracerSettings settings;
    settings.integrator = integrator;
    settings.seed = 7;
    const bool path = integrator == render::Integrator::Path;
    INFO((path ? "path tracer" : "Whitted"));
    const auto render = [&](float distance, float tilt, scene::MipFilter mip) {
      const auto img =
          test::renderScene(*device, stripedQuad(distance, tilt, mip), kSize, kSize, 1, settings);
      REQUIRE(image::countNonFinite(img) == 0);
      return middleStats(img);
    };

    const Stats coarse = render(distanceForLevel(3.25f), 0.0f, scene::MipFilter::Linear);
    INFO("2^3.25 texels a pixel: mean " << coarse.mean << ", deviation " << coarse.deviation
                                        << ", worst " << coarse.worst);
    CHECK(coarse.worst < 0.01);
    CHECK(coarse.deviation < 0.005);

    const Stats fine = render(distanceForLevel(1.75f), 0.0f, scene::MipFilter::Linear);
    INFO("2^1.75 texels a pixel: mean " << fine.mean << ", deviation " << fine.deviation);
    CHECK(fine.deviation > 0.2);
    CHECK(std::abs(fine.mean - 0.5) < 0.1);

    const Stats tilted = render(distanceForLevel(2.25f), 60.0f, scene::MipFilter::Linear);
    INFO("tilted 60 degrees, 2^2.25 texels head-on: mean "
         << tilted.mean << ", deviation " << tilted.deviation << ", worst " << tilted.worst);
    CHECK(tilted.worst < 0.01);
    CHECK(tilted.deviation < 0.005);
    const Stats untilted = render(distanceForLevel(2.25f), 0.0f, scene::MipFilter::Linear);
    INFO("the same head-on: deviation " << untilted.deviation);
    CHECK(untilted.deviation > 0.1);

    // glTF's minFilter LINEAR (no mipmap mode) keeps level 0 at any
    // distance: the stripes alias, as the file asks.
    const Stats level0 = render(distanceForLevel(3.25f), 0.0f, scene::MipFilter::None);
    INFO("minFilter without mipmaps: deviation " << level0.deviation);
    CHECK(level0.deviation > 0.2);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
