// The thin-lens camera: a point-like emitter out of focus images to a disk
// of the circle of confusion the thin-lens construction gives; in focus, to
// a point; a bad lens is refused.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>

#include "penumbra/util/error.h"
#include "render_test_utils.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;

namespace {

constexpr uint32_t kSize = 64;
constexpr float kFovDegrees = 40.0f;
constexpr double kEmitterDistance = 4.0;
constexpr float kEmitterHalfSize = 0.025f;  // 1.1 px wide from 4 m: a point
constexpr uint32_t kSpp = 1024;             // about 1200 samples land on the emitter

// A camera at the origin looking along +z at a small square emitter 4 m
// ahead (facing it), on black.
scene::Scene pointEmitter(float apertureRadius, float focusDistance) {
  scene::Scene s;
  s.name = "point emitter";
  s.camera.forward = glm::vec3(0, 0, 1);
  s.camera.up = glm::vec3(0, 1, 0);
  s.camera.verticalFovDegrees = kFovDegrees;
  s.camera.apertureRadius = apertureRadius;
  s.camera.focusDistance = focusDistance;
  s.materials.push_back(scene::Material::lambert("light", glm::vec3(0.0f), glm::vec3(100.0f)));
  scene::Mesh quad;
  quad.name = "emitter";
  const float h = kEmitterHalfSize, z = float(kEmitterDistance);
  quad.positions = {{-h, -h, z}, {-h, h, z}, {h, h, z}, {h, -h, z}};  // facing -z
  quad.indices = {0, 1, 2, 0, 2, 3};
  s.meshes.push_back(quad);
  s.instances.push_back({0, glm::dmat4(1.0)});
  return s;
}

// The blurred image against the pinhole's: a disk of `radius` px within half
// a pixel (R = sqrt(2 (mean square - the pinhole's)), see below), the same
// flux (each image is about 1200 samples' worth: 3 % noise) and centre.
// Blurring moves light; it does not make or lose it, nor move its centre.
void checkDisk(const image::Image& img, const test::Spot& pinhole, double radius) {
  REQUIRE(image::countNonFinite(img) == 0);
  const auto blurred = test::measureSpot(img);
  const double measured = std::sqrt(2.0 * (blurred.meanSquare - pinhole.meanSquare));
  INFO("disk radius " << measured << " px, thin lens says " << radius << "; flux " << blurred.flux
                      << " vs pinhole " << pinhole.flux);
  CHECK(std::abs(measured - radius) < 0.5);
  CHECK(std::abs(blurred.flux / pinhole.flux - 1.0) < 0.1);
  CHECK(std::abs(blurred.cx - pinhole.cx) < 0.25);
  CHECK(std::abs(blurred.cy - pinhole.cy) < 0.25);
}

}  // namespace

