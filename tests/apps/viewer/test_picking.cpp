// Focus-on-click picking through the renderer's probe rays (apps/viewer/picking.h).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cstring>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/scene/scene_loader.h"
#include "picking.h"
#include "shaders/compute_harness.h"
#include "test_device.h"

using namespace penumbra;
using Catch::Approx;

TEST_CASE("picking: the camera ray is the one the shading core traces",
          "[viewer][gpu][spirv-only]") {
  // A tilted camera and a wide image, so that every term of the model counts.
  scene::Camera camera;
  camera.position = {1.0, 2.0, -3.0};
  camera.forward = {0.3f, -0.2f, 1.0f};
  camera.up = {0.1f, 1.0f, 0.0f};
  camera.verticalFovDegrees = 50.0f;
  const uint32_t width = 320, height = 120;
  std::vector<glm::vec2> film;
  for (float y : {0.0f, 0.5f, 37.25f, 60.0f, 119.5f, 120.0f})
    for (float x : {0.0f, 0.5f, 101.75f, 160.0f, 319.5f, 320.0f}) film.push_back({x, y});

  // What the ray generation shaders compute from the frame constants the path
  // tracer makes of this camera (shaders/shared/camera.hlsli).
  auto device = test::makeTestDevice();
  gpu::FrameConstants constants{};
  constants.camera = render::cameraData(camera, width, height, camera.position);
  constants.width = width;
  constants.height = height;
  constants.samplesThisFrame = 1;
  test::ComputeHarness harness(*device, "camera_harness.comp");
  const uint32_t count = uint32_t(film.size());
  const auto bytes =
      harness.run(&count, sizeof(count),
                  {{&constants, sizeof(constants)}, {film.data(), film.size() * sizeof(glm::vec2)}},
                  film.size() * sizeof(glm::vec4), 1);
  std::vector<glm::vec4> shader(film.size());
  std::memcpy(shader.data(), bytes.data(), bytes.size());

  for (size_t i = 0; i < film.size(); ++i) {
    INFO("film (" << film[i].x << ", " << film[i].y << ")");
    const viewer::Ray ray = viewer::cameraRay(camera, width, height, film[i]);
    CHECK(glm::dvec3(ray.origin) == camera.position);
    // float arithmetic on the GPU against the model's double: 1e-5 rad lets
    // through a picked point 10 um off per metre, not a wrong basis or a
    // half-pixel shift (3.6e-3 rad here).
    CHECK(glm::length(ray.direction - glm::vec3(shader[i])) < 1e-5f);
  }
  // The centre looks along forward; the top edge is half the field of view up.
  const viewer::Ray centre = viewer::cameraRay(camera, width, height, {160, 60});
  CHECK(glm::length(centre.direction - glm::normalize(camera.forward)) < 1e-6f);
  const viewer::Ray top = viewer::cameraRay(camera, width, height, {160, 0});
  CHECK(std::acos(glm::dot(top.direction, centre.direction)) == Approx(glm::radians(25.0f)));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("picking: the Cornell box's centre ray hits the tall block's front face",
          "[viewer][gpu]") {
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
