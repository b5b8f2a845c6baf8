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

namespace {

// What the ray generation shaders compute from the frame constants the path
// tracer makes of this camera (shaders/shared/camera.hlsli), with the render
// origin at the camera's position: for each film position its ray's origin
// (relative to that) and direction.
std::vector<glm::vec4> shaderCameraRays(rhi::IDevice& device, const scene::Camera& camera,
                                        uint32_t width, uint32_t height,
                                        const std::vector<glm::vec2>& film) {
  gpu::FrameConstants constants{};
  constants.camera = render::cameraData(camera, width, height, camera.position);
  constants.sceneFlags = render::cameraSceneFlags(camera);
  constants.width = width;
  constants.height = height;
  constants.samplesThisFrame = 1;
  test::ComputeHarness harness(device, "camera_harness.comp");
  const uint32_t count = uint32_t(film.size());
  const auto bytes =
      harness.run(&count, sizeof(count),
                  {{&constants, sizeof(constants)}, {film.data(), film.size() * sizeof(glm::vec2)}},
                  2 * film.size() * sizeof(glm::vec4), 1);
  std::vector<glm::vec4> rays(2 * film.size());
  std::memcpy(rays.data(), bytes.data(), bytes.size());
  return rays;
}

}  // namespace

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

  auto device = test::makeTestDevice();
  scene::Camera orthographic = camera;
  orthographic.orthographicHeight = 3.0f;
  for (const scene::Camera& c : {camera, orthographic}) {
    INFO((c.orthographic() ? "orthographic" : "perspective"));
    const std::vector<glm::vec4> shader = shaderCameraRays(*device, c, width, height, film);
    for (size_t i = 0; i < film.size(); ++i) {
      INFO("film (" << film[i].x << ", " << film[i].y << ")");
      const viewer::Ray ray = viewer::cameraRay(c, width, height, film[i]);
      // float arithmetic on the GPU against the model's double: 1e-5 rad
      // lets through a picked point 10 um off per metre, not a wrong basis
      // or a half-pixel shift (3.6e-3 rad here); 1e-5 m of an orthographic
      // film 3 m tall, not a shift of 1 % of a pixel.
      CHECK(glm::length(ray.origin - glm::vec3(c.position) - glm::vec3(shader[2 * i])) < 1e-5f);
      CHECK(glm::length(ray.direction - glm::vec3(shader[2 * i + 1])) < 1e-5f);
    }
  }
  // The centre looks along forward; the top edge is half the field of view up.
  const viewer::Ray centre = viewer::cameraRay(camera, width, height, {160, 60});
  CHECK(glm::dvec3(centre.origin) == camera.position);
  CHECK(glm::length(centre.direction - glm::normalize(camera.forward)) < 1e-6f);
  const viewer::Ray top = viewer::cameraRay(camera, width, height, {160, 0});
  CHECK(glm::dvec3(top.origin) == camera.position);
  CHECK(std::acos(glm::dot(top.direction, centre.direction)) == Approx(glm::radians(25.0f)));
  // Orthographic: the top edge's ray is parallel to the centre's, half the
  // height (1.5 m) above it.
  const viewer::Ray orthoCentre = viewer::cameraRay(orthographic, width, height, {160, 60});
  const viewer::Ray orthoTop = viewer::cameraRay(orthographic, width, height, {160, 0});
  CHECK(glm::length(orthoTop.direction - orthoCentre.direction) < 1e-6f);
  CHECK(glm::length(orthoTop.origin - orthoCentre.origin) == Approx(1.5f));
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
