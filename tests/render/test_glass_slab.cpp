// The path tracer's smooth glass against ray optics: a glass slab between
// the camera and an emitter, with nothing else in the scene (what the
// glass reflects goes into the black void). The glass furnace cannot see
// Fresnel's value or the refraction direction, since every split and every
// direction ends on the same Le; these scenes can.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/scene/mesh_builders.h"
#include "ray_geometry.h"
#include "render_test_utils.h"
#include "spectrum_reference.h"

using namespace penumbra;

namespace {
constexpr float kLe = 1.0f;
constexpr float kIor = 1.5f;
constexpr uint32_t kSize = 32;

scene::Material smoothGlass() {
  scene::Material m;
  m.name = "glass";
  m.baseColor = glm::vec3(1.0f);
  m.roughness = 0.0f;
  m.specTrans = 1.0f;
  m.ior = kIor;
  return m;
}

// A slab of the given thickness, 8 x 8 (wider than the view), centred at
// z = 3 and turned `tiltDegrees` about y; an emitter in the plane z = 8
// facing the camera, covering x in [emitterMinX, emitterMaxX] and all of y
// in view.
scene::Scene slabScene(float tiltDegrees, float thickness, float emitterMinX, float emitterMaxX) {
  scene::Scene s;
  s.name = "glass slab";
  s.camera.position = glm::vec3(0.0f);
  s.camera.forward = glm::vec3(0, 0, 1);
  s.camera.up = glm::vec3(0, 1, 0);
  s.camera.verticalFovDegrees = 20.0f;
  s.materials.push_back(smoothGlass());
  s.materials.push_back(scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(kLe)));
  const glm::mat4 tilt = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 3}),
                                     glm::radians(tiltDegrees), glm::vec3(0, 1, 0));
  const float h = 0.5f * thickness;
  s.meshes.push_back(scene::makeBox({-4, -4, -h}, {4, 4, h}, false, 0));
  s.instances.push_back({0, tilt});
  // Front (counter-clockwise) side towards the camera: cross(+y, +x) = -z.
  s.meshes.push_back(
      scene::makeQuad({emitterMinX, -10, 8}, {0, 20, 0}, {emitterMaxX - emitterMinX, 0, 0}, 1));
  s.instances.push_back({1, glm::mat4(1.0f)});
  scene::validate(s);
  return s;
}

render::PathTracerSettings slabSettings() {
  render::PathTracerSettings settings;
  settings.maxDepth = 16;  // internal reflections beyond that carry < R^14 ~ 1e-18
  // Inside the glass the throughput is 1 / eta^2, which roulette would turn
  // into needless noise.
  settings.russianRoulette = false;
  return settings;
}

auto kindOf(const scene::Scene& s) {
  return [&s](uint32_t m) {
    return s.materials[m].specTrans > 0.0f ? test::SurfaceKind::Glass : test::SurfaceKind::Opaque;
  };
}
auto iorOf(const scene::Scene& s) {
  return [&s](uint32_t m) { return s.materials[m].ior; };
}

// Fraction of light a smooth slab transmits at incidence cosine cosI: the
// first surface passes 1 - R1, the second 1 - R2, and light reflected back
// and forth inside (R2 at each inner face, both faces see the same internal
// angle) adds the geometric series (1 - R1)(1 - R2) sum (R2^2)^k.
double slabTransmittance(float cosI) {
  const float r1 = test::fresnelUnpolarised(cosI, 1.0f, kIor);
  const float sinT = std::sqrt(1.0f - cosI * cosI) / kIor;
  const float r2 = test::fresnelUnpolarised(std::sqrt(1.0f - sinT * sinT), kIor, 1.0f);
  return (1.0 - r1) * (1.0 - r2) / (1.0 - double(r2) * r2);
}
}  // namespace

