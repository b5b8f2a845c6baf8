#include "picking.h"

#include <cmath>

#include "penumbra/render/camera_model.h"

namespace penumbra::viewer {

Ray cameraRay(const scene::Camera& camera, uint32_t width, uint32_t height, glm::vec2 pixel) {
  const render::CameraRay ray =
      render::cameraRay(render::cameraModel(camera, width, height), pixel);
  return {glm::vec3(ray.origin), glm::vec3(ray.direction)};
}

std::optional<PickHit> pick(render::PathTracer& tracer, const scene::Scene& scene, const Ray& ray) {
  const auto hits = tracer.traceProbeRays({{ray.origin, ray.direction, 1e30f}});
  if (hits.empty() || !hits[0].isHit()) return std::nullopt;
  const render::SurfaceHit& hit = hits[0];
  // InstanceData lists the mesh instances, then the implicit objects.
  const size_t meshInstances = scene.instances.size();
  PickHit result;
  result.position = hit.position;
  result.distance = hit.hitT * glm::length(ray.direction);
  if (hit.instanceIndex < meshInstances) {
    const auto& mesh = scene.meshes[scene.instances[hit.instanceIndex].mesh];
    result.object = mesh.name;
    result.material = mesh.material;
  } else {
    const auto& object = scene.implicits.at(hit.instanceIndex - meshInstances);
    result.object = object.name;
    result.material = object.material;
  }
  return result;
}

}  // namespace penumbra::viewer
