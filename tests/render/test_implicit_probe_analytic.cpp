// Ray-level checks of the analytic implicit kinds (sphere, plane, box) through
// the production pipeline (PathTracer::traceProbeRays), against closed-form
// intersections. Tolerances are float32 error bounds with margin: a solver
// that is right to float precision passes, a wrong root, normal or
// object-to-world scaling is off by far more.
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "implicit_test_support.h"
#include "test_device.h"

using namespace penumbra;
using test::checkHit;
using test::checkMiss;
using test::probeRay;

namespace {
namespace shapes = scene::implicit;

// Unit-sized scenes: float32 puts t and normals within ~1e-6; 1e-5 leaves
// a tenfold margin.
constexpr double kUnitTolerance = 1e-5;

// Exact ray/sphere intersection in double: the nearest root >= 0.
struct SphereRoot {
  double t;
  glm::dvec3 normal;
};
SphereRoot nearestSphereRoot(glm::dvec3 origin, glm::dvec3 direction, glm::dvec3 centre,
                             double radius) {
  const glm::dvec3 d = glm::normalize(direction);
  const glm::dvec3 f = origin - centre;
  const double b = glm::dot(f, d);
  const glm::dvec3 closest = f - b * d;
  const double halfChord = std::sqrt(radius * radius - glm::dot(closest, closest));
  const double t = -b - halfChord >= 0.0 ? -b - halfChord : -b + halfChord;
  return {t, glm::normalize(f + t * d)};
}

// The ray as the GPU receives it (float), for exact expectations.
glm::dvec3 asSent(glm::vec3 v) {
  return glm::dvec3(v);
}

}  // namespace

