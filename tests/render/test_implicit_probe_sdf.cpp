// Ray-level checks of the sphere-traced kinds (torus, rounded box, blend,
// Mandelbulb) through the production pipeline, against closed-form surfaces.
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

constexpr float kTolerance = 1e-5f;  // object space, for every object below but the step-limit pair

scene::ImplicitObject marched(std::string name, scene::ImplicitShape shape, glm::mat4 transform,
                              float tolerance = kTolerance, uint32_t maxSteps = 1000) {
  auto o = test::implicitObject(std::move(name), std::move(shape), transform);
  o.sphereTracing = {maxSteps, tolerance};
  return o;
}

// A march stops where the distance bound is below `tolerance` and then
// steps by that bound once more. The bound falls along the ray at `slope`
// (the incidence cosine for an exact SDF, less where a blend's gradient is
// shorter than 1), so what is left to the surface is below
// tolerance / slope; plus float rounding of the position (1e-6 relative).
double sdfTTolerance(double worldTolerance, double slope, double t) {
  return worldTolerance / slope + 1e-6 * t;
}

// Normals are sampled at 1e-3 |p| (sphere_tracing.hlsli): float rounding of
// the distances (a few 1e-7 |p|) tilts them by ~2e-4, curvature by
// (1e-3 |p| / radius of curvature)^2 < 1e-4 here.
constexpr double kNormalTolerance = 1e-3;

// Blend primitives k apart: the smooth minimum lifts the saddle between two
// spheres of radius 0.5 whose centres are +-0.55 by k/4, closing the 0.1 gap.
shapes::Blend twoSpheres(float blendRadius) {
  shapes::Blend b;
  b.primitives = {{shapes::Sphere{0.5f}, glm::vec3(-0.55f, 0, 0)},
                  {shapes::Sphere{0.5f}, glm::vec3(0.55f, 0, 0)}};
  b.blendRadius = blendRadius;
  return b;
}

// A flat slab with a small sphere far above it, joined without blending, so
// the object's bounds reach high above the slab and a march can start there.
shapes::Blend slabUnderTallBounds() {
  shapes::Blend b;
  b.primitives = {{shapes::Box{glm::vec3(2, 0.5f, 2)}, glm::vec3(0)},
                  {shapes::Sphere{0.1f}, glm::vec3(0, 10, 0)}};
  b.blendRadius = 0.0f;
  return b;
}

}  // namespace

