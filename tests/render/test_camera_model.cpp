// The camera model (engine/penumbra/render/camera_model.h): the field of view a scene
// camera keeps at image aspects other than the one it was set up for.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "penumbra/render/camera_model.h"
#include "penumbra/scene/camera_placement.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using Catch::Approx;

namespace {

// The angle between the camera's forward axis and the pinhole ray through a
// film position, in degrees.
double angleFromAxis(const render::CameraModel& m, glm::dvec2 film) {
  const glm::dvec3 d = render::cameraRay(m, film).direction;
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
  const glm::dvec3 point = window.position + 5.0 * render::cameraRay(window, {97, 611}).direction;
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

TEST_CASE("camera model: an orthographic camera's rays are parallel, from a film of its height",
          "[camera]") {
  // Tilted, so that every basis vector counts; 2 m tall, set up for a 3:2 frame.
  scene::Camera c;
  c.position = {1.0, -2.0, 0.5};
  c.forward = {0.0f, -0.6f, 0.8f};
  c.up = {0.0f, 0.8f, 0.6f};
  c.orthographicHeight = 2.0f;
  c.aspectRatio = 1.5f;
  const glm::dvec3 forward(0.0, -0.6, 0.8), up(0.0, 0.8, 0.6), right(-1.0, 0.0, 0.0);
  REQUIRE(glm::length(glm::cross(forward, up) - right) < 1e-12);

  // A 3:2 image: 2 m tall and 3 m wide, one pixel is 2/300 m.
  const render::CameraModel m = render::cameraModel(c, 450, 300);
  REQUIRE(m.orthographic);
  for (glm::dvec2 film :
       {glm::dvec2(0, 0), glm::dvec2(225, 150), glm::dvec2(450, 300), glm::dvec2(97.5, 211.25)}) {
    INFO("film (" << film.x << ", " << film.y << ")");
    const render::CameraRay ray = render::cameraRay(m, film);
    CHECK(glm::length(ray.direction - forward) < 1e-7);
    const glm::dvec3 expected = c.position + (film.x - 225.0) * (2.0 / 300.0) * right -
                                (film.y - 150.0) * (2.0 / 300.0) * up;
    CHECK(glm::length(ray.origin - expected) < 1e-6);
    // The projection inverts the ray at any distance along it.
    for (double t : {0.5, 40.0}) {
      const glm::dvec2 back = render::projectToFilm(m, ray.origin + t * ray.direction);
      CHECK(back.x == Approx(film.x).margin(1e-6));
      CHECK(back.y == Approx(film.y).margin(1e-6));
    }
  }
  // Narrower than its frame: the 3 m width holds, the height grows.
  const render::CameraModel square = render::cameraModel(c, 300, 300);
  CHECK(glm::length(render::cameraRay(square, {0, 150}).origin - (c.position - 1.5 * right)) <
        1e-6);
  CHECK(glm::length(render::cameraRay(square, {150, 0}).origin - (c.position + 1.5 * up)) < 1e-6);
  // Wider: the 2 m height holds.
  const render::CameraModel wide = render::cameraModel(c, 600, 300);
  CHECK(glm::length(render::cameraRay(wide, {300, 0}).origin - (c.position + 1.0 * up)) < 1e-6);
}

TEST_CASE("camera model: an orthographic height must lie in [0, 1e9]", "[camera]") {
  scene::Camera c;
  c.orthographicHeight = -1.0f;
  REQUIRE_THROWS_WITH(scene::validateCamera(c),
                      Catch::Matchers::ContainsSubstring("orthographic height -1 must be finite"));
  c.orthographicHeight = INFINITY;
  REQUIRE_THROWS_AS(scene::validateCamera(c), Error);
  c.orthographicHeight = 2e9f;
  REQUIRE_THROWS_WITH(scene::validateCamera(c), Catch::Matchers::ContainsSubstring("at most 1e9"));
  c.orthographicHeight = 0.0f;
  REQUIRE_NOTHROW(scene::validateCamera(c));
  REQUIRE_FALSE(c.orthographic());
}

TEST_CASE("camera model: cameras share a film only with the same projection and size", "[camera]") {
  scene::Camera a;
  scene::Camera moved = a;
  moved.position = {3.0, 1.0, 2.0};
  moved.forward = {1.0f, 0.0f, 0.0f};
  CHECK(scene::sameFilm(a, moved));
  scene::Camera wider = a;
  wider.verticalFovDegrees = 50.0f;
  CHECK_FALSE(scene::sameFilm(a, wider));
  scene::Camera ortho = a;
  ortho.orthographicHeight = 2.0f;
  CHECK_FALSE(scene::sameFilm(a, ortho));
  // An orthographic camera's field of view is not used.
  scene::Camera orthoWider = ortho;
  orthoWider.verticalFovDegrees = 50.0f;
  CHECK(scene::sameFilm(ortho, orthoWider));
  scene::Camera taller = ortho;
  taller.orthographicHeight = 3.0f;
  CHECK_FALSE(scene::sameFilm(ortho, taller));
  scene::Camera framed = a;
  framed.aspectRatio = 1.5f;
  CHECK_FALSE(scene::sameFilm(a, framed));
}

TEST_CASE(
    "camera model: the orthographic height at a distance shows that plane as the "
    "perspective view does",
    "[camera]") {
  scene::Camera perspective;
  perspective.forward = {0.0f, -0.6f, 0.8f};
  perspective.up = {0.0f, 0.8f, 0.6f};
  perspective.verticalFovDegrees = 35.0f;
  perspective.aspectRatio = 1.5f;
  const double distance = 3.25;
  scene::Camera orthographic = perspective;
  orthographic.orthographicHeight = scene::orthographicHeightAt(perspective, distance);
  CHECK(orthographic.orthographicHeight ==
        Approx(2.0 * distance * std::tan(glm::radians(17.5))).epsilon(1e-6));
  // Points of the plane `distance` ahead land on the same film positions,
  // whatever the image's shape; nearer ones do not.
  for (auto [width, height] : {std::pair{300u, 200u}, std::pair{200u, 300u}}) {
    const render::CameraModel p = render::cameraModel(perspective, width, height);
    const render::CameraModel o = render::cameraModel(orthographic, width, height);
    const glm::dvec3 onPlane = p.position + distance * p.forward + 0.7 * p.right - 0.4 * p.up;
    const glm::dvec2 a = render::projectToFilm(p, onPlane), b = render::projectToFilm(o, onPlane);
    CHECK(glm::length(a - b) < 1e-4);
    const glm::dvec3 nearer = onPlane - 1.0 * p.forward;
    CHECK(glm::length(render::projectToFilm(p, nearer) - render::projectToFilm(o, nearer)) > 1.0);
  }
}
