// glTF's KHR_lights_punctual through both the importer and the renderer:
// each light's irradiance on a grey floor against the analytic value
// (tests/data/gltf/make_gltf.py, punctual_lights(), builds the files).
#include <algorithm>
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <functional>

#include "penumbra/scene/gltf_loader.h"
#include "penumbra/util/error.h"
#include "render_test_utils.h"
#include "test_data.h"

using namespace penumbra;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAlbedo = 0.5;  // the floor's, Lambertian (specularFactor 0)
constexpr uint32_t kSize = 32;

std::string gltf(const std::string& name) {
  return test::dataPath("gltf/" + name);
}

// Irradiance a light gives at a floor point (x, 0, z), per unit colour.
using Irradiance = std::function<double(double x, double z)>;

// Irradiance of an isotropic point light of intensity `intensity` 2 m above
// the origin at (x, 0, z): I cos(theta) / d^2, cos(theta) = 2 / d.
double pointIrradiance(double intensity, double x, double z) {
  const double d2 = x * x + 4.0 + z * z;
  return intensity * (2.0 / std::sqrt(d2)) / d2;
}

// The floor's radiance in each pixel, albedo / pi x E, averaged over a 4 x 4
// grid of the pixel's footprint (the renderer jitters over the pixel).
std::vector<double> expectedFloor(const scene::Scene& scene, const Irradiance& irradiance) {
  std::vector<double> expected(kSize * kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      double sum = 0;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const glm::vec2 film(float(x) + (i + 0.5f) / 4.0f, float(y) + (j + 0.5f) / 4.0f);
          const glm::vec3 d = test::cameraRayDirection(scene.camera, kSize, kSize, film);
          const double t = scene.camera.position.y / -double(d.y);
          const glm::dvec3 hit = scene.camera.position + t * glm::dvec3(d);
          sum += kAlbedo / kPi * irradiance(hit.x, hit.z);
        }
      expected[y * kSize + x] = sum / 16.0;
    }
  return expected;
}

// Renders the file and compares each pixel with expectedFloor. A per-pixel
// tolerance of 2 % of the value plus 0.5 % of the peak lets through no
// wrong falloff (the spot's smoothstep instead of t^2 is up to 3x off
// between the cones), no missing cosine, and no 1/d instead of 1/d^2.
void checkFloor(const std::string& file, const Irradiance& irradiance, glm::vec3 colour) {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadGltf(gltf(file));
  REQUIRE(scene.pointLights.size() == 1u);
  render::PathTracerSettings settings;
  settings.seed = 5;
  const auto img = test::renderScene(*device, scene, kSize, kSize, 64, settings);
  REQUIRE(image::countNonFinite(img) == 0);
  const std::vector<double> expected = expectedFloor(scene, irradiance);
  const double peak = *std::max_element(expected.begin(), expected.end());
  int bad = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) {
        const double want = expected[y * kSize + x] * colour[c];
        const double got = img.pixel(x, y)[c];
        if (std::abs(got - want) > 0.02 * want + 0.005 * peak * colour[c]) {
          if (bad++ < 5)
            UNSCOPED_INFO("pixel " << x << "," << y << " channel " << c << ": " << got
                                   << ", expected " << want);
        }
      }
  INFO(file << ": peak radiance " << peak << ", centre " << img.pixel(kSize / 2, kSize / 2)[0]);
  CHECK(bad == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

}  // namespace

