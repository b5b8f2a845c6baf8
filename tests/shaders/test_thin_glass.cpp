// Thin glass (Disney `thin`) is a sheet with the same medium on both sides:
// light meets an air-to-glass boundary whichever face it arrives at, so there
// is no total internal reflection and the lobe looks the same from both
// faces. Before this was tested, light arriving at the back face used the
// glass-to-air index, was totally reflected beyond 41.8 degrees and stayed
// trapped inside a thin glass sphere (a soap bubble went 16-50% dark in the
// glass furnace).
#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "bsdf_harness.h"
#include "test_device.h"

using namespace penumbra;
using test::BsdfHarness;

namespace {
constexpr float kIor = 1.5f;

glm::vec3 direction(float cosTheta, float phi, bool backFace) {
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), backFace ? -cosTheta : cosTheta};
}
glm::vec3 throughSheet(glm::vec3 v) {
  return {v.x, v.y, -v.z};
}

// Unpolarised Fresnel reflectance from index 1 into `ior` at incidence cosine c.
double fresnelAirTo(double ior, double c) {
  const double sinT2 = (1.0 - c * c) / (ior * ior);
  const double cosT = std::sqrt(1.0 - sinT2);
  const double rs = (c - ior * cosT) / (c + ior * cosT);
  const double rp = (cosT - ior * c) / (cosT + ior * c);
  return 0.5 * (rs * rs + rp * rp);
}

scene::Material thinGlass(float roughness) {
  scene::Material m;
  m.baseColor = glm::vec3(1.0f);
  m.specTrans = 1.0f;
  m.roughness = roughness;
  m.ior = kIor;
  m.thin = true;
  return m;
}
}  // namespace

TEST_CASE("thin smooth glass reflects with the air-to-glass Fresnel from either face",
          "[shaders][bsdf][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  BsdfHarness harness(*device);
  const auto m = thinGlass(0.0f);
  // cos 0.5 and 0.2 are beyond the glass-to-air critical angle (cos 0.745),
  // where a back face that took itself for glass would reflect everything.
  for (bool backFace : {false, true})
    for (float c : {1.0f, 0.5f, 0.2f}) {
      INFO((backFace ? "back" : "front") << " face, cos " << c);
      const glm::vec3 wo = direction(c, 0.3f, backFace);
      const auto samples = harness.sample(m, wo, 1u << 16, 11);
      uint64_t reflected = 0;
      for (const auto& s : samples) {
        REQUIRE(s.isDelta);
        if (s.wi.z * wo.z > 0) {
          ++reflected;
        } else {
          // Straight through, untinted (baseColor 1), no 1/eta^2: the sheet
          // does not change the medium.
          REQUIRE(std::abs(s.wi.x + wo.x) < 1e-5f);
          REQUIRE(std::abs(s.wi.y + wo.y) < 1e-5f);
          REQUIRE(std::abs(s.wi.z + wo.z) < 1e-5f);
        }
        REQUIRE(std::abs(s.weight.x - 1.0f) < 1e-5f);
      }
      const double f = fresnelAirTo(kIor, c);
      const double fraction = double(reflected) / samples.size();
      // Binomial: 4 standard errors of 65536 samples.
      INFO("reflected fraction " << fraction << " vs Fresnel " << f);
      REQUIRE(std::abs(fraction - f) <= 4 * std::sqrt(f * (1 - f) / samples.size()));
    }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("thin rough glass evaluates the same from either face",
          "[shaders][bsdf][gpu][spirv-only]") {
  // Mirroring both directions through the sheet must not change f or pdf.
  auto device = test::makeTestDevice();
  BsdfHarness harness(*device);
  const auto m = thinGlass(0.5f);
  for (float c : {0.9f, 0.5f, 0.2f}) {
    INFO("cos " << c);
    const glm::vec3 wo = direction(c, 0.3f, false);
    std::vector<glm::vec3> wi, wiMirrored;
    for (int i = 0; i < 64; ++i) {
      // Both hemispheres: reflection (z > 0) and transmission (z < 0).
      const float ci = -0.95f + 1.9f * (float(i) + 0.5f) / 64.0f;
      wi.push_back(direction(std::abs(ci), 0.3f + 2.3f * float(i), ci < 0.0f));
      wiMirrored.push_back(throughSheet(wi.back()));
    }
    const auto front = harness.eval(m, wo, wi);
    const auto back = harness.eval(m, throughSheet(wo), wiMirrored);
    uint32_t nonZero = 0;
    for (size_t i = 0; i < wi.size(); ++i) {
      INFO("wi " << wi[i].x << " " << wi[i].y << " " << wi[i].z);
      const float scale = std::max(front[i].f.x, 1e-6f);
      REQUIRE(std::abs(front[i].f.x - back[i].f.x) <= 1e-4f * scale);
      REQUIRE(std::abs(front[i].pdf - back[i].pdf) <= 1e-4f * std::max(front[i].pdf, 1e-6f));
      if (front[i].f.x > 0.0f) ++nonZero;
    }
    REQUIRE(nonZero >= 32u);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
