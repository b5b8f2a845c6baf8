// The environment's lookup and importance sampling (shaders/shared/
// environment.hlsli, tables from render/environment_map.h), run on the test
// device through harness/environment_harness.comp. The expectations are
// worked out here from the map alone, in double, from the documented
// convention (top row +y, centre column -z, u towards +x; density
// proportional to luminance x sin(theta) per texel): the directions' chi-square
// against the texel probabilities, the density each sample reports, the
// density's integral over the sphere, the rotation, and which texel a
// direction reads.
#include <fmt/format.h>

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "compute_harness.h"
#include "penumbra/render/environment_map.h"
#include "test_device.h"

using namespace penumbra;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Result {
  glm::dvec3 direction;
  double pdf;
  glm::dvec3 radiance;
  double pdfAgain;
};

// A 32 x 16 map that is far from uniform: a sky gradient, one black band,
// a bright 2 x 1 spot, and one coloured texel near the bottom.
scene::Environment testMap() {
  scene::Environment env;
  env.width = 32;
  env.height = 16;
  env.source = "test map";
  env.radiance.resize(32 * 16);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      env.radiance[y * 32 + x] =
          glm::vec3(0.2f + 0.05f * float(x % 7) + 0.1f * float(15 - y) / 15.0f);
  for (uint32_t x = 0; x < 32; ++x) env.radiance[10 * 32 + x] = glm::vec3(0.0f);  // black band
  env.radiance[4 * 32 + 20] = env.radiance[4 * 32 + 21] = glm::vec3(40.0f, 30.0f, 20.0f);
  env.radiance[14 * 32 + 3] = glm::vec3(5.0f, 0.0f, 0.0f);
  return env;
}

// The texel probabilities the documented density gives.
std::vector<double> expectedTexelProbabilities(const scene::Environment& env) {
  std::vector<double> p(env.radiance.size());
  double total = 0;
  for (uint32_t y = 0; y < env.height; ++y)
    for (uint32_t x = 0; x < env.width; ++x) {
      const glm::vec3 r = env.radiance[y * env.width + x];
      const double l = 0.2126 * r.x + 0.7152 * r.y + 0.0722 * r.z;
      p[y * env.width + x] = l * std::sin((y + 0.5) / env.height * kPi);
      total += p[y * env.width + x];
    }
  for (double& v : p) v /= total;
  return p;
}

// The map direction turned back by the rotation, then its texel.
uint32_t texelOf(const scene::Environment& env, glm::dvec3 d) {
  const double a = glm::radians(double(env.rotationDegrees));
  const glm::dvec3 m(std::cos(a) * d.x - std::sin(a) * d.z, d.y,
                     std::sin(a) * d.x + std::cos(a) * d.z);
  double u = 0.5 + std::atan2(m.x, -m.z) / (2 * kPi);
  u -= std::floor(u);
  const double v = std::acos(std::clamp(m.y, -1.0, 1.0)) / kPi;
  const uint32_t x = std::min(uint32_t(u * env.width), env.width - 1);
  const uint32_t y = std::min(uint32_t(v * env.height), env.height - 1);
  return y * env.width + x;
}

std::vector<Result> run(rhi::IDevice& device, const scene::Environment& env, uint32_t mode,
                        const std::vector<gpu::float4>& inputs) {
  test::ComputeHarness harness(device, "environment_harness.comp");
  const render::EnvironmentTables t = render::buildEnvironmentTables(env);
  struct {
    uint32_t mode, count;
  } push{mode, uint32_t(inputs.size())};
  const auto raw = harness.run(&push, sizeof(push),
                               {{&t.info, sizeof(t.info)},
                                {t.texels.data(), t.texels.size() * sizeof(gpu::float4)},
                                {t.cdf.data(), t.cdf.size() * sizeof(float)},
                                {inputs.data(), inputs.size() * sizeof(gpu::float4)}},
                               inputs.size() * 8 * sizeof(float), (push.count + 63) / 64);
  std::vector<float> f(inputs.size() * 8);
  std::memcpy(f.data(), raw.data(), f.size() * sizeof(float));
  std::vector<Result> results(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    const float* r = &f[i * 8];
    results[i] = {{r[0], r[1], r[2]}, r[3], {r[4], r[5], r[6]}, r[7]};
  }
  return results;
}

std::vector<gpu::float4> uniformPairs(size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<gpu::float4> pairs(count);
  for (auto& p : pairs) p = {std::min(u(rng), 0.99999994f), std::min(u(rng), 0.99999994f), 0, 0};
  return pairs;
}

}  // namespace

