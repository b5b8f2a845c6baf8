// PathTracer changes after construction, as the viewer makes them: camera,
// materials, size. Each must give the image a new PathTracer built for the
// changed scene gives (same device, same seed). Tolerance 1e-5 per value,
// relative to 1 or the value: measured bit-identical on lavapipe; on the
// NVIDIA H200 a second pipeline in the same process differs in the last bits
// (6 % of values, by less than 1e-6), as a compiler contracting a * b + c
// differently would. A wrong camera, material or size differs by far more.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstring>
#include <string>

#include "effects.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"
#include "render_test_utils.h"

using namespace penumbra;

namespace {
constexpr uint32_t kSize = 32;
constexpr uint32_t kSpp = 4;

image::Image accumulate(render::PathTracer& tracer, uint32_t spp) {
  render::PathTracerSettings settings;
  settings.seed = 5;
  while (tracer.accumulatedSamples() < spp) tracer.renderFrame(settings, 2);
  return tracer.readback();
}

bool matches(const image::Image& a, const image::Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (size_t i = 0; i < a.rgba.size(); ++i)
    if (!(std::abs(a.rgba[i] - b.rgba[i]) <= 1e-5f * std::max(1.0f, std::abs(b.rgba[i])))) return false;
  return true;
}

// For the failure message: how many values differ, and by how much at most.
std::string differences(const image::Image& a, const image::Image& b) {
  if (a.rgba.size() != b.rgba.size()) return "sizes differ";
  size_t count = 0;
  float largest = 0.0f;
  for (size_t i = 0; i < a.rgba.size(); ++i)
    if (a.rgba[i] != b.rgba[i]) {
      ++count;
      largest = std::max(largest, std::abs(a.rgba[i] - b.rgba[i]));
    }
  return std::to_string(count) + " of " + std::to_string(a.rgba.size()) +
         " values differ, by up to " + std::to_string(double(largest) * 1e6) + "e-6";
}
}  // namespace

TEST_CASE("path tracer: setCamera renders what a scene with that camera renders", "[render][gpu]") {
  auto device = test::makeTestDevice();
  auto scene = scene::loadScene("cornell-box");
  render::PathTracer tracer(*device, scene, kSize, kSize);
  const auto before = accumulate(tracer, kSpp);
  scene.camera.position += glm::vec3(0.05f, -0.02f, 0.1f);
  tracer.setCamera(scene.camera);
  REQUIRE(tracer.accumulatedSamples() == 0u);
  const auto moved = accumulate(tracer, kSpp);
  render::PathTracer fresh(*device, scene, kSize, kSize);
  const auto freshImage = accumulate(fresh, kSpp);
  INFO(differences(moved, freshImage));
  REQUIRE(matches(moved, freshImage));
  REQUIRE_FALSE(matches(moved, before));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("path tracer: updateMaterials matches a new tracer and rebuilds for new effects",
          "[render][gpu]") {
  auto device = test::makeTestDevice();
  auto scene = scene::loadScene("cornell-box");
  render::PathTracer tracer(*device, scene, kSize, kSize);
  REQUIRE(tracer.pipelineEffects() == uint32_t(PT_EFFECT_AREA_LIGHTS));
  accumulate(tracer, kSpp);

  // The white walls become rough metal: the pipeline needs the specular layer.
  for (auto& m : scene.materials)
    if (m.name == "white") {
      m.model = scene::MaterialModel::Disney;
      m.metallic = 1.0f;
      m.roughness = 0.3f;
    }
  REQUIRE(tracer.updateMaterials(scene.materials));
  REQUIRE(tracer.pipelineEffects() == uint32_t(PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR));
  REQUIRE(tracer.accumulatedSamples() == 0u);
  const auto updated = accumulate(tracer, kSpp);
  render::PathTracer fresh(*device, scene, kSize, kSize);
  REQUIRE(fresh.pipelineEffects() == tracer.pipelineEffects());
  const auto freshImage = accumulate(fresh, kSpp);
  INFO(differences(updated, freshImage));
  REQUIRE(matches(updated, freshImage));

  // A colour change keeps the pipeline.
  scene.materials[0].baseColor *= 0.5f;
  REQUIRE_FALSE(tracer.updateMaterials(scene.materials));

  // Emission is tabulated for NEE with the scene: changing it is refused.
  for (auto& m : scene.materials)
    if (m.isEmissive()) m.emission *= 2.0f;
  REQUIRE_THROWS_AS(tracer.updateMaterials(scene.materials), Error);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("path tracer: resize matches a new tracer of that size", "[render][gpu]") {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box");
  render::PathTracer tracer(*device, scene, kSize, kSize);
  accumulate(tracer, kSpp);
  tracer.resize(24, 16);
  REQUIRE(tracer.width() == 24u);
  REQUIRE(tracer.accumulatedSamples() == 0u);
  const auto resized = accumulate(tracer, kSpp);
  REQUIRE(resized.width == 24u);
  REQUIRE(resized.height == 16u);
  render::PathTracer fresh(*device, scene, 24, 16);
  const auto freshImage = accumulate(fresh, kSpp);
  INFO(differences(resized, freshImage));
  REQUIRE(matches(resized, freshImage));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