// A lens of radius A focused at z_f sees a point at z_o as a disk on the
// focal plane of radius A |z_o - z_f| / z_o, which is A |z_o - z_f| /
// (z_o z_f tan(fov/2)) of the image's half height. The blurred image is the
// pinhole image spread by a uniform disk of radius R, whose mean squared
// radius R^2 / 2 adds to the pinhole image's own (the emitter's extent and
// the pixels'), so R = sqrt(2 (mean square - the pinhole's)). Within half a
// pixel: a lens of the wrong radius, or rays aimed at the wrong plane, moves
// R by more (10 % of the 4.4 px radius is 0.44 px).
TEST_CASE("depth of field: a point out of focus images to the circle of confusion",
          "[render][gpu][camera]") {
  auto device = test::makeTestDevice();
  const double tanHalfFov = std::tan(kFovDegrees * 0.5 * 3.14159265358979323846 / 180.0);
  render::PathTracerSettings settings;
  settings.seed = 9;

  const auto pinhole = test::measureSpot(
      test::renderScene(*device, pointEmitter(0.0f, 1.0f), kSize, kSize, kSpp, settings));
  INFO("pinhole: centroid " << pinhole.cx << "," << pinhole.cy << ", mean square "
                            << pinhole.meanSquare);
  CHECK(pinhole.meanSquare < 0.6);  // within the 2 x 2 pixels about the centre

  for (float focus : {2.0f, 8.0f}) {
    const float aperture = 0.2f;
    const double radius = aperture * std::abs(kEmitterDistance - focus) /
                          (kEmitterDistance * focus * tanHalfFov) * (kSize / 2.0);
    INFO("focus " << focus << " m");
    checkDisk(
        test::renderScene(*device, pointEmitter(aperture, focus), kSize, kSize, kSpp, settings),
        pinhole, radius);
  }

  // Focused on the emitter, the lens changes nothing but noise.
  const auto focused = test::measureSpot(test::renderScene(
      *device, pointEmitter(0.2f, float(kEmitterDistance)), kSize, kSize, kSpp, settings));
  INFO("in focus: mean square " << focused.meanSquare);
  CHECK(std::abs(focused.meanSquare - pinhole.meanSquare) < 0.05);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// Through an orthographic camera a film point's ray leaves the film plane
// along forward and meets the plane in focus at z_f; the lens moves its
// origin by l (|l| <= A) and aims it at that point, so at depth z_o it is
// off by l (1 - z_o / z_f): a point is a disk of radius A |1 - z_o / z_f|
// in world units on the film, whatever the depths' scale (0.1 m and
// 0.05 m here: 6.4 and 3.2 px of a view 1 m tall on 64 px). Within half a
// pixel, as above: a perspective formula (A |z_o - z_f| / z_o) would give
// 3.2 and 6.4 px, swapped.
TEST_CASE("depth of field: an orthographic camera's circle of confusion is A |1 - z/z_focus|",
          "[render][gpu][camera]") {
  auto device = test::makeTestDevice();
  constexpr double kViewHeight = 1.0;  // metres on 64 px
  auto orthographic = [&](float aperture, float focus) {
    scene::Scene s = pointEmitter(aperture, focus);
    s.camera.orthographicHeight = float(kViewHeight);
    return s;
  };
  render::PathTracerSettings settings;
  settings.seed = 10;
  const auto pinhole = test::measureSpot(
      test::renderScene(*device, orthographic(0.0f, 1.0f), kSize, kSize, kSpp, settings));
  for (float focus : {2.0f, 8.0f}) {
    const float aperture = 0.1f;
    const double radius =
        aperture * std::abs(1.0 - kEmitterDistance / focus) * (kSize / kViewHeight);
    INFO("focus " << focus << " m");
    checkDisk(
        test::renderScene(*device, orthographic(aperture, focus), kSize, kSize, kSpp, settings),
        pinhole, radius);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// With six blades the circle of confusion is a regular hexagon inscribed in
// the round one: corners where the lens's right axis points (the image's x
// axis; point-symmetric, so the image's inversion changes nothing), flat
// sides across the image's y axis, at cos(30 deg) = 0.87 of the radius. The
// light between 0.91 and 1.0 of the radius lies in the corner directions
// (within 10 degrees of the x axis) and not in the side directions (within
// 10 degrees of the y axis, where the hexagon ends by 0.88), where a round
// aperture has it in both.
TEST_CASE("depth of field: six aperture blades make a hexagonal circle of confusion",
          "[render][gpu][camera]") {
  auto device = test::makeTestDevice();
  const double tanHalfFov = std::tan(kFovDegrees * 0.5 * 3.14159265358979323846 / 180.0);
  const float aperture = 0.8f, focus = 2.0f;
  const double radius = aperture * std::abs(kEmitterDistance - focus) /
                        (kEmitterDistance * focus * tanHalfFov) * (kSize / 2.0);  // 17.6 px
  render::PathTracerSettings settings;
  settings.seed = 21;
  double cornerToSide[2];
  for (uint32_t blades : {0u, 6u}) {
    scene::Scene s = pointEmitter(aperture, focus);
    s.camera.apertureBlades = blades;
    // 4096 spp: about 150 samples land in each direction's part of the ring.
    const auto img = test::renderScene(*device, s, kSize, kSize, 4 * kSpp, settings);
    REQUIRE(image::countNonFinite(img) == 0);
    const test::Spot spot = test::measureSpot(img);
    double corner = 0, side = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const double dx = x + 0.5 - spot.cx, dy = y + 0.5 - spot.cy;
        const double r = std::sqrt(dx * dx + dy * dy) / radius;
        if (r < 0.91 || r > 1.0) continue;
        const double angle =
            std::atan2(std::abs(dy), std::abs(dx)) * 180.0 / 3.14159265358979323846;
        if (angle < 10.0) corner += img.pixel(x, y)[0];
        if (angle > 80.0) side += img.pixel(x, y)[0];
      }
    INFO(blades << " blades: outer ring light in the corner directions " << corner << ", sides "
                << side);
    REQUIRE(corner > 0.0);
    cornerToSide[blades == 0 ? 0 : 1] = side / corner;
  }
  INFO("side / corner light: round " << cornerToSide[0] << ", six blades " << cornerToSide[1]);
  // Round: the same ring either way (8 % noise each).
  CHECK(std::abs(cornerToSide[0] - 1.0) < 0.35);
  // Hexagon: the sides' ring lies outside it but for the emitter's own
  // 1.1 px and the pixels' blurring the edge.
  CHECK(cornerToSide[1] < 0.25);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("depth of field: a negative aperture or a lens without focus is refused", "[camera]") {
  scene::Camera c;
  c.apertureRadius = -0.1f;
  REQUIRE_THROWS_WITH(scene::validateCamera(c), ContainsSubstring("aperture radius -0.1"));
  c.apertureRadius = 0.1f;
  c.focusDistance = 0.0f;
  REQUIRE_THROWS_WITH(scene::validateCamera(c), ContainsSubstring("focus distance 0"));
  c.apertureRadius = 0.0f;  // a pinhole needs no focus
  REQUIRE_NOTHROW(scene::validateCamera(c));
  c.apertureBlades = 2;
  REQUIRE_THROWS_WITH(scene::validateCamera(c), ContainsSubstring("2 aperture blades"));
  // f/2 at a 39.6 degree field of view (a 35 mm camera's 33 mm lens): 8.3 mm.
  CHECK(std::abs(scene::apertureRadiusForFNumber(2.0f, 39.6f) - 0.0083f) < 0.0001f);
}