TEST_CASE("implicit probe: torus, rounded box and blend, from outside, inside and grazing",
          "[render][gpu][implicit]") {
  auto device = test::makeTestDevice();
  const glm::mat4 stoodUpDoubled =
      glm::scale(glm::rotate(test::translate({30, 0, 10}), glm::radians(90.0f), glm::vec3(1, 0, 0)),
                 glm::vec3(2.0f));
  auto s = test::implicitScene({
      marched("torus", shapes::Torus{1.0f, 0.25f}, test::translate({0, 0, 5})),
      marched("big torus", shapes::Torus{1.0f, 0.25f}, stoodUpDoubled),
      marched("rounded box", shapes::RoundedBox{glm::vec3(1), 0.2f}, test::translate({0, 20, 5})),
      marched("blend", twoSpheres(0.3f), test::translate({0, 40, 5})),
      marched("union", twoSpheres(0.0f), test::translate({20, 40, 5})),
  });
  render::PathTracer tracer(*device, s, 1, 1);

  const glm::dvec3 corner = glm::normalize(glm::dvec3(1, 1, 1));
  const glm::dvec3 edge = glm::normalize(glm::dvec3(1, 0, 1));
  const glm::dvec3 boxCentre(0, 20, 5);
  std::vector<render::ProbeRay> rays = {
      probeRay({0, 0, 0}, {0, 0, 1}),               // 0 torus, outer equator
      probeRay({0, 5, 5}, {0, -1, 0}),              // 1 torus, down its hole
      probeRay({1, 5, 5}, {0, -1, 0}),              // 2 torus, top of the tube
      probeRay({1, 0, 5}, {0, 1, 0}),               // 3 from inside the tube, up
      probeRay({1, 0, 5}, {1, 0, 0}),               // 4 from inside the tube, out
      probeRay({-5, 0.24, 5}, {1, 0, 0}),           // 5 grazing the tube top
      probeRay({-5, 0.26, 5}, {1, 0, 0}),           // 6 just over the tube
      probeRay({32, 0, 20}, {0, 0, -1}),            // 7 big torus, its front (+z now)
      probeRay({32, 0, 0}, {0, 0, 1}),              // 8 big torus, its back
      probeRay({50, 0, 10}, {-1, 0, 0}),            // 9 big torus, outer equator
      probeRay({0, 20, 0}, {0, 0, 1}),              // 10 rounded box face
      probeRay(boxCentre + 5.0 * corner, -corner),  // 11 rounded box corner
      probeRay(boxCentre + 5.0 * edge, -edge),      // 12 rounded box edge
      probeRay(boxCentre, {1, 0, 0}),               // 13 from inside the rounded box
      probeRay({0, 45, 5}, {0, -1, 0}),             // 14 down onto the blend's neck
      probeRay({-5, 40, 5}, {1, 0, 0}),             // 15 blend, far side of one sphere
      probeRay({20, 45, 5}, {0, -1, 0}),            // 16 the same neck without blending
  };
  const auto hits = tracer.traceProbeRays(rays);

  const double tol = kTolerance;
  checkHit(rays[0], hits[0], {3.75, {0, 0, -1}, sdfTTolerance(tol, 1, 3.75), kNormalTolerance});
  checkMiss(rays[1], hits[1]);
  checkHit(rays[2], hits[2], {4.75, {0, 1, 0}, sdfTTolerance(tol, 1, 4.75), kNormalTolerance});
  checkHit(rays[3], hits[3], {0.25, {0, 1, 0}, sdfTTolerance(tol, 1, 0.25), kNormalTolerance});
  checkHit(rays[4], hits[4], {0.25, {1, 0, 0}, sdfTTolerance(tol, 1, 0.25), kNormalTolerance});
  // At height 0.24 the tube (radius 0.25 round x = -1) starts at
  // x = -1 - sqrt(0.25^2 - 0.24^2) = -1.07, where the normal is (-0.07, 0.24)/0.25.
  const double grazingT = 5.0 - 1.0 - std::sqrt(0.0625 - double(0.24f) * double(0.24f));
  const glm::dvec3 grazingNormal = glm::normalize(glm::dvec3(grazingT - 4.0, double(0.24f), 0));
  checkHit(
      rays[5], hits[5],
      {grazingT, grazingNormal, sdfTTolerance(tol, -grazingNormal.x, grazingT), kNormalTolerance});
  checkMiss(rays[6], hits[6]);
  // Scaled by 2 about (30, 0, 10) and stood up (its axis along z): the tube's
  // top (1, 0.25, 0) lands at (32, 0, 10.5), its outer rim at x = 32.5.
  const double bigTol = 2.0 * tol;
  checkHit(rays[7], hits[7], {9.5, {0, 0, 1}, sdfTTolerance(bigTol, 1, 9.5), kNormalTolerance});
  checkHit(rays[8], hits[8], {9.5, {0, 0, -1}, sdfTTolerance(bigTol, 1, 9.5), kNormalTolerance});
  checkHit(rays[9], hits[9], {17.5, {1, 0, 0}, sdfTTolerance(bigTol, 1, 17.5), kNormalTolerance});
  checkHit(rays[10], hits[10], {4.0, {0, 0, -1}, sdfTTolerance(tol, 1, 4), kNormalTolerance});
  // The corner is a sphere of radius 0.2 round (0.8, 0.8, 0.8), the edge a
  // cylinder of radius 0.2 round x = z = 0.8.
  const double cornerT = 5.0 - (0.8 * std::sqrt(3.0) + 0.2);
  checkHit(rays[11], hits[11], {cornerT, corner, sdfTTolerance(tol, 1, cornerT), kNormalTolerance});
  const double edgeT = 5.0 - (0.8 * std::sqrt(2.0) + 0.2);
  checkHit(rays[12], hits[12], {edgeT, edge, sdfTTolerance(tol, 1, edgeT), kNormalTolerance});
  checkHit(rays[13], hits[13], {1.0, {1, 0, 0}, sdfTTolerance(tol, 1, 1), kNormalTolerance});
  // On the y axis both spheres are sqrt(0.55^2 + y^2) - 0.5 away, equal, so
  // the smooth minimum is that minus k/4 = 0.075: zero at y = sqrt(0.575^2 - 0.55^2).
  // There it is the mean of the two distances, whose gradient along y is
  // y / 0.575: the blend's slope along the ray.
  const double neckY = std::sqrt(0.575 * 0.575 - 0.55 * 0.55);
  checkHit(
      rays[14], hits[14],
      {5.0 - neckY, {0, 1, 0}, sdfTTolerance(tol, neckY / 0.575, 5.0 - neckY), kNormalTolerance});
  // 1.1 from the other sphere, beyond k: no blending on the far side.
  checkHit(rays[15], hits[15], {3.95, {-1, 0, 0}, sdfTTolerance(tol, 1, 3.95), kNormalTolerance});
  checkMiss(rays[16], hits[16]);
  for (size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].isHit()) continue;
    const uint32_t expectedObject = i <= 6 ? 0u : i <= 9 ? 1u : i <= 13 ? 2u : 3u;
    INFO("ray " << i);
    CHECK(hits[i].instanceIndex == expectedObject);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("implicit probe: a march that reaches its step limit is a miss",
          "[render][gpu][implicit]") {
  // A ray 1 above a flat face, meeting it at 60 degrees: each step moves the
  // distance d along the ray, i.e. d cos 60 = d / 2 closer, so the k-th
  // distance is 2^-(k-1). Tolerance 1e-4 is first undercut by 2^-14 (2^-13 =
  // 1.2e-4 is not), at the 15th evaluation: 14 steps must miss, 15 must hit.
  auto device = test::makeTestDevice();
  auto s = test::implicitScene({
      marched("14 steps", slabUnderTallBounds(), test::translate({0, 0, 0}), 1e-4f, 14),
      marched("15 steps", slabUnderTallBounds(), test::translate({20, 0, 0}), 1e-4f, 15),
  });
  render::PathTracer tracer(*device, s, 1, 1);
  const glm::dvec3 start(0, 1.5, -std::sqrt(3.0));  // 1 above the slab's top face
  const glm::dvec3 direction(0, -0.5, std::sqrt(3.0) / 2);
  std::vector<render::ProbeRay> rays = {probeRay(start, direction),
                                        probeRay(start + glm::dvec3(20, 0, 0), direction)};
  const auto hits = tracer.traceProbeRays(rays);
  checkMiss(rays[0], hits[0]);
  CHECK(hits[0].hitT == -1.0f);  // the miss shader's report, not a partial march
  // The 15th distance is 2^-14; the final step along the ray leaves 2^-14.
  checkHit(rays[1], hits[1], {2.0, {0, 1, 0}, 1e-4, kNormalTolerance});
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("implicit probe: the Mandelbulb's tip on its axis", "[render][gpu][implicit]") {
  // On the +z axis the power-8 triplex iteration is the real map
  // x <- x^8 + c, which stays bounded exactly for c <= c* = (7/8) 8^(-1/7)
  // = 0.650 (its fixed point's derivative reaches 1 there). Just beyond c*
  // the orbit lingers in a bottleneck for about pi / sqrt(28 x*^6 (c - c*))
  // iterations, so with 32 iterations points up to ~0.003 past c* still look
  // bounded: the tip lies in [c*, c* + 0.01]. The tip is a cusp, so its
  // normal is whatever the finite differences make of it, but the bulb is
  // mirror-symmetric in y (phi -> -phi commutes with the triplex power), so
  // central differences give it no y component, and it faces the ray.
  auto device = test::makeTestDevice();
  shapes::Mandelbulb bulb{8.0f, 32};
  auto s = test::implicitScene({marched("bulb", bulb, test::translate({0, 0, 5}))});
  render::PathTracer tracer(*device, s, 1, 1);
  const double cStar = 0.875 * std::pow(8.0, -1.0 / 7.0);
  std::vector<render::ProbeRay> rays = {probeRay({0, 0, 8}, {0, 0, -1}),
                                        probeRay({0, 1.3, 8}, {0, 0, -1})};
  const auto hits = tracer.traceProbeRays(rays);
  INFO("tip at z = " << 5.0 + 3.0 - hits[0].hitT << " (c* = " << cStar << ")");
  REQUIRE(hits[0].isHit());
  const double tipZ = 3.0 - hits[0].hitT;
  CHECK(tipZ >= cStar - 1e-3);
  CHECK(tipZ <= cStar + 0.01);
  CHECK(hits[0].geometricNormal.z > 0.0f);
  CHECK(std::abs(hits[0].geometricNormal.y) <= 1e-3f);
  // 1.3 off the axis is outside the ball of radius 2^(1/7) = 1.10 that holds the set.
  checkMiss(rays[1], hits[1]);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
