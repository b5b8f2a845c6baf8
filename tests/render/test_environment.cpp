// Environment lighting through the path tracer: the furnace under a
// uniform environment (analytic), MIS against each strategy alone on a map
// with a small bright spot, the hidden background, the soft sun's
// irradiance and penumbra (analytic), the default environment of a scene
// without light, and the errors of bad environment input.
#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "penumbra/batch/render_job.h"
#include "penumbra/image/image_io.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/mesh_builders.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"
#include "render_test_utils.h"
#include "test_data.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kSky = 0.7f;  // the uniform environment's radiance

// A Lambertian sphere of radius 1 at the origin, seen from 4 m away so
// that it fills the middle of the image and the corners see the sky.
scene::Scene sphereUnderSky(float albedo, const scene::Environment& environment) {
  scene::Scene s;
  s.name = "sphere under the sky";
  s.materials.push_back(scene::Material::lambert("sphere", glm::vec3(albedo)));
  s.meshes.push_back(scene::makeIcosphere(3, 1.0f, false, 0));
  s.instances.push_back({0, glm::dmat4(1.0)});
  s.camera.position = {0.0, 0.0, 4.0};
  s.camera.forward = {0.0f, 0.0f, -1.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  s.camera.verticalFovDegrees = 40.0f;
  s.environment = environment;
  return s;
}

// Whether pixel (x, y) of a size x size image sees only the sphere (every
// point of its footprint) or only the sky.
enum class Seen { Sphere, Sky, Both };
Seen seen(const scene::Scene& s, uint32_t x, uint32_t y, uint32_t size) {
  int sphere = 0, sky = 0;
  for (glm::vec2 film : test::pixelFootprint(x, y)) {
    const glm::dvec3 d = test::cameraRayDirection(s.camera, glm::dvec2(film), size, size);
    const glm::dvec3 o = s.camera.position;
    // |o + t d| = r has a root when (o.d)^2 - (|o|^2 - r^2) >= 0; the
    // icosphere's facets lie within 0.2 % inside the unit sphere, so
    // footprints that graze it (within 1 %) count as both.
    const double b = glm::dot(o, d), c = glm::dot(o, o);
    const double disc = b * b - c;
    if (disc > -1.0 + 0.02) ++sphere;
    if (disc < -1.0 - 0.02) ++sky;
  }
  if (sphere == 9) return Seen::Sphere;
  if (sky == 9) return Seen::Sky;
  return Seen::Both;
}

struct Means {
  double sphere = 0, sky = 0;
  double worstSphere = 0, worstSky = 0;  // largest relative deviation of a pixel
};

Means measure(const scene::Scene& s, const image::Image& img, double sphereValue, double skyValue) {
  Means m;
  int nSphere = 0, nSky = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const double v = img.pixel(x, y)[1];
      switch (seen(s, x, y, img.width)) {
        case Seen::Sphere:
          m.sphere += v;
          ++nSphere;
          m.worstSphere = std::max(m.worstSphere, std::abs(v - sphereValue) / sphereValue);
          break;
        case Seen::Sky:
          m.sky += v;
          ++nSky;
          m.worstSky = std::max(m.worstSky, skyValue > 0 ? std::abs(v - skyValue) / skyValue : v);
          break;
        case Seen::Both:
          break;
      }
    }
  REQUIRE(nSphere > 50);
  REQUIRE(nSky > 50);
  m.sphere /= nSphere;
  m.sky /= nSky;
  return m;
}

double relMse(const image::Image& img, const image::Image& reference) {
  double sum = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.rgba[i + c], d = img.rgba[i + c] - r;
      sum += d * d / (r * r + 1e-2);
    }
  return sum / (img.rgba.size() / 4 * 3);
}

}  // namespace

