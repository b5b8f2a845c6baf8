#pragma once
// What is under the cursor: the viewer's focus-on-click and material
// selection. The ray goes through the renderer's own pipeline
// (PathTracer::traceProbeRays), so triangles and implicit surfaces are picked
// exactly as they are drawn.
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "penumbra/render/path_tracer.h"
#include "penumbra/scene/scene.h"

namespace penumbra::viewer {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit length
};

// The ray through `pixel` ((0,0) the top-left corner, pixel centres at +0.5)
// of an image of width x height: the engine's camera model
// (render/camera_model.h), the one the shading core's frame constants are made of.
Ray cameraRay(const scene::Camera& camera, uint32_t width, uint32_t height, glm::vec2 pixel);

struct PickHit {
  glm::vec3 position{0.0f};
  float distance = 0;
  std::string object;  // the mesh's or implicit object's name
  uint32_t material = 0;
};

// The closest hit along `ray`, if any; `scene` is the one `tracer` renders.
std::optional<PickHit> pick(render::PathTracer& tracer, const scene::Scene& scene, const Ray& ray);

}  // namespace penumbra::viewer
