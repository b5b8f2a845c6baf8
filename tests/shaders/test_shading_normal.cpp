// The shading normal's bend for a valid mirror reflection
// (bendForValidReflection, shaders/shared/surface_hit.hlsli), run on the test
// device through harness/shading_normal_harness.comp, checked by what it
// promises rather than by its formula: a normal whose mirror reflection of
// the viewer already leaves the surface by the margin is returned as it is;
// any other is turned towards the geometric normal, in their plane, by the
// least angle that lifts the reflection to exactly the margin.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <random>
#include <vector>

#include "compute_harness.h"
#include "test_device.h"

using namespace penumbra;

namespace {

struct BendCase {
  glm::vec4 n, ng, wo;
};

// The reflection of wo about n, its height over the plane of ng.
double reflectionHeight(glm::dvec3 n, glm::dvec3 ng, glm::dvec3 wo) {
  return glm::dot(2.0 * glm::dot(n, wo) * n - wo, ng);
}

double margin(glm::dvec3 ng, glm::dvec3 wo) {
  return std::min(0.9 * glm::dot(wo, ng), 0.01);
}

glm::dvec3 unitFromAngles(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

TEST_CASE("shading normal: bent by the least turn that makes the mirror reflection valid",
          "[shaders][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  // Geometric normal +z; shading normals tilted up to 80 degrees (normal
  // maps); viewers from head-on to 0.06 degrees above the surface, the
  // grazing end where the margin is 0.9 wo.ng rather than 0.01.
  std::mt19937 rng(20261205);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<BendCase> cases;
  const glm::dvec3 ng(0, 0, 1);
  for (int i = 0; i < 4096; ++i) {
    const glm::dvec3 n =
        unitFromAngles(glm::radians(80.0) * u(rng), glm::two_pi<double>() * u(rng));
    const double woZ = i % 4 == 0 ? std::pow(10.0, -3.0 * u(rng)) : u(rng);
    const glm::dvec3 wo =
        unitFromAngles(std::acos(std::max(woZ, 1e-3)), glm::two_pi<double>() * u(rng));
    if (glm::dot(wo, n) <= 0.0) continue;  // shadingNormalFor hands these the geometric normal
    cases.push_back(
        {glm::vec4(glm::vec3(n), 0), glm::vec4(glm::vec3(ng), 0), glm::vec4(glm::vec3(wo), 0)});
  }
  test::ComputeHarness harness(*device, "shading_normal_harness.comp");
  const uint32_t count = uint32_t(cases.size());
  const auto bytes =
      harness.run(&count, sizeof(count), {{cases.data(), cases.size() * sizeof(BendCase)}},
                  cases.size() * sizeof(glm::vec4), (count + 63) / 64);
  std::vector<glm::vec4> bent(cases.size());
  std::memcpy(bent.data(), bytes.data(), bytes.size());

  int unchanged = 0, turned = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const glm::dvec3 n(cases[i].n), wo(cases[i].wo), b(bent[i]);
    INFO("case " << i << ": n " << n.x << " " << n.y << " " << n.z << ", wo " << wo.x << " " << wo.y
                 << " " << wo.z);
    REQUIRE(std::isfinite(b.x + b.y + b.z));
    CHECK(std::abs(glm::length(b) - 1.0) < 1e-5);
    const double m = margin(ng, wo);
    if (reflectionHeight(n, ng, wo) >= m + 1e-5) {
      // Valid already: untouched (float rounding of the test's own inputs aside).
      CHECK(glm::length(b - n) < 1e-6);
      ++unchanged;
      continue;
    }
    if (reflectionHeight(n, ng, wo) > m - 1e-5) continue;  // on the boundary: either answer
    ++turned;
    // In the plane of n and ng, between them: no component out of that plane,
    // and no further from ng than n was.
    const glm::dvec3 across = glm::normalize(glm::cross(ng, n));
    CHECK(std::abs(glm::dot(b, across)) < 1e-5);
    CHECK(glm::dot(b, ng) >= glm::dot(n, ng) - 1e-6);
    // The reflection now leaves at the margin: exactly there, since a lesser
    // turn would leave it below (the height grows monotonically towards ng
    // over this range, which the test checks by stepping back a little).
    CHECK(std::abs(reflectionHeight(b, ng, wo) - m) < 2e-4);
    const glm::dvec3 inPlane = glm::normalize(b - glm::dot(b, ng) * ng);
    const double tilt = std::atan2(glm::dot(b, inPlane), glm::dot(b, ng));
    const glm::dvec3 lessTurned = std::sin(tilt + 1e-2) * inPlane + std::cos(tilt + 1e-2) * ng;
    CHECK(reflectionHeight(lessTurned, ng, wo) < m);
  }
  // Both branches are exercised in quantity.
  CHECK(unchanged > 1000);
  CHECK(turned > 300);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