TEST_CASE("implicit probe: spheres, grazing, from inside, tiny and distant, ellipsoid",
          "[render][gpu][implicit]") {
  auto device = test::makeTestDevice();
  auto s = test::implicitScene({
      test::implicitObject("unit", shapes::Sphere{1.0f}, test::translate({0, 0, 5})),
      // Radius 1e-3 at distance 1e4: b^2 - c would cancel to nothing in float.
      test::implicitObject("tiny far", shapes::Sphere{1e-3f}, test::translate({1e4f, 0, 0})),
      test::implicitObject("ellipsoid", shapes::Sphere{1.0f},
                           glm::scale(test::translate({0, 30, 10}), glm::vec3(1, 2, 3))),
      test::implicitObject("half-size", shapes::Sphere{1.0f},
                           glm::scale(test::translate({0, -30, 10}), glm::vec3(0.5f))),
  });
  // A triangle quad (facing +z) first, so implicit instance indices start at 1.
  scene::Mesh quad;
  quad.name = "quad";
  quad.positions = {{-21, -1, 5}, {-19, -1, 5}, {-19, 1, 5}, {-21, 1, 5}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  s.meshes.push_back(quad);
  s.instances.push_back({0, glm::mat4(1.0f)});
  render::PathTracer tracer(*device, s, 1, 1);

  const double grazingHalfChord = std::sqrt(1.0 - double(0.999f) * double(0.999f));
  const double insideHalfChord = std::sqrt(1.0 - 0.25);
  std::vector<render::ProbeRay> rays = {
      probeRay({0, 0, 0}, {0, 0, 1}),         // 0 head-on
      probeRay({0, 0.6, 0}, {0, 0, 1}),       // 1 off-centre
      probeRay({0, 0.999f, 0}, {0, 0, 1}),    // 2 grazing, just inside the rim
      probeRay({0, 1.001f, 0}, {0, 0, 1}),    // 3 grazing, just outside
      probeRay({0, 0, 5}, {0, 0, 1}),         // 4 from the centre
      probeRay({0, 0.5, 4.5}, {0, 0, 1}),     // 5 from inside, off-centre
      probeRay({0, 0, 0}, {0, 0, -1}),        // 6 pointing away
      probeRay({0, 0, 0}, {0, 0, 1}, 3.9f),   // 7 tMax short of it
      probeRay({-20, 0, 0}, {0, 0, 1}),       // 8 the triangle quad
      probeRay({0, 0, 0}, {1e4, 0, 0}),       // 9 tiny far sphere, centre
      probeRay({0, 0, 0}, {1e4, 5e-4, 0}),    // 10 half its radius off-centre
      probeRay({0, 0, 0}, {1e4, 9e-4, 0}),    // 11 near its rim
      probeRay({0, 0, 0}, {1e4, 1.1e-3, 0}),  // 12 past its rim
      probeRay({9999.5, 0, 0}, {1, 0, 0}),    // 13 from close by
      probeRay({0, 30, 0}, {0, 0, 1}),        // 14 ellipsoid, along its 3 axis
      probeRay({5, 31, 10}, {-1, 0, 0}),      // 15 ellipsoid, off-axis
      probeRay({0, -30, 0}, {0, 0, 1}),       // 16 half-size sphere
  };
  const auto hits = tracer.traceProbeRays(rays);
  REQUIRE(hits.size() == rays.size());

  checkHit(rays[0], hits[0], {4.0, {0, 0, -1}, kUnitTolerance, kUnitTolerance});
  checkHit(rays[1], hits[1], {4.2, {0, 0.6, -0.8}, kUnitTolerance, kUnitTolerance});
  checkHit(rays[2], hits[2],
           {5.0 - grazingHalfChord,
            {0, double(0.999f), -grazingHalfChord},
            kUnitTolerance,
            kUnitTolerance});
  checkMiss(rays[3], hits[3]);
  checkHit(rays[4], hits[4], {1.0, {0, 0, 1}, kUnitTolerance, kUnitTolerance});
  checkHit(rays[5], hits[5],
           {0.5 + insideHalfChord, {0, 0.5, insideHalfChord}, kUnitTolerance, kUnitTolerance});
  checkMiss(rays[6], hits[6]);
  checkMiss(rays[7], hits[7]);
  checkHit(rays[8], hits[8], {5.0, {0, 0, 1}, kUnitTolerance, kUnitTolerance});
  CHECK(hits[8].instanceIndex == 0u);
  for (int i : {0, 1, 2, 4, 5}) CHECK(hits[i].instanceIndex == 1u);
  CHECK(hits[0].primitiveIndex == 0u);

  // World t near 1e4 is resolved to float's spacing there (9.8e-4), so t is
  // held to two spacings; the normal comes from the closest approach and the
  // half chord, which keep their relative precision, so it is held to 1e-4.
  const glm::dvec3 farCentre(1e4, 0, 0);
  for (int i : {9, 10, 11}) {
    const auto root =
        nearestSphereRoot(asSent(rays[i].origin), asSent(rays[i].direction), farCentre, 1e-3);
    checkHit(rays[i], hits[i], {root.t, root.normal, 2e-3, 1e-4});
    CHECK(hits[i].instanceIndex == 2u);
  }
  checkMiss(rays[12], hits[12]);
  checkHit(rays[13], hits[13], {0.5 - 1e-3, {-1, 0, 0}, kUnitTolerance, 1e-4});

  // Ellipsoid x^2 + (y/2)^2 + (z/3)^2 = 1 around (0, 30, 10): along z it ends
  // at z = 7; at y = 1 (local) it reaches x = sqrt(1 - 1/4), where the normal
  // is along (x, y/4, z/9).
  checkHit(rays[14], hits[14], {7.0, {0, 0, -1}, kUnitTolerance, kUnitTolerance});
  const double ellipseX = std::sqrt(0.75);
  checkHit(rays[15], hits[15],
           {5.0 - ellipseX, glm::normalize(glm::dvec3(ellipseX, 0.25, 0)), kUnitTolerance,
            kUnitTolerance});
  // Radius 1 scaled by 0.5: world t must be in world units.
  checkHit(rays[16], hits[16], {9.5, {0, 0, -1}, kUnitTolerance, kUnitTolerance});
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("implicit probe: infinite and bounded planes, boxes from outside and inside",
          "[render][gpu][implicit]") {
  auto device = test::makeTestDevice();
  const glm::mat4 standUp =  // the bounded plane's front turned from +y to +z
      glm::rotate(test::translate({0, 5, 10}), glm::radians(90.0f), glm::vec3(1, 0, 0));
  const glm::mat4 turned =
      glm::rotate(test::translate({0, 40, 10}), glm::radians(45.0f), glm::vec3(0, 1, 0));
  auto s = test::implicitScene({
      test::implicitObject("floor", shapes::Plane{}, test::translate({0, -1, 0})),
      test::implicitObject("panel", shapes::Plane{glm::vec2(1, 2)}, standUp),
      test::implicitObject("box", shapes::Box{glm::vec3(1, 0.5, 2)}, test::translate({0, 20, 10})),
      test::implicitObject("turned box", shapes::Box{glm::vec3(1)}, turned),
  });
  render::PathTracer tracer(*device, s, 1, 1);

  const double diagonal = std::sqrt(0.5);
  const glm::dvec3 toTurnedCentre(diagonal, 0, diagonal);
  std::vector<render::ProbeRay> rays = {
      probeRay({0, 1, 0}, {0, -1, 0}),               // 0 floor from above
      probeRay({0, -3, 0}, {0, 1, 0}),               // 1 floor from below
      probeRay({0, 1, 0}, {1, -1, 0}),               // 2 floor at 45 degrees
      probeRay({0, 1, 0}, {1, -1e-3, 0}),            // 3 floor, grazing
      probeRay({0, 1, 0}, {1, 0, 0}),                // 4 parallel to the floor
      probeRay({0, 5, 0}, {0, 0, 1}),                // 5 panel centre
      probeRay({0.9, 6.9, 0}, {0, 0, 1}),            // 6 panel, inside its corner
      probeRay({1.1, 5, 0}, {0, 0, 1}),              // 7 beside the panel
      probeRay({0, 7.1, 0}, {0, 0, 1}),              // 8 above the panel
      probeRay({0, 5, 20}, {0, 0, -1}),              // 9 panel from behind
      probeRay({0, 20, 0}, {0, 0, 1}),               // 10 box -z face
      probeRay({5, 20.2, 10}, {-1, 0, 0}),           // 11 box +x face
      probeRay({0.3, 25, 9}, {0, -1, 0}),            // 12 box top
      probeRay({0.3, 15, 11}, {0, 1, 0}),            // 13 box bottom
      probeRay({0, 20, 10}, {0, 1, 0}),              // 14 from the box centre
      probeRay({0, 20, 10}, {1, 1, 0}),              // 15 from the centre, diagonally
      probeRay({-5, 20.5f - 1e-4f, 10}, {1, 0, 0}),  // 16 grazing just under the top
      probeRay({-5, 20.5f + 1e-4f, 10}, {1, 0, 0}),  // 17 grazing just over it
      probeRay(glm::dvec3(0, 40, 10) - 5.0 * toTurnedCentre, toTurnedCentre),  // 18
  };
  const auto hits = tracer.traceProbeRays(rays);

  const double tol = kUnitTolerance;
  checkHit(rays[0], hits[0], {2.0, {0, 1, 0}, tol, tol});
  checkHit(rays[1], hits[1], {2.0, {0, 1, 0}, tol, tol});  // the front normal, seen from behind
  checkHit(rays[2], hits[2], {2.0 * std::sqrt(2.0), {0, 1, 0}, tol, tol});
  // t = 2 / |d.y| = 2000.001: -o.y / d.y is exact to a few ULPs, so relative 1e-5.
  const double grazingT = 2.0 / (double(rays[3].direction.y) * -1.0);
  checkHit(rays[3], hits[3], {grazingT, {0, 1, 0}, 1e-5 * grazingT, tol});
  checkMiss(rays[4], hits[4]);
  checkHit(rays[5], hits[5], {10.0, {0, 0, 1}, tol, tol});
  checkHit(rays[6], hits[6], {10.0, {0, 0, 1}, tol, tol});
  checkMiss(rays[7], hits[7]);
  checkMiss(rays[8], hits[8]);
  checkHit(rays[9], hits[9], {10.0, {0, 0, 1}, tol, tol});
  checkHit(rays[10], hits[10], {8.0, {0, 0, -1}, tol, tol});
  checkHit(rays[11], hits[11], {4.0, {1, 0, 0}, tol, tol});
  checkHit(rays[12], hits[12], {4.5, {0, 1, 0}, tol, tol});
  checkHit(rays[13], hits[13], {4.5, {0, -1, 0}, tol, tol});
  checkHit(rays[14], hits[14], {0.5, {0, 1, 0}, tol, tol});
  checkHit(rays[15], hits[15], {0.5 * std::sqrt(2.0), {0, 1, 0}, tol, tol});
  checkHit(rays[16], hits[16], {4.0, {-1, 0, 0}, tol, tol});
  checkMiss(rays[17], hits[17]);
  // The turned box's -z face now faces (-1, 0, -1)/sqrt(2), one unit from its centre.
  checkHit(rays[18], hits[18], {4.0, {-diagonal, 0, -diagonal}, tol, tol});
  for (size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].isHit()) continue;
    const uint32_t expectedObject = i <= 4 ? 0u : i <= 9 ? 1u : i <= 17 ? 2u : 3u;
    INFO("ray " << i);
    CHECK(hits[i].instanceIndex == expectedObject);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