TEST_CASE("glass slab: transmits (1 - R1)(1 - R2) / (1 - R2^2) of an emitter behind it",
          "[render][gpu][glass]") {
  // Each sample either transmits (value Le) or is reflected into the void (0)
  // somewhere on the way, so a pixel is Le times a binomial fraction and the
  // image mean over 1024 pixels x 64 spp has a standard error of
  // sqrt(T (1 - T) / 65536) = 0.0010 Le at normal incidence (T = 0.923),
  // 0.0015 Le at 50-70 degrees (T ~ 0.82). Measured |mean - expected|:
  // 2.4e-5 at normal incidence, 9.7e-5 at 60 degrees. Held to 0.006 (4-6
  // standard errors); dropping Fresnel makes T = 1 (+8% and +22% here), and
  // Schlick's approximation in place of the exact equations moves the
  // 60-degree case by ~4%.
  auto device = test::makeTestDevice();
  constexpr uint32_t kSpp = 64;
  for (float tilt : {0.0f, 60.0f}) {
    INFO("slab normal at " << tilt << " degrees to the view axis");
    const auto s = slabScene(tilt, 0.5f, -3.0f, 3.0f);
    const auto tris = test::worldTriangles(s);
    const glm::vec3 slabNormal = glm::vec3(s.instances[0].transform * glm::vec4(0, 0, 1, 0));
    const auto img = test::renderScene(*device, s, kSize, kSize, kSpp, slabSettings());
    REQUIRE(image::countNonFinite(img) == 0);
    double expectedSum = 0, renderedSum = 0;
    uint32_t worstPixels = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const auto d = test::cameraRayDirection(s.camera, kSize, kSize, {x + 0.5f, y + 0.5f});
        // Every pixel looks through both big faces onto the emitter, and
        // what the front face reflects misses it (else it would add to T).
        const auto p = test::traceMainPath(tris, s.camera.position, d, kindOf(s), iorOf(s));
        REQUIRE(p.material == 1u);
        REQUIRE(p.refractions == 2u);
        const auto front = test::intersect(tris, s.camera.position, d);
        const auto mirrored = test::traceMainPath(
            tris, front->position, test::reflectAbout(d, front->normal), kindOf(s), iorOf(s));
        REQUIRE(mirrored.material == test::MainPath::kNothing);
        const double t = slabTransmittance(std::abs(glm::dot(d, slabNormal)));
        expectedSum += t;
        renderedSum += img.pixel(x, y)[0];
        // Per pixel: within 5 binomial standard errors of 64 samples.
        if (std::abs(img.pixel(x, y)[0] / kLe - t) > 5.0 * std::sqrt(t * (1 - t) / kSpp))
          ++worstPixels;
      }
    const double expected = expectedSum / (kSize * kSize);
    const double rendered = renderedSum / (kSize * kSize) / kLe;
    INFO("mean transmittance rendered " << rendered << ", expected " << expected);
    REQUIRE(std::abs(rendered - expected) <= 0.006);
    REQUIRE(worstPixels == 0u);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("glass slab: a tilted slab shifts an emitter's edge by Snell's law",
          "[render][gpu][glass]") {
  // A 2 thick slab turned 60 degrees displaces what is seen through it by
  // t sin(i - r) / cos r: 1.03 at i = 60 degrees (r = 35.3), 0.75-1.33
  // across the view's 50-70 degrees, i.e. 9-15 pixels at the emitter, so
  // its edge (x = 0.5) appears shifted and a band of pixels whose straight
  // line misses the emitter must see it. A pixel whose rays all follow one main path (refract in,
  // refract out) that ends on the emitter reads at least w Le (w = (1 - R1)(1 - R2), the
  // probability of that path); one whose main path misses reads at most (1 - w) Le, all of the
  // other branches. Monte Carlo noise of 256 binomial samples is at most 0.5 / 16 = 0.031 Le; the
  // bounds allow 5 times that.
  auto device = test::makeTestDevice();
  constexpr uint32_t kSpp = 256;
  const double noise = 5.0 * 0.5 / std::sqrt(double(kSpp));
  const auto s = slabScene(60.0f, 2.0f, 0.5f, 10.0f);
  const auto tris = test::worldTriangles(s);
  const auto img = test::renderScene(*device, s, kSize, kSize, kSpp, slabSettings());
  REQUIRE(image::countNonFinite(img) == 0);
  uint32_t lit = 0, dark = 0, shifted = 0, failures = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      bool consistent = true;
      float w = 1.0f;
      test::MainPath first;
      const auto footprint = test::pixelFootprint(x, y);
      for (size_t i = 0; i < footprint.size(); ++i) {
        const auto d = test::cameraRayDirection(s.camera, kSize, kSize, footprint[i]);
        const auto p = test::traceMainPath(tris, s.camera.position, d, kindOf(s), iorOf(s));
        if (i == 0) first = p;
        consistent = consistent && p.route == first.route && p.material == first.material;
        w = std::min(w, p.weight);
      }
      if (!consistent || first.refractions != 2) continue;
      const auto d = test::cameraRayDirection(s.camera, kSize, kSize, {x + 0.5f, y + 0.5f});
      const bool straightOnEmitter = d.x > 0.0f;  // the unbent ray's side of x = 0
      const bool onEmitter = first.material == 1u;
      const float v = img.pixel(x, y)[0] / kLe;
      if (onEmitter) {
        ++lit;
        if (v < w - noise) ++failures;
      } else {
        ++dark;
        if (v > 1.0 - w + noise) ++failures;
      }
      if (onEmitter != straightOnEmitter) ++shifted;
    }
  INFO(lit << " pixels on the emitter, " << dark << " off, " << shifted
           << " of them on the other side of the edge than their straight line");
  REQUIRE(failures == 0u);
  // Counts when written: 736 lit, 256 dark, 224 shifted (7 columns).
  REQUIRE(lit >= 400u);
  REQUIRE(dark >= 150u);
  REQUIRE(shifted >= 150u);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// KHR_materials_volume's absorption: light crossing the slab's inside over a
// length L keeps attenuationColor^(L / attenuationDistance) of itself per
// channel (Beer-Lambert), on every pass, so the slab transmits
//   (1 - R1)(1 - R2) tau / (1 - R2^2 tau^2),   tau = colour^(L / a),
// with L = thickness / cos(theta_t). Colour (0.5, 0.8, 1), a = 0.25, 0.5
// thick: tau = 0.25, 0.64 and 1 at normal incidence. Held, as the clear slab,
// to 0.006 of the mean: attenuating over the straight thickness instead of
// the refracted path moves the red channel by 37 % at 60 degrees, a clear
// medium by 300 %.
TEST_CASE("glass slab: an absorbing medium transmits colour^(L / distance) per pass",
          "[render][gpu][glass]") {
  auto device = test::makeTestDevice();
  constexpr uint32_t kSpp = 64;
  const glm::vec3 colour(0.5f, 0.8f, 1.0f);
  constexpr float kDistance = 0.25f, kThickness = 0.5f;
  for (float tilt : {0.0f, 60.0f}) {
    INFO("slab normal at " << tilt << " degrees to the view axis");
    auto s = slabScene(tilt, kThickness, -3.0f, 3.0f);
    s.materials[0].attenuationColor = colour;
    s.materials[0].attenuationDistance = kDistance;
    const glm::vec3 slabNormal = glm::vec3(s.instances[0].transform * glm::vec4(0, 0, 1, 0));
    const auto img = test::renderScene(*device, s, kSize, kSize, kSpp, slabSettings());
    REQUIRE(image::countNonFinite(img) == 0);
    for (int c = 0; c < 3; ++c) {
      double expectedSum = 0, renderedSum = 0;
      for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
          const auto d = test::cameraRayDirection(s.camera, kSize, kSize, {x + 0.5f, y + 0.5f});
          const float cosI = std::abs(glm::dot(d, slabNormal));
          const float r1 = test::fresnelUnpolarised(cosI, 1.0f, kIor);
          const float sinT = std::sqrt(1.0f - cosI * cosI) / kIor;
          const float cosT = std::sqrt(1.0f - sinT * sinT);
          const float r2 = test::fresnelUnpolarised(cosT, kIor, 1.0f);
          const double tau = std::pow(double(colour[c]), kThickness / cosT / kDistance);
          expectedSum += (1.0 - r1) * (1.0 - r2) * tau / (1.0 - double(r2) * r2 * tau * tau);
          renderedSum += img.pixel(x, y)[c];
        }
      const double expected = expectedSum / (kSize * kSize);
      const double rendered = renderedSum / (kSize * kSize) / kLe;
      INFO("channel " << c << ": mean transmittance rendered " << rendered << ", expected "
                      << expected);
      CHECK(std::abs(rendered - expected) <= 0.006);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {
// Radiance along a ray through smooth glass of index `ior`, every Fresnel
// branch followed (deterministically) until its weight is below 1e-6: Le
// from the emitter's front, nothing from the void.
double splitRadiance(const std::vector<test::WorldTriangle>& tris, glm::vec3 o, glm::vec3 d,
                     float ior, double weight = 1.0, int depth = 0) {
  if (weight < 1e-6 || depth > 24) return 0.0;
  const auto hit = test::intersect(tris, o, d);
  if (!hit) return 0.0;
  if (hit->material == 1u) return glm::dot(d, hit->normal) < 0.0f ? weight * kLe : 0.0;
  const bool entering = glm::dot(d, hit->normal) < 0.0f;
  const float n1 = entering ? 1.0f : ior, n2 = entering ? ior : 1.0f;
  const float r = test::fresnelUnpolarised(glm::dot(d, hit->normal), n1, n2);
  double sum = splitRadiance(tris, hit->position, test::reflectAbout(d, hit->normal), ior,
                             weight * r, depth + 1);
  if (const auto t = test::refractSnell(d, hit->normal, n1, n2))
    sum += splitRadiance(tris, hit->position, *t, ior, weight * (1.0 - r), depth + 1);
  return sum;
}
}  // namespace

TEST_CASE("glass slab: a dispersive slab splits an emitter's edge into Cauchy's colours",
          "[render][gpu][glass]") {
  // A slab 6 thick turned 60 degrees shifts what is seen through it by
  // t sin(i - r) / cos r, which grows with the index: with dispersion 3
  // (Abbe number 6.7, exaggerated so the fringe spans several pixels), ior
  // 1.5, blue at 420 nm (n 1.56) is shifted 0.19 further than red at 650 nm
  // (n 1.47), 2-3 columns of a 2-degree view at the emitter. Each column's
  // colour is the share of the spectrum whose shifted ray lands on the
  // emitter, weighted by those wavelengths' colours. Per column (32 rows x
  // 256 spp) the noise is at most 1.3 / sqrt(8192) = 0.014 per channel (a
  // wavelength's weight has a standard deviation of 1.2-1.3); columns are
  // held to 0.06. Without dispersion every column
  // is grey: the fringe's columns are off by 0.3 and more; a wrong-signed
  // law swaps red and blue.
  constexpr float kDispersion = 3.0f;
  constexpr uint32_t kSpp = 256;
  scene::Scene s;
  s.name = "dispersive slab";
  s.camera.position = glm::vec3(0.0f);
  s.camera.forward = glm::vec3(0, 0, 1);
  s.camera.up = glm::vec3(0, 1, 0);
  s.camera.verticalFovDegrees = 2.0f;
  auto glass = smoothGlass();
  glass.dispersion = kDispersion;
  s.materials.push_back(glass);
  s.materials.push_back(scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(kLe)));
  const glm::mat4 tilt = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 10}),
                                     glm::radians(60.0f), glm::vec3(0, 1, 0));
  s.meshes.push_back(scene::makeBox({-20, -20, -3}, {20, 20, 3}, false, 0));
  s.instances.push_back({0, tilt});
  // The emitter's edge where the view's centre ray lands at the d line's
  // index: the fringe falls in the middle of the image.
  const auto tris0 = test::worldTriangles(s);
  glm::vec3 exit = s.camera.position;
  glm::vec3 out = test::cameraRayDirection(s.camera, kSize, kSize, {kSize / 2.0f, kSize / 2.0f});
  for (auto [n1, n2] : {std::pair{1.0f, 1.5f}, std::pair{1.5f, 1.0f}}) {
    const auto hit = test::intersect(tris0, exit, out);
    REQUIRE(hit);
    const auto t = test::refractSnell(out, hit->normal, n1, n2);
    REQUIRE(t);
    exit = hit->position;
    out = *t;
  }
  const float edge = exit.x + (40.0f - exit.z) / out.z * out.x;
  s.meshes.push_back(scene::makeQuad({edge, -50, 40}, {0, 100, 0}, {100, 0, 0}, 1));
  s.instances.push_back({1, glm::mat4(1.0f)});
  scene::validate(s);
  const auto tris = test::worldTriangles(s);

  auto device = test::makeTestDevice();
  auto settings = slabSettings();
  settings.sampler = render::Sampler::Random;
  const auto img = test::renderScene(*device, s, kSize, kSize, kSpp, settings);
  REQUIRE(image::countNonFinite(img) == 0);

  const test::Spectrum spec = test::spectrum(100);
  double cyanest = 0, bluest = 0;
  uint32_t failures = 0;
  for (uint32_t x = 0; x < kSize; ++x) {
    glm::dvec3 expected(0.0), rendered(0.0);
    int points = 0;
    for (float fy : {0.5f, 16.0f, 31.5f})
      for (int sub = 0; sub < 8; ++sub, ++points) {
        const auto d =
            test::cameraRayDirection(s.camera, kSize, kSize, {float(x) + (sub + 0.5f) / 8.0f, fy});
        for (size_t i = 0; i < spec.lambda.size(); ++i) {
          const float n = float(test::cauchyIor(1.5, kDispersion, spec.lambda[i]));
          expected += spec.weight[i] * splitRadiance(tris, s.camera.position, d, n) /
                      double(spec.lambda.size());
        }
      }
    expected /= double(points);
    for (uint32_t y = 0; y < kSize; ++y)
      for (int c = 0; c < 3; ++c) rendered[c] += img.pixel(x, y)[c] / (kLe * kSize);
    INFO("column " << x << ": expected " << expected.x << " " << expected.y << " " << expected.z
                   << ", rendered " << rendered.x << " " << rendered.y << " " << rendered.z);
    for (int c = 0; c < 3; ++c)
      if (std::abs(rendered[c] - expected[c]) > 0.06) ++failures;
    CHECK(glm::all(glm::lessThanEqual(glm::abs(rendered - expected), glm::dvec3(0.06))));
    cyanest = std::max(cyanest, expected.y - expected.x);
    bluest = std::max(bluest, expected.z - expected.y);
  }
  // The view holds the fringe: red, bent least, leaves the emitter's image
  // first, so from lit to dark the columns go white, cyan (green and blue
  // left), blue, black. Written: 0.56 and 0.73.
  INFO("most cyan column: green - red " << cyanest << "; bluest: blue - green " << bluest);
  REQUIRE(cyanest > 0.3);
  REQUIRE(bluest > 0.3);
  REQUIRE(failures == 0u);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
