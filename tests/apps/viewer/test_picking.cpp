// Focus-on-click picking on the CPU (apps/viewer/picking.h).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include "picking.h"
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

TEST_CASE("picking: the Cornell box's centre ray hits the tall block's front face", "[viewer]") {
  const auto scene = scene::loadScene("cornell-box");
  const auto ray = viewer::cameraRay(scene.camera, 64, 64, {32, 32});
  const auto hit = viewer::pick(scene, ray);
  REQUIRE(hit.has_value());
  // The camera is at (278, 273, -800) mm looking down +z. The tall block's
  // front face runs from (423, 0, 247) to (265, 0, 296) mm; at x = 278 it is
  // at z = 247 + (278 - 423) * (296 - 247) / (265 - 423) = 291.968 mm.
  CHECK(hit->position.z == Approx(0.291968f).margin(1e-5));
  CHECK(hit->distance == Approx(1.091968f).margin(1e-5));
  CHECK(scene.materials[hit->material].name == "white");
  CHECK(scene.meshes[scene.instances[hit->instance].mesh].name == "tall block");
  // Looking away from the box: nothing.
  viewer::Ray away{scene.camera.position, {0, 0, -1}};
  CHECK_FALSE(viewer::pick(scene, away).has_value());
}