TEST_CASE("glTF lights: KHR_lights_punctual lights become the scene's delta lights", "[gltf]") {
  const auto point = scene::loadGltf(gltf("lights_point.gltf"));
  REQUIRE(point.pointLights.size() == 1u);
  const scene::PointLight& p = point.pointLights[0];
  CHECK(p.type == scene::LightType::Point);
  CHECK(p.position.y == Catch::Approx(2.0));
  CHECK(p.intensity.r == Catch::Approx(8.0f));  // colour x intensity
  CHECK(p.intensity.g == Catch::Approx(4.0f));
  CHECK(p.intensity.b == Catch::Approx(2.0f));
  CHECK(p.range == 0.0f);
  CHECK(scene::loadGltf(gltf("lights_point_range.gltf")).pointLights[0].range == 3.0f);

  const auto spot = scene::loadGltf(gltf("lights_spot.gltf")).pointLights.at(0);
  CHECK(spot.type == scene::LightType::Spot);
  CHECK(spot.innerConeDegrees == Catch::Approx(20.0f));
  CHECK(spot.outerConeDegrees == Catch::Approx(40.0f));
  CHECK(spot.direction.y == Catch::Approx(-1.0f));  // the node's -z, turned down

  const auto sun = scene::loadGltf(gltf("lights_directional.gltf")).pointLights.at(0);
  CHECK(sun.type == scene::LightType::Directional);
  CHECK(sun.direction.y == Catch::Approx(-std::sqrt(0.5f)));
  CHECK(sun.direction.z == Catch::Approx(std::sqrt(0.5f)));

  for (const char* bad : {"invalid_light_cone.gltf", "invalid_light_index.gltf"}) {
    INFO(bad);
    try {
      scene::loadGltf(gltf(bad));
      FAIL("loaded");
    } catch (const Error& e) {
      const std::string message = e.what();
      UNSCOPED_INFO(message);
      CHECK(message.find(bad) != std::string::npos);
      CHECK(message.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("glTF lights: a point light's irradiance is I cos(theta) / d^2", "[render][gpu][gltf]") {
  checkFloor("lights_point.gltf", [](double x, double z) { return pointIrradiance(8.0, x, z); },
             {1.0f, 0.5f, 0.25f});
}

TEST_CASE("glTF lights: range fades a point light as (1 - (d/range)^4)^2", "[render][gpu][gltf]") {
  checkFloor("lights_point_range.gltf",
             [](double x, double z) {
               const double r = std::sqrt(x * x + 4.0 + z * z) / 3.0;
               const double window = std::max(0.0, 1.0 - r * r * r * r);
               return pointIrradiance(8.0, x, z) * window * window;
             },
             {1.0f, 1.0f, 1.0f});
}

TEST_CASE("glTF lights: a spot is full within its inner cone, t^2 between, dark outside",
          "[render][gpu][gltf]") {
  const double cosInner = std::cos(20.0 * kPi / 180.0), cosOuter = std::cos(40.0 * kPi / 180.0);
  checkFloor("lights_spot.gltf",
             [&](double x, double z) {
               const double cosAngle = 2.0 / std::sqrt(x * x + 4.0 + z * z);
               const double t = std::clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
               return pointIrradiance(8.0, x, z) * t * t;
             },
             {1.0f, 1.0f, 1.0f});
}

TEST_CASE("glTF lights: a directional light's irradiance is lux x cos(theta)",
          "[render][gpu][gltf]") {
  const auto sun = [](double, double) { return 3.0 * std::sqrt(0.5); };
  checkFloor("lights_directional.gltf", sun, {1.0f, 1.0f, 1.0f});
}

TEST_CASE("delta lights: one per vertex, chosen uniformly, adds up to all of them",
          "[render][gpu][gltf]") {
  // A point light, a spot and a sun over the floor at once. Each vertex
  // traces one shadow ray, towards one of the three chosen in proportion to
  // the irradiance it could give there, its contribution divided by that
  // probability; the mean must be the sum of the three analytic
  // irradiances. Compared in 4 x 4 pixel blocks at 1024 spp: 3 % per block
  // and 1 % over the image let through no missing division (each light's
  // share is a third or more of a block somewhere), no light never chosen
  // and no choice out of proportion to the probability it is divided by.
  auto device = test::makeTestDevice();
  auto scene = scene::loadGltf(gltf("lights_point.gltf"));
  REQUIRE(scene.pointLights.size() == 1u);
  scene.pointLights[0].intensity = glm::vec3(8.0f);  // white, as the other two
  scene.pointLights.push_back(scene::loadGltf(gltf("lights_spot.gltf")).pointLights.at(0));
  scene.pointLights.push_back(scene::loadGltf(gltf("lights_directional.gltf")).pointLights.at(0));
  const double cosInner = std::cos(20.0 * kPi / 180.0), cosOuter = std::cos(40.0 * kPi / 180.0);
  const auto all = [&](double x, double z) {
    const double cosAngle = 2.0 / std::sqrt(x * x + 4.0 + z * z);
    const double t = std::clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return pointIrradiance(8.0, x, z) * (1.0 + t * t) + 3.0 * std::sqrt(0.5);
  };
  render::PathTracerSettings settings;
  settings.seed = 17;
  const auto img = test::renderScene(*device, scene, kSize, kSize, 1024, settings);
  REQUIRE(image::countNonFinite(img) == 0);
  const std::vector<double> expected = expectedFloor(scene, all);
  double gotSum = 0, wantSum = 0;
  int bad = 0;
  for (uint32_t by = 0; by < kSize; by += 4)
    for (uint32_t bx = 0; bx < kSize; bx += 4) {
      double got = 0, want = 0;
      for (uint32_t y = by; y < by + 4; ++y)
        for (uint32_t x = bx; x < bx + 4; ++x) {
          got += img.pixel(x, y)[1];
          want += expected[y * kSize + x];
        }
      gotSum += got;
      wantSum += want;
      if (std::abs(got - want) > 0.03 * want && bad++ < 5)
        UNSCOPED_INFO("block " << bx << "," << by << ": " << got / 16 << ", expected "
                               << want / 16);
    }
  INFO("image mean " << gotSum / (kSize * kSize) << ", expected " << wantSum / (kSize * kSize));
  CHECK(bad == 0);
  CHECK(std::abs(gotSum - wantSum) <= 0.01 * wantSum);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