// A convex Lambertian of albedo rho under a uniform sky of radiance L
// reflects rho L from every point (every bounce ray escapes), so with rho = 1
// it vanishes into the sky. Cosine-weighted BSDF sampling is exact here
// (weight rho, radiance L); NEE and MIS sample the whole sky (about
// uniformly: a sample's relative deviation is about 1.3), so their sphere
// means are held to 1 %, 4 standard errors at 1024 spp over ~250 pixels.
// A missing cosine, a density off by the Jacobian, or light counted by both
// strategies is off by 30 % or more.
TEST_CASE("environment: a furnace sphere of albedo rho under a uniform sky is rho L",
          "[render][gpu][environment]") {
  auto device = test::makeTestDevice();
  const auto sky = scene::constantEnvironment(glm::vec3(kSky));
  using S = render::SamplingStrategy;
  for (float albedo : {1.0f, 0.5f}) {
    const auto s = sphereUnderSky(albedo, sky);
    for (auto strategy : {S::Bsdf, S::Nee, S::Mis}) {
      render::PathTracerSettings settings;
      settings.strategy = strategy;
      settings.russianRoulette = false;
      settings.seed = 3;
      const auto img =
          test::renderScene(*device, s, 32, 32, strategy == S::Bsdf ? 16 : 1024, settings);
      REQUIRE(image::countNonFinite(img) == 0);
      const Means m = measure(s, img, albedo * kSky, kSky);
      INFO("albedo " << albedo << ", strategy " << int(strategy) << ": sphere " << m.sphere
                     << " (worst pixel " << m.worstSphere << "), sky " << m.sky);
      CHECK(std::abs(m.sphere - albedo * kSky) <= 0.01 * albedo * kSky);
      CHECK(m.worstSky < 1e-6);  // the background is the sky's radiance itself
      if (strategy == S::Bsdf) CHECK(m.worstSphere < 1e-4);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment: a hidden background is black; the sky still lights the sphere",
          "[render][gpu][environment]") {
  auto device = test::makeTestDevice();
  auto sky = scene::constantEnvironment(glm::vec3(kSky));
  sky.visibleBackground = false;
  sky.intensity = 2.0f;
  const auto s = sphereUnderSky(0.5f, sky);
  render::PathTracerSettings settings;
  settings.strategy = render::SamplingStrategy::Bsdf;  // exact: no noise to allow for
  const auto img = test::renderScene(*device, s, 32, 32, 16, settings);
  const Means m = measure(s, img, 0.5 * 2.0 * kSky, 0.0);
  INFO("sphere " << m.sphere << ", sky " << m.sky);
  CHECK(m.worstSphere < 1e-4);
  CHECK(m.sky == 0.0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// A small bright spot over a dim sky lighting a diffuse sphere (where
// sampling the map wins) above a near-mirror floor (where sampling the BSDF
// wins): MIS must beat both strategies over the image at equal samples.
TEST_CASE("environment: MIS beats BSDF-only and NEE-only sampling on a bright spot",
          "[render][gpu][environment]") {
  auto device = test::makeTestDevice();
  scene::Environment env;
  env.width = 64;
  env.height = 32;
  env.source = "spot";
  env.radiance.assign(64 * 32, glm::vec3(0.05f));
  // 2 x 2 texels (0.2 % of the sphere's solid angle), 45 degrees up, in front.
  for (uint32_t y : {7u, 8u})
    for (uint32_t x : {30u, 31u}) env.radiance[y * 64 + x] = glm::vec3(400.0f);
  scene::Scene s = sphereUnderSky(0.8f, env);
  s.camera.position = {0.0, 1.0, 5.0};
  s.camera.forward = glm::normalize(glm::vec3(0.0f, -0.45f, -1.0f));
  scene::Material floor = scene::Material::lambert("floor", glm::vec3(0.9f));
  floor.model = scene::MaterialModel::Disney;
  floor.metallic = 1.0f;
  floor.roughness = 0.08f;
  s.materials.push_back(floor);
  s.meshes.push_back(
      scene::makeQuad({-6.0f, -1.0f, 6.0f}, {12.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -12.0f}, 1));
  s.instances.push_back({1, glm::dmat4(1.0)});
  constexpr uint32_t kSize = 32;
  render::PathTracerSettings reference;
  reference.seed = 1000;  // not a seed of the images compared with it
  reference.maxDepth = 4;
  const auto ref = test::renderScene(*device, s, kSize, kSize, 2048, reference);
  REQUIRE(image::countNonFinite(ref) == 0);
  double error[3];
  using S = render::SamplingStrategy;
  const S strategies[] = {S::Bsdf, S::Nee, S::Mis};
  for (int i = 0; i < 3; ++i) {
    render::PathTracerSettings settings;
    settings.strategy = strategies[i];
    settings.maxDepth = 4;
    settings.seed = 1;
    const auto img = test::renderScene(*device, s, kSize, kSize, 16, settings);
    REQUIRE(image::countNonFinite(img) == 0);
    error[i] = relMse(img, ref);
  }
  INFO("relMSE at 16 spp: BSDF " << error[0] << ", NEE " << error[1] << ", MIS " << error[2]);
  CHECK(error[2] < error[0]);
  CHECK(error[2] < error[1]);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {

// A grey floor (y = 0) under a black slab at height 1 that covers x < 0,
// lit by a sun straight overhead; the camera sits between them, looking
// down at the slab's shadow edge.
scene::Scene sunOverEdge(float angularRadiusDegrees) {
  scene::Scene s;
  s.name = "sun over an edge";
  s.materials.push_back(scene::Material::lambert("floor", glm::vec3(0.5f)));
  s.materials.push_back(scene::Material::lambert("slab", glm::vec3(0.0f)));
  s.meshes.push_back(
      scene::makeQuad({-10.0f, 0.0f, 10.0f}, {20.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -20.0f}, 0));
  s.meshes.push_back(
      scene::makeQuad({-10.0f, 1.0f, 10.0f}, {10.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -20.0f}, 1));
  s.instances = {{0, glm::dmat4(1.0)}, {1, glm::dmat4(1.0)}};
  scene::PointLight sun;
  sun.type = scene::LightType::Directional;
  sun.direction = {0.0f, -1.0f, 0.0f};
  sun.intensity = glm::vec3(3.0f);
  sun.angularRadiusDegrees = angularRadiusDegrees;
  s.pointLights.push_back(sun);
  s.camera.position = {0.0, 0.5, 0.0};
  s.camera.forward = {0.0f, -1.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.verticalFovDegrees = 60.0f;
  return s;
}

}  // namespace

// The floor's radiance is rho / pi E(x). From x the slab's edge (1 m up)
// hides the part of the sun's disk beyond it: in units s = x / tan(a) of the
// disk's radius, the visible fraction is 1 - (acos s - s sqrt(1 - s^2)) / pi
// (a disk cut by a chord; the small-angle view of a 10 degree sun is within
// 1.5 %). Fully lit, a soft sun gives E cos(theta) as a delta sun does. A
// soft sun sampled as a delta light, or with the wrong cone or weight, is
// off by far more than the 4 % allowed.
TEST_CASE("environment: a soft sun's penumbra is the disk's visible fraction",
          "[render][gpu][environment]") {
  auto device = test::makeTestDevice();
  constexpr uint32_t kSize = 48;
  const double tanRadius = std::tan(10.0 * kPi / 180.0);
  render::PathTracerSettings settings;
  settings.maxDepth = 1;
  settings.seed = 4;
  for (float radius : {0.0f, 10.0f}) {
    const auto s = sunOverEdge(radius);
    const auto img = test::renderScene(*device, s, kSize, kSize, 256, settings);
    REQUIRE(image::countNonFinite(img) == 0);
    int bad = 0, checked = 0;
    for (uint32_t x = 0; x < kSize; ++x) {
      // The pixel column's floor x at its centre (the camera looks straight down).
      const glm::dvec3 d =
          test::cameraRayDirection(s.camera, glm::dvec2(x + 0.5, kSize / 2.0), kSize, kSize);
      const double floorX = s.camera.position.x + d.x * (0.5 / -d.y);
      double fraction = floorX > 0 ? 1.0 : 0.0;
      if (radius > 0) {
        const double u = std::clamp(floorX / tanRadius, -1.0, 1.0);
        fraction = 1.0 - (std::acos(u) - u * std::sqrt(1.0 - u * u)) / kPi;
      } else if (std::abs(floorX) < 0.02) {
        continue;  // the hard edge crosses this pixel
      }
      const double want = 0.5 / kPi * 3.0 * fraction;
      double got = 0;
      for (uint32_t y = 8; y < kSize - 8; ++y) got += img.pixel(x, y)[0];
      got /= kSize - 16;
      ++checked;
      if (std::abs(got - want) > 0.04 * 0.5 / kPi * 3.0) {
        if (bad++ < 5)
          UNSCOPED_INFO("radius " << radius << ", x " << floorX << ": " << got << ", expected "
                                  << want);
      }
    }
    CHECK(checked > 40);
    CHECK(bad == 0);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment: a glTF file without lights is lit by the default environment",
          "[render][gpu][environment]") {
  auto device = test::makeTestDevice();
  scene::Scene s = scene::loadGltf(test::dataPath("gltf/attributes.gltf"));
  REQUIRE_FALSE(s.hasOwnLighting());
  REQUIRE_FALSE(s.environment.present());
  scene::Scene unlit = s;
  render::applyEnvironmentChoice(unlit, {.map = "none"});
  CHECK_FALSE(unlit.environment.present());
  const auto black = test::renderScene(*device, unlit, 16, 16, 4);
  CHECK(image::meanRgb(black).g == 0.0);
  render::applyEnvironmentChoice(s, {});
  REQUIRE(s.environment.present());
  CHECK(s.environment.source == "default studio");
  const auto lit = test::renderScene(*device, s, 16, 16, 16);
  REQUIRE(image::countNonFinite(lit) == 0);
  CHECK(image::meanRgb(lit).g > 0.05);
  // A scene with light of its own keeps its lighting.
  scene::Scene cornell = scene::loadScene("cornell-box");
  REQUIRE(cornell.hasOwnLighting());
  render::applyEnvironmentChoice(cornell, {});
  CHECK_FALSE(cornell.environment.present());
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment: a glTF file's emissive materials do not count as its lighting",
          "[environment]") {
  // emissive_quad.gltf: an emissive quad and no punctual light, as a model
  // with a glowing label or screen is.
  scene::Scene s = scene::loadGltf(test::dataPath("gltf/emissive_quad.gltf"));
  REQUIRE(s.hasEmitters());
  CHECK_FALSE(s.hasOwnLighting());
  scene::Scene unlit = s;
  render::applyEnvironmentChoice(unlit, {.map = "none"});
  CHECK_FALSE(unlit.environment.present());
  render::applyEnvironmentChoice(s, {});
  REQUIRE(s.environment.present());
  CHECK(s.environment.source == "default studio");
  // The same material declared by a scene file is a light.
  for (auto& m : s.materials) m.emissionIsLighting = true;
  CHECK(s.hasOwnLighting());
  // A punctual light is lighting whatever the materials say.
  scene::Scene withLight = scene::loadGltf(test::dataPath("gltf/lights_point.gltf"));
  CHECK(withLight.hasOwnLighting());
}

TEST_CASE("environment: .exr and .hdr maps load; bad maps and settings are refused",
          "[environment]") {
  const auto dir = std::filesystem::temp_directory_path() / "penumbra_env_test";
  std::filesystem::create_directories(dir);
  // An EXR as the renderer writes them: 3 x 2, each texel's own values.
  image::Image exr(3, 2);
  for (uint32_t i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) exr.rgba[i * 4 + c] = 0.25f * float(i) + float(c);
  image::saveExr((dir / "map.exr").string(), exr);
  const auto fromExr = scene::loadEnvironmentMap((dir / "map.exr").string());
  REQUIRE(fromExr.width == 3);
  REQUIRE(fromExr.height == 2);
  CHECK(fromExr.radiance[4] == glm::vec3(1.0f, 2.0f, 3.0f));  // row 1, column 1
  // A Radiance file written by hand, flat (not run-length) scanlines: RGBE
  // (128, 64, 32, 129) is (1, 0.5, 0.25) x 2^(129 - 136) x 128.
  {
    std::ofstream hdr(dir / "map.hdr", std::ios::binary);
    hdr << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
    const unsigned char texels[] = {128, 64, 32, 129, 0, 0, 0, 0};
    hdr.write(reinterpret_cast<const char*>(texels), sizeof(texels));
  }
  const auto fromHdr = scene::loadEnvironmentMap((dir / "map.hdr").string());
  REQUIRE(fromHdr.width == 2);
  REQUIRE(fromHdr.height == 1);
  CHECK(fromHdr.radiance[0] == glm::vec3(1.0f, 0.5f, 0.25f));
  CHECK(fromHdr.radiance[1] == glm::vec3(0.0f));
  REQUIRE_THROWS_WITH(scene::loadEnvironmentMap((dir / "missing.exr").string()),
                      ContainsSubstring("missing.exr") && ContainsSubstring("no such file"));
  // A PNG is no HDR image, whatever its name says.
  const std::string png = test::dataPath("gltf/alpha_mask_quad.png");
  REQUIRE_THROWS_WITH(scene::loadEnvironmentMap(png), ContainsSubstring("not an HDR image"));
  const auto fakeHdr = dir / "fake.hdr";
  std::filesystem::copy_file(png, fakeHdr, std::filesystem::copy_options::overwrite_existing);
  REQUIRE_THROWS_WITH(scene::loadEnvironmentMap(fakeHdr.string()),
                      ContainsSubstring("fake.hdr") && ContainsSubstring("not a Radiance HDR"));
  const auto fakeExr = dir / "fake.exr";
  std::filesystem::copy_file(png, fakeExr, std::filesystem::copy_options::overwrite_existing);
  REQUIRE_THROWS_WITH(scene::loadEnvironmentMap(fakeExr.string()), ContainsSubstring("fake.exr"));
  auto env = scene::constantEnvironment(glm::vec3(1.0f));
  env.intensity = -1.0f;
  REQUIRE_THROWS_WITH(scene::validateEnvironment(env), ContainsSubstring("intensity -1"));
  env.intensity = 1.0f;
  // Larger than 16384x8192 (2^27 texels, a 2 GiB buffer): refused before
  // the texels are even looked at.
  scene::Environment huge;
  huge.width = 16384;
  huge.height = 8193;
  huge.source = "huge.exr";
  REQUIRE_THROWS_WITH(scene::validateEnvironment(huge),
                      ContainsSubstring("huge.exr") && ContainsSubstring("more than 16384x8192"));
  huge.width = 16385;
  huge.height = 1;
  REQUIRE_THROWS_WITH(scene::validateEnvironment(huge), ContainsSubstring("more than 16384x8192"));
  env.radiance[5].y = std::nanf("");
  REQUIRE_THROWS_WITH(scene::validateEnvironment(env), ContainsSubstring("texel (5, 0)"));
  // Settings with no environment to apply them to.
  scene::Scene cornell = scene::loadScene("cornell-box");
  render::EnvironmentChoice rotate;
  rotate.rotationDegrees = 30.0f;
  REQUIRE_THROWS_WITH(render::applyEnvironmentChoice(cornell, rotate),
                      ContainsSubstring("need an environment"));
  std::filesystem::remove_all(dir);
}
