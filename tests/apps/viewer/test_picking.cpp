// Focus-on-click picking through the renderer's probe rays (apps/viewer/picking.h).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include "picking.h"
#include "render/path_tracer.h"
#include "test_device.h"
#include "scene/scene_loader.h"

using namespace penumbra;
using Catch::Approx;

TEST_CASE("picking: the camera ray follows the shading core's pinhole model", "[viewer]") {
  scene::Camera camera;
  camera.position = {0, 0, 0};
  camera.forward = {0, 0, 1};
  camera.up = {0, 1, 0};
  camera.verticalFovDegrees = 90.0f;  // tan(45 deg) = 1
  // The image centre looks straight ahead.
  const auto centre = viewer::cameraRay(camera, 200, 100, {100, 50});
  CHECK(centre.direction.z == Approx(1.0f));
  // The top edge's centre is 45 degrees up.
  const auto top = viewer::cameraRay(camera, 200, 100, {100, 0});
  CHECK(top.direction.y == Approx(std::sqrt(0.5f)));
  CHECK(top.direction.z == Approx(std::sqrt(0.5f)));
  // The left edge: x = -aspect (2) in film units along right = forward x up = -x.
  const auto left = viewer::cameraRay(camera, 200, 100, {0, 50});
  CHECK(left.direction.x / left.direction.z == Approx(2.0f));
}

TEST_CASE("picking: the Cornell box's centre ray hits the tall block's front face", "[viewer][gpu]") {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box");
  render::PathTracer tracer(*device, scene, 8, 8);
  const auto ray = viewer::cameraRay(scene.camera, 64, 64, {32, 32});
  const auto hit = viewer::pick(tracer, scene, ray);
  REQUIRE(hit.has_value());
  // The camera is at (278, 273, -800) mm looking down +z. The tall block's
  // front face runs from (423, 0, 247) to (265, 0, 296) mm; at x = 278 it is
  // at z = 247 + (278 - 423) * (296 - 247) / (265 - 423) = 291.968 mm.
  CHECK(hit->position.z == Approx(0.291968f).margin(1e-5));
  CHECK(hit->distance == Approx(1.091968f).margin(1e-5));
  CHECK(scene.materials[hit->material].name == "white");
  CHECK(hit->object == "tall block");
  // Looking away from the box: nothing.
  viewer::Ray away{scene.camera.position, {0, 0, -1}};
  CHECK_FALSE(viewer::pick(tracer, scene, away).has_value());
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("picking: implicit surfaces are picked as they are drawn", "[viewer][gpu]") {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box-whitted");
  render::PathTracer tracer(*device, scene, 8, 8);
  // The glass sphere: radius 100 mm about (175, 100, 170) mm. A ray from
  // straight above its centre meets it at the top, y = 200 mm.
  const viewer::Ray down{{0.175f, 0.5f, 0.170f}, {0, -1, 0}};
  const auto hit = viewer::pick(tracer, scene, down);
  REQUIRE(hit.has_value());
  CHECK(hit->object == "glass sphere");
  CHECK(scene.materials[hit->material].name == "glass");
  CHECK(hit->distance == Approx(0.3f).margin(1e-5));
  CHECK(hit->position.y == Approx(0.2f).margin(1e-5));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
