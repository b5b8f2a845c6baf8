// The orthographic camera (scene::Camera::orthographicHeight): parallel rays
// from a film of the camera's height, so a square keeps its size and place
// in the image at any distance, and nothing behind the film is seen.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include "effects.h"
#include "render_test_utils.h"

using namespace penumbra;
using Catch::Approx;

namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;
constexpr float kViewHeight = 2.0f;  // metres: one pixel is 2/48 m
constexpr float kHalfSide = 0.3f;    // the square: 14.4 px a side
constexpr float kCentreX = 0.4f, kCentreY = -0.2f;

// An orthographic camera at the origin looking along +z at a square emitter
// of radiance 1 at `distance` (facing it), on black.
scene::Scene squareAt(float distance) {
  scene::Scene s;
  s.name = "square";
  s.camera.forward = glm::vec3(0, 0, 1);
  s.camera.up = glm::vec3(0, 1, 0);
  s.camera.orthographicHeight = kViewHeight;
  s.materials.push_back(scene::Material::lambert("light", glm::vec3(0.0f), glm::vec3(1.0f)));
  scene::Mesh quad;
  quad.name = "emitter";
  const float h = kHalfSide, x = kCentreX, y = kCentreY, z = distance;
  quad.positions = {{x - h, y - h, z}, {x - h, y + h, z}, {x + h, y + h, z}, {x + h, y - h, z}};
  quad.indices = {0, 1, 2, 0, 2, 3};  // facing -z
  s.meshes.push_back(quad);
  s.instances.push_back({0, glm::dmat4(1.0)});
  return s;
}

}  // namespace

// The square is 0.6 m / (2 m / 48 px) = 14.4 px a side, 207.36 px^2. The
// camera's right is forward x up = -x, so its centre, 0.4 m along +x and
// 0.2 m down, is 9.6 px left and 4.8 px below the image's centre (32, 24):
// at (22.4, 28.8) px. 64 jittered samples leave about 0.5 px^2 of noise on
// the area (its 58 edge pixels); 1 % lets through a film 0.5 % too tall or
// short, and 0.05 px a film point off by 2 mm.
TEST_CASE("orthographic camera: a square keeps its size and place at any distance",
          "[render][gpu][camera]") {
  auto device = test::makeTestDevice();
  for (float distance : {1.0f, 30.0f}) {
    INFO("square " << distance << " m ahead");
    const image::Image img = test::renderScene(*device, squareAt(distance), kWidth, kHeight, 64);
    REQUIRE(image::countNonFinite(img) == 0);
    const test::Spot c = test::measureSpot(img);
    CHECK(c.flux == Approx(207.36).epsilon(0.01));
    CHECK(c.cx == Approx(22.4).margin(0.05));
    CHECK(c.cy == Approx(28.8).margin(0.05));
  }
  // Behind the film plane: not seen.
  const image::Image behind = test::renderScene(*device, squareAt(-1.0f), kWidth, kHeight, 16);
  CHECK(test::measureSpot(behind).flux == 0.0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// The projection is a variant bit (PT_EFFECT_ORTHOGRAPHIC), so a perspective
// pipeline has no orthographic code: switching the camera must rebuild the
// pipeline, and render what a tracer built for that camera renders (same
// seed, so bit for bit).
TEST_CASE("orthographic camera: switching projection rebuilds the pipeline for it",
          "[render][gpu][camera]") {
  auto device = test::makeTestDevice();
  scene::Scene scene = squareAt(5.0f);
  const scene::Camera parallel = scene.camera;
  scene.camera.orthographicHeight = 0.0f;
  scene.camera.verticalFovDegrees = 30.0f;
  const scene::Camera perspective = scene.camera;

  render::PathTracer tracer(*device, scene, kWidth, kHeight);
  CHECK(tracer.pipelineEffects() == PT_EFFECT_AREA_LIGHTS);
  tracer.setCamera(parallel);
  CHECK(tracer.pipelineEffects() == (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_ORTHOGRAPHIC));
  render::PathTracerSettings settings;
  settings.seed = 11;
  tracer.renderFrame(settings, 4);
  render::PathTracer built(*device, scene, kWidth, kHeight, {}, parallel);
  CHECK(built.pipelineEffects() == (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_ORTHOGRAPHIC));
  built.renderFrame(settings, 4);
  const image::Image switched = tracer.readback();
  CHECK(switched.rgba == built.readback().rgba);
  // The square seen orthographically: 207.36 px^2 within its noise (see above).
  CHECK(test::measureSpot(switched).flux == Approx(207.36).epsilon(0.05));

  tracer.setCamera(perspective);
  CHECK(tracer.pipelineEffects() == PT_EFFECT_AREA_LIGHTS);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
