#include "picking.h"

#include <cmath>

namespace penumbra::viewer {

Ray cameraRay(const scene::Camera& camera, uint32_t width, uint32_t height, glm::vec2 pixel) {
  const glm::vec3 forward = glm::normalize(camera.forward);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tanHalfFov = std::tan(glm::radians(camera.verticalFovDegrees) * 0.5f);
  const float aspect = float(width) / float(height);
  const float sx = (2.0f * pixel.x / float(width) - 1.0f) * tanHalfFov * aspect;
  const float sy = (1.0f - 2.0f * pixel.y / float(height)) * tanHalfFov;
  return {camera.position, glm::normalize(forward + sx * right + sy * up)};
}

std::optional<PickHit> pick(const scene::Scene& scene, const Ray& ray) {
  std::optional<PickHit> best;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const auto& instance = scene.instances[i];
    const auto& mesh = scene.meshes[instance.mesh];
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = glm::vec3(instance.transform *
                         glm::vec4(mesh.positions[mesh.indices[t + size_t(k)]], 1.0f));
      // Möller-Trumbore.
      const glm::vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
      const glm::vec3 h = glm::cross(ray.direction, e2);
      const float det = glm::dot(e1, h);
      if (std::abs(det) < 1e-12f) continue;
      const float inv = 1.0f / det;
      const glm::vec3 s = ray.origin - p[0];
      const float u = glm::dot(s, h) * inv;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 q = glm::cross(s, e1);
      const float v = glm::dot(ray.direction, q) * inv;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float distance = glm::dot(e2, q) * inv;
      if (distance <= 0.0f || (best && distance >= best->distance)) continue;
      best = PickHit{ray.origin + ray.direction * distance, distance, i, mesh.material};
    }
  }
  return best;
}

}  // namespace penumbra::viewer
