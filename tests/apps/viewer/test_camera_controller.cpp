// The viewer's camera controller, without a window (apps/viewer/camera_controller.h).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include "camera_controller.h"

using namespace penumbra;
using Catch::Approx;

namespace {
// Looking down +z with +y up: the path tracer's right vector is
// forward x up = (0,0,1) x (0,1,0) = (-1,0,0).
scene::Camera homeCamera() {
  scene::Camera c;
  c.position = {1.0f, 2.0f, 3.0f};
  c.forward = {0.0f, 0.0f, 1.0f};
  c.up = {0.0f, 1.0f, 0.0f};
  c.verticalFovDegrees = 40.0f;
  return c;
}
}  // namespace

TEST_CASE("camera controller: no input leaves the scene camera bit for bit", "[viewer]") {
  scene::Camera home = homeCamera();
  home.forward = {0.1f, -0.2f, 0.97f};  // not normalised: must come back unchanged all the same
  viewer::CameraController controller(home, 2.0f);
  REQUIRE_FALSE(controller.update({}, 0.016f));
  const auto& c = controller.camera();
  REQUIRE(c.position == home.position);
  REQUIRE(c.forward == home.forward);
  REQUIRE(c.up == home.up);
  REQUIRE(c.verticalFovDegrees == home.verticalFovDegrees);
}

TEST_CASE("camera controller: WASD/QE move by speed x time along the camera axes", "[viewer]") {
  viewer::CameraController controller(homeCamera(), 2.0f);
  viewer::CameraInput forward;
  forward.move = {0, 0, 1};  // W
  REQUIRE(controller.update(forward, 0.5f));
  // 2 m/s for 0.5 s along +z.
  CHECK(controller.camera().position.x == Approx(1.0f));
  CHECK(controller.camera().position.z == Approx(4.0f));

  viewer::CameraInput strafe;
  strafe.move = {1, 1, 0};  // D and E
  controller.update(strafe, 0.25f);
  // Right is -x (see homeCamera), up is +y; 0.5 m each.
  CHECK(controller.camera().position.x == Approx(0.5f));
  CHECK(controller.camera().position.y == Approx(2.5f));
  CHECK(controller.camera().position.z == Approx(4.0f));
}

TEST_CASE("camera controller: dragging turns, elevation stops short of the poles", "[viewer]") {
  viewer::CameraController controller(homeCamera(), 1.0f);
  viewer::CameraInput drag;
  // 450 px right at 0.2 deg/px = 90 degrees to the right: forward becomes the old right.
  drag.turn = {450.0f, 0.0f};
  REQUIRE(controller.update(drag, 0.016f));
  CHECK(controller.camera().forward.x == Approx(-1.0f).margin(1e-6));
  CHECK(controller.camera().forward.z == Approx(0.0f).margin(1e-6));

  // Dragging the mouse up (negative y) looks up; far beyond 90 degrees it stops at 89.
  drag.turn = {0.0f, -10000.0f};
  controller.update(drag, 0.016f);
  const glm::vec3 f = controller.camera().forward;
  CHECK(glm::length(f) == Approx(1.0f));
  CHECK(f.y == Approx(std::sin(glm::radians(89.0f))));
  CHECK(controller.camera().up == glm::vec3(0, 1, 0));

  controller.reset();
  CHECK(controller.camera().forward == homeCamera().forward);
  CHECK(controller.camera().position == homeCamera().position);
}

TEST_CASE("camera controller: the wheel scales the speed by 1.25 per notch", "[viewer]") {
  viewer::CameraController controller(homeCamera(), 1.0f);
  viewer::CameraInput scroll;
  scroll.scrollSteps = 2;
  // The speed alone is no camera change: the accumulation keeps going.
  REQUIRE_FALSE(controller.update(scroll, 0.016f));
  CHECK(controller.speed() == Approx(1.5625f));
  scroll.scrollSteps = -2;
  controller.update(scroll, 0.016f);
  CHECK(controller.speed() == Approx(1.0f));
}

TEST_CASE("camera controller: on an orthographic camera the wheel zooms, 1.25 per notch",
          "[viewer]") {
  // Moving along a parallel view does not change it; the height it shows does.
  scene::Camera home = homeCamera();
  home.orthographicHeight = 2.0f;
  viewer::CameraController controller(home, 1.0f);
  viewer::CameraInput scroll;
  scroll.scrollSteps = 2;  // towards: closer in
  REQUIRE(controller.update(scroll, 0.016f));
  CHECK(controller.camera().orthographicHeight == Approx(2.0f / 1.5625f));
  CHECK(controller.camera().position == home.position);
  CHECK(controller.speed() == 1.0f);
  scroll.scrollSteps = -3;
  REQUIRE(controller.update(scroll, 0.016f));
  CHECK(controller.camera().orthographicHeight == Approx(2.0f * 1.25f));
  // Far out or in it stops at the heights a camera may hold, and stays
  // orthographic (a height of 0 would mean perspective).
  scroll.scrollSteps = -1000;
  controller.update(scroll, 0.016f);
  CHECK(controller.camera().orthographicHeight == viewer::CameraController::kMaxOrthographicHeight);
  scroll.scrollSteps = 1e30f;
  controller.update(scroll, 0.016f);
  CHECK(controller.camera().orthographicHeight == viewer::CameraController::kMinOrthographicHeight);
  CHECK(controller.camera().orthographic());
  controller.reset();
  CHECK(controller.camera().orthographicHeight == 2.0f);
}

TEST_CASE("camera controller: focusOn faces the target and focuses on it; position and up stay",
          "[viewer]") {
  viewer::CameraController controller(homeCamera(), 1.0f);
  controller.focusOn({4.0f, 2.0f, 3.0f});  // 3 m along +x from (1, 2, 3)
  CHECK(controller.camera().forward == glm::vec3(1, 0, 0));
  CHECK(controller.camera().position == homeCamera().position);
  CHECK(controller.camera().up == homeCamera().up);
  CHECK(controller.camera().focusDistance == Approx(3.0f));
  // Straight up has no right vector: the direction stays, and a target in
  // the camera's own plane leaves the focus where it was.
  controller.focusOn({1.0f, 10.0f, 3.0f});
  CHECK(controller.camera().forward == glm::vec3(1, 0, 0));
  CHECK(controller.camera().focusDistance == Approx(3.0f));
}

TEST_CASE("camera controller: an orthographic focusOn slides to centre the target, direction kept",
          "[viewer]") {
  scene::Camera home = homeCamera();
  home.orthographicHeight = 2.0f;
  viewer::CameraController controller(home, 1.0f);
  // 0.5 m to its right (forward x up is -x), 0.25 m down, 4 m ahead.
  controller.focusOn({0.5f, 1.75f, 7.0f});
  CHECK(controller.camera().forward == home.forward);
  CHECK(controller.camera().up == home.up);
  CHECK(controller.camera().position.x == Approx(0.5));
  CHECK(controller.camera().position.y == Approx(1.75));
  CHECK(controller.camera().position.z == Approx(3.0));
  CHECK(controller.camera().focusDistance == Approx(4.0f));
  CHECK(controller.camera().orthographicHeight == 2.0f);
}