TEST_CASE("environment sampling: directions follow luminance x sin(theta) (chi-square)",
          "[shaders][gpu][environment][spirv-only]") {
  auto device = test::makeTestDevice();
  const scene::Environment env = testMap();
  const std::vector<double> p = expectedTexelProbabilities(env);
  constexpr size_t kSamples = 200000;
  const auto results = run(*device, env, 0, uniformPairs(kSamples, 7));
  std::vector<double> counts(p.size(), 0.0);
  int mismatches = 0, edgeMismatches = 0;
  std::string mismatchLog;  // the first few
  for (const auto& r : results) {
    REQUIRE(std::abs(glm::length(r.direction) - 1.0) < 1e-5);
    const uint32_t texel = texelOf(env, r.direction);
    counts[texel] += 1;  // never one the density gives nothing (the black band) but at its edge
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - r.direction.y * r.direction.y));
    const double expected = p[texel] * env.width * env.height / (2 * kPi * kPi * sinTheta);
    const glm::vec3 texelRadiance = env.radiance[texel];
    if (std::abs(r.pdf - expected) > 1e-3 * expected ||
        std::abs(r.radiance.x - texelRadiance.x) > 1e-6 * (1 + texelRadiance.x)) {
      // Where the direction lies in texels (the test's double arithmetic).
      double u = 0.5 + std::atan2(r.direction.x, -r.direction.z) / (2 * kPi);
      u -= std::floor(u);
      const double x = u * env.width;
      const double y = std::acos(std::clamp(r.direction.y, -1.0, 1.0)) / kPi * env.height;
      const double toEdge = std::min(std::abs(x - std::round(x)), std::abs(y - std::round(y)));
      if (toEdge < 0.005) {
        ++edgeMismatches;
      } else {
        if (mismatches++ < 5)
          mismatchLog +=
              fmt::format("texel ({:.4f}, {:.4f}): density {} for {}, radiance {} for {}\n", x, y,
                          r.pdf, expected, r.radiance.x, texelRadiance.x);
      }
    }
  }
  // The density must be the documented one to 0.1 % (its float error is
  // ~1e-6), the radiance the texel's, except for directions within 0.005
  // texel of an edge: Vulkan's sin, cos and acos are exact only to 2^-11
  // (absolute), so the shader and this test's double arithmetic may put
  // those on different sides (measured on lavapipe: 50 of 200000, all
  // within 0.001 texel).
  INFO(mismatchLog);
  INFO(mismatches << " samples away from texel edges and " << edgeMismatches
                  << " at an edge report another texel's density or radiance");
  CHECK(mismatches == 0);
  CHECK(edgeMismatches <= int(kSamples / 1000));
  // Cells with fewer than 5 expected samples are pooled.
  double statistic = 0, pooledObserved = 0, pooledExpected = 0;
  int cells = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double expected = p[i] * kSamples;
    if (expected < 5) {  // the black band's texels too (their edges' few samples)
      pooledObserved += counts[i];
      pooledExpected += expected;
      continue;
    }
    statistic += (counts[i] - expected) * (counts[i] - expected) / expected;
    ++cells;
  }
  if (pooledExpected > 0) {
    statistic +=
        (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++cells;
  }
  const double pValue = boost::math::gamma_q((cells - 1) / 2.0, statistic / 2.0);
  INFO("chi-square " << statistic << " over " << cells << " cells, p = " << pValue);
  // p > 1e-3 fails a correct sampler once in a thousand seeds; a texel
  // drawn 10 % too often at 200k samples (the spot's share: ~40 %) is
  // rejected at p ~ 1e-50.
  CHECK(pValue > 1e-3);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment sampling: the density integrates to 1 over the sphere",
          "[shaders][gpu][environment][spirv-only]") {
  auto device = test::makeTestDevice();
  scene::Environment env = testMap();
  env.rotationDegrees = 33.0f;
  // Equal-area cells: uniform in z = cos(theta) and in phi; 1024 x 512
  // cell centres, each 4 pi / N of solid angle.
  const uint32_t nx = 1024, nz = 512;
  std::vector<gpu::float4> dirs;
  for (uint32_t j = 0; j < nz; ++j)
    for (uint32_t i = 0; i < nx; ++i) {
      const double z = 1.0 - 2.0 * (j + 0.5) / nz, phi = 2 * kPi * (i + 0.5) / nx;
      const double r = std::sqrt(1 - z * z);
      dirs.push_back({float(r * std::cos(phi)), float(z), float(r * std::sin(phi)), 0.0f});
    }
  const auto results = run(*device, env, 1, dirs);
  double integral = 0;
  for (const auto& r : results) integral += r.pdf;
  integral *= 4 * kPi / double(nx * nz);
  INFO("integral " << integral);
  // The grid's error is where cells straddle texel edges: about 0.1 %
  // here; a density missing the sin(theta) Jacobian or a factor of the
  // texel count is off by 20 % or more.
  CHECK(std::abs(integral - 1.0) < 0.005);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment: directions read the documented texels, rotated",
          "[shaders][gpu][environment][spirv-only]") {
  auto device = test::makeTestDevice();
  // One bright texel per axis direction, so each lookup says where it read.
  scene::Environment env;
  env.width = 8;
  env.height = 4;
  env.source = "axes";
  env.radiance.assign(32, glm::vec3(0.0f));
  env.radiance[1 * 8 + 4] = {1, 0,
                             0};  // u 0.5-0.625, v 0.25-0.5: the centre column, above the horizon
  env.radiance[1 * 8 + 6] = {0, 1, 0};                           // u 0.75-0.875: towards +x
  for (uint32_t x = 0; x < 8; ++x) env.radiance[x] = {0, 0, 1};  // the top row: up (any azimuth)
  const auto lookup = [&](const scene::Environment& e, glm::vec3 d) {
    return run(*device, e, 1, {{d.x, d.y, d.z, 0.0f}})[0].radiance;
  };
  // Slightly off the texel edges, above the horizon.
  const glm::vec3 front = glm::normalize(glm::vec3(0.1f, 0.3f, -1.0f));
  const glm::vec3 right = glm::normalize(glm::vec3(1.0f, 0.3f, 0.1f));
  CHECK(lookup(env, front).x == 1.0);
  CHECK(lookup(env, right).y == 1.0);
  CHECK(lookup(env, {0.0f, 1.0f, 0.0f}).z == 1.0);
  // Rotated by 90 degrees counter-clockwise seen from above: what lay in
  // front (-z) now lies to the left (-x), and +x's texel is now in front.
  env.rotationDegrees = 90.0f;
  const glm::vec3 left = glm::normalize(glm::vec3(-1.0f, 0.3f, -0.1f));
  CHECK(lookup(env, left).x == 1.0);
  CHECK(lookup(env, front).y == 1.0);
  // Sampling with the same numbers, rotated, turns each direction by the
  // rotation: x' = x cos a + z sin a, z' = -x sin a + z cos a.
  scene::Environment map = testMap();
  const auto pairs = uniformPairs(256, 3);
  const auto plain = run(*device, map, 0, pairs);
  map.rotationDegrees = 90.0f;
  const auto turned = run(*device, map, 0, pairs);
  for (size_t i = 0; i < pairs.size(); ++i) {
    const glm::dvec3 d = plain[i].direction;
    const glm::dvec3 expected(d.z, d.y, -d.x);
    CHECK(glm::length(turned[i].direction - expected) < 1e-5);
    CHECK(std::abs(turned[i].pdf - plain[i].pdf) <= 1e-5 * plain[i].pdf);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment: the density a sample reports is the one MIS evaluates",
          "[shaders][gpu][environment][spirv-only]") {
  auto device = test::makeTestDevice();
  scene::Environment env = testMap();
  env.rotationDegrees = -71.0f;
  env.intensity = 2.5f;
  const auto results = run(*device, env, 0, uniformPairs(4096, 11));
  for (const auto& r : results) {
    REQUIRE(r.pdf > 0.0);
    CHECK(std::abs(r.pdfAgain - r.pdf) <= 1e-3 * r.pdf);
    // Intensity scales the radiance, not the density.
    const glm::vec3 texel = env.radiance[texelOf(env, r.direction)];
    CHECK(std::abs(r.radiance.y - 2.5 * texel.y) <= 1e-5 * (1 + texel.y));
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("environment sampling: a texel's probability is the one its float table steps draw",
          "[environment]") {
  // A texel's draw probability is the width of its row's step in the rows'
  // float CDF times the width of its own step in the row's (the search
  // takes the first entry above u). A dim texel after a bright one has a
  // step of about 1e-8 in double, which float rounding makes 0 or 6e-8:
  // a probability taken from the double weights would then be off by
  // that factor for NEE and MIS alike.
  scene::Environment env;
  env.width = 8;
  env.height = 4;
  env.source = "high dynamic range";
  env.radiance.assign(32, glm::vec3(0.01f));
  env.radiance[1 * 8 + 2] = glm::vec3(1e6f);  // a sun in row 1
  env.radiance[2 * 8 + 0] = glm::vec3(3.0f);
  const render::EnvironmentTables t = render::buildEnvironmentTables(env);
  REQUIRE(t.cdf.size() == 4 + 32);
  double sum = 0.0;
  bool someStepRoundedAway = false;
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 8; ++x) {
      const double row = double(t.cdf[y]) - (y > 0 ? double(t.cdf[y - 1]) : 0.0);
      const size_t c = 4 + y * 8 + x;
      const double column = double(t.cdf[c]) - (x > 0 ? double(t.cdf[c - 1]) : 0.0);
      const double drawn = row * column;
      INFO("texel (" << x << ", " << y << ")");
      CHECK(double(t.texels[y * 8 + x].w) == Catch::Approx(drawn).epsilon(1e-6).margin(1e-30));
      sum += t.texels[y * 8 + x].w;
      const double exact = expectedTexelProbabilities(env)[y * 8 + x];
      if (std::abs(drawn - exact) > 0.5 * exact) someStepRoundedAway = true;
    }
  // The map is one where it matters: float rounding moved some texel's
  // draw probability by more than half its exact value.
  CHECK(someStepRoundedAway);
  CHECK(sum == Catch::Approx(1.0).epsilon(1e-6));
}
