#pragma once
// What is under the cursor: the viewer's focus-on-click and material
// selection. PathTracer::traceProbeRays (the GPU probe, on another branch)
// is meant for this; until it reaches main the viewer intersects the scene's
// triangles on the CPU, which is exact for triangle scenes and fast enough
// for one ray per click.
#include <glm/glm.hpp>
#include <optional>

#include "scene/scene.h"

namespace penumbra::viewer {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit length
};

// The ray through `pixel` ((0,0) the top-left corner, pixel centres at +0.5)
// of an image of width x height, as the shading core's pinhole camera
// (shaders/shared/camera.hlsli) traces it.
Ray cameraRay(const scene::Camera& camera, uint32_t width, uint32_t height, glm::vec2 pixel);

struct PickHit {
  glm::vec3 position{0.0f};
  float distance = 0;
  uint32_t instance = 0;
  uint32_t material = 0;
};

// The closest triangle hit along `ray` (both faces), if any.
std::optional<PickHit> pick(const scene::Scene& scene, const Ray& ray);

}  // namespace penumbra::viewer
