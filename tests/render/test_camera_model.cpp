// The camera model (engine/penumbra/render/camera_model.h): the field of view a scene
// camera keeps at image aspects other than the one it was set up for.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "penumbra/render/camera_model.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using Catch::Approx;

namespace {

// The angle between the camera's forward axis and the pinhole ray through a
// film position, in degrees.
double angleFromAxis(const render::CameraModel& m, glm::dvec2 film) {
  const glm::dvec3 d = render::cameraRayDirection(m, film);
  return glm::degrees(std::acos(glm::dot(d, m.forward)));
}

scene::Camera wideCamera() {
  scene::Camera c;
  c.forward = {0, 0, 1};
  c.verticalFovDegrees = 16.0f;
  c.aspectRatio = 3.5f;  // set up for a 1400x400 frame
  return c;
}

}  // namespace

TEST_CASE("camera model: an image narrower than the camera's frame keeps its horizontal field",
          "[camera]") {
  const scene::Camera c = wideCamera();
  // Half the frame's horizontal field: atan(3.5 tan 8 deg), worked by hand.
  const double halfHorizontal = glm::degrees(std::atan(3.5 * std::tan(glm::radians(8.0))));
  REQUIRE(halfHorizontal == Approx(26.19).margin(0.01));

  const render::CameraModel frame = render::cameraModel(c, 1400, 400);
  CHECK(angleFromAxis(frame, {1400, 200}) == Approx(halfHorizontal).epsilon(1e-9));
  CHECK(angleFromAxis(frame, {700, 0}) == Approx(8.0).epsilon(1e-9));

  // 16:9: the same horizontal field, more above and below.
  const render::CameraModel window = render::cameraModel(c, 1280, 720);
  CHECK(angleFromAxis(window, {1280, 360}) == Approx(halfHorizontal).epsilon(1e-9));
  const double halfVertical =
      glm::degrees(std::atan(3.5 * std::tan(glm::radians(8.0)) / (1280.0 / 720.0)));
  CHECK(angleFromAxis(window, {640, 0}) == Approx(halfVertical).epsilon(1e-9));

  // Wider than the frame: the vertical field holds, more at the sides.
  const render::CameraModel wider = render::cameraModel(c, 2000, 400);
  CHECK(angleFromAxis(wider, {1000, 0}) == Approx(8.0).epsilon(1e-9));

  // Without a frame aspect the vertical field holds at every aspect.
  scene::Camera plain = c;
  plain.aspectRatio = 0.0f;
  CHECK(angleFromAxis(render::cameraModel(plain, 1280, 720), {640, 0}) ==
        Approx(8.0).epsilon(1e-9));
  // The projection is the ray's inverse with the fitted field too.
  const glm::dvec3 point = window.position + 5.0 * render::cameraRayDirection(window, {97, 611});
  const glm::dvec2 film = render::projectToFilm(window, point);
  CHECK(film.x == Approx(97.0).epsilon(1e-9));
  CHECK(film.y == Approx(611.0).epsilon(1e-9));
}

TEST_CASE("camera model: material-test shows all seven spheres in a 16:9 window", "[camera]") {
  // scenes/material-test.json: seven spheres of radius 0.4 from x = 2.7 to
  // -2.7 at y = 0.4, z = 0 (the scene's data, not the code under test).
  const scene::Scene scene = scene::loadScene("material-test");
  for (auto [width, height] : {std::pair{1280u, 720u}, std::pair{1400u, 400u},
                               std::pair{800u, 800u}, std::pair{600u, 900u}}) {
    const render::CameraModel m = render::cameraModel(scene.camera, width, height);
    for (int i = 0; i < 7; ++i) {
      const double x = 2.7 - 5.4 * i / 6.0;
      for (double side : {-0.4, 0.4}) {
        const glm::dvec2 film = render::projectToFilm(m, {x + side, 0.4, 0.0});
        INFO(width << "x" << height << ", sphere " << i << ", side " << side);
        CHECK(film.x >= 0.0);
        CHECK(film.x <= double(width));
        CHECK(film.y >= 0.0);
        CHECK(film.y <= double(height));
      }
    }
  }
}

TEST_CASE("camera model: a camera's aspect ratio must be finite and >= 0", "[camera]") {
  scene::Camera c;
  c.aspectRatio = -1.0f;
  REQUIRE_THROWS_WITH(scene::validateCamera(c),
                      Catch::Matchers::ContainsSubstring("aspect ratio -1 must be finite"));
  c.aspectRatio = std::nanf("");
  REQUIRE_THROWS_AS(scene::validateCamera(c), Error);
  c.aspectRatio = 0.0f;
  REQUIRE_NOTHROW(scene::validateCamera(c));
}
