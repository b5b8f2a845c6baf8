// The view of a scene without cameras and the view given on the command line
// (scene/camera_placement.h), checked by geometry computed here.
#include <algorithm>
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>

#include "penumbra/scene/camera_placement.h"

using namespace penumbra;
using Catch::Approx;
using Catch::Matchers::ContainsSubstring;

namespace {

// A scene of one box instance spanning lo..hi (its eight corners).
scene::Scene boxScene(glm::dvec3 lo, glm::dvec3 hi) {
  scene::Scene s;
  s.materials.push_back(scene::Material::lambert("grey", glm::vec3(0.5f)));
  scene::Mesh m;
  for (int i = 0; i < 8; ++i)
    m.positions.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
  m.indices = {0, 1, 3};
  s.meshes.push_back(m);
  s.instances.push_back({0, glm::dmat4(1.0)});
  return s;
}

// The angle in degrees between the camera's forward and the direction to p.
double offAxisDegrees(const scene::Camera& c, glm::dvec3 p) {
  const glm::dvec3 d = glm::normalize(p - c.position);
  return glm::degrees(std::acos(std::clamp(glm::dot(d, glm::dvec3(c.forward)), -1.0, 1.0)));
}

}  // namespace

TEST_CASE("camera framing: the bounds fit the frame, seen from a three-quarter view above",
          "[scene][camera]") {
  const glm::dvec3 lo(10, -2, 3), hi(14, 1, 4);
  const scene::Scene s = boxScene(lo, hi);
  const scene::Camera c = scene::framingCamera(s);
  REQUIRE(c.aspectRatio == 1.0f);  // the fit below holds at any image shape
  // It looks at the centre of the bounds.
  const glm::dvec3 centre = 0.5 * (lo + hi);
  CHECK(offAxisDegrees(c, centre) < 1e-3);
  // From the front (+z), the right (+x) and above, 45 degrees round and 30 up.
  const glm::dvec3 back = glm::normalize(c.position - centre);
  CHECK(glm::degrees(std::asin(back.y)) == Approx(30.0).margin(1e-4));
  CHECK(glm::degrees(std::atan2(back.x, back.z)) == Approx(45.0).margin(1e-4));
  // Every corner lies within the half field of view of the axis (the
  // narrower of the vertical and horizontal ones at aspect 1), and the
  // farthest touches it: a fit, not a distant speck.
  double widest = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    widest = std::max(widest, offAxisDegrees(c, p));
  }
  CHECK(widest <= 22.5 + 1e-6);
  CHECK(widest > 0.6 * 22.5);

  // A flat model (the xz plane) is seen from 30 degrees above its plane, not
  // edge on as from the front.
  const scene::Camera flat = scene::framingCamera(boxScene({-1, 0, -1}, {1, 0, 1}));
  CHECK(std::abs(flat.forward.y) == Approx(0.5).margin(1e-5));
}

TEST_CASE(
    "camera placement: position, look-at, field of view and orthographic height over the scene's "
    "camera",
    "[scene][camera]") {
  scene::Scene s = boxScene({0, 0, 0}, {1, 1, 1});
  s.camera.position = {0, 0, 10};
  s.camera.forward = {0, 0, -1};
  s.camera.up = {0, 1, 0};
  s.camera.verticalFovDegrees = 40.0f;
  s.camera.aspectRatio = 1.5f;  // a glTF camera's frame

  // Nothing given: nothing changes.
  scene::Scene same = s;
  scene::placeCamera(same, {});
  CHECK(same.camera.position == s.camera.position);
  CHECK(same.camera.forward == s.camera.forward);

  // A position alone keeps the direction.
  scene::Scene moved = s;
  scene::placeCamera(moved, {.position = glm::dvec3(3, 4, 5)});
  CHECK(moved.camera.position == glm::dvec3(3, 4, 5));
  CHECK(moved.camera.forward == glm::vec3(0, 0, -1));

  // Position and look-at: forward is the unit direction between them; up kept.
  scene::Scene aimed = s;
  scene::placeCamera(aimed, {.position = glm::dvec3(4, 0, 3),
                             .lookAt = glm::dvec3(0, 0, 0),
                             .verticalFovDegrees = 60.0f});
  CHECK(glm::length(aimed.camera.forward - glm::vec3(-0.8f, 0.0f, -0.6f)) < 1e-6f);
  CHECK(aimed.camera.up == glm::vec3(0, 1, 0));
  CHECK(aimed.camera.verticalFovDegrees == 60.0f);
  CHECK(aimed.camera.aspectRatio == 0.0f);  // the vertical field of view at any image shape

  // Looking straight down: up cannot stay +y, and becomes +z.
  scene::Scene down = s;
  scene::placeCamera(down, {.position = glm::dvec3(0, 5, 0), .lookAt = glm::dvec3(0, 0, 0)});
  CHECK(glm::length(down.camera.forward - glm::vec3(0, -1, 0)) < 1e-6f);
  CHECK(down.camera.up == glm::vec3(0, 0, 1));
  scene::validateCamera(down.camera);

  // An orthographic height makes the camera orthographic, a field of view
  // perspective again; each holds at every image shape.
  scene::Scene ortho = s;
  scene::placeCamera(ortho, {.orthographicHeight = 3.0f});
  CHECK(ortho.camera.orthographic());
  CHECK(ortho.camera.orthographicHeight == 3.0f);
  CHECK(ortho.camera.aspectRatio == 0.0f);
  CHECK(ortho.camera.position == s.camera.position);
  scene::placeCamera(ortho, {.verticalFovDegrees = 30.0f});
  CHECK_FALSE(ortho.camera.orthographic());
  CHECK(ortho.camera.verticalFovDegrees == 30.0f);

  // Unusable placements are refused by name.
  CHECK_THROWS_WITH(
      scene::placeCamera(s, {.verticalFovDegrees = 30.0f, .orthographicHeight = 2.0f}),
      ContainsSubstring("give --fov (perspective) or --orthographic, not both"));
  CHECK_THROWS_WITH(scene::placeCamera(s, {.orthographicHeight = 0.0f}),
                    ContainsSubstring("--orthographic 0 must be finite and > 0"));
  CHECK_THROWS_WITH(scene::placeCamera(s, {.lookAt = glm::dvec3(0, 0, 10)}),
                    ContainsSubstring("--look-at (0, 0, 10) is the camera's position"));
  CHECK_THROWS_WITH(scene::placeCamera(s, {.verticalFovDegrees = 180.0f}),
                    ContainsSubstring("--fov 180 must lie in (0, 180)"));
  CHECK_THROWS_WITH(scene::placeCamera(s, {.position = glm::dvec3(NAN, 0, 0)}),
                    ContainsSubstring("--camera-position"));
  CHECK_THROWS_WITH(scene::placeCamera(s, {.name = "nope"}),
                    ContainsSubstring("no camera named 'nope'"));
}
