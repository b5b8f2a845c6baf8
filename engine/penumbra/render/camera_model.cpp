#include "penumbra/render/camera_model.h"

#include <cmath>

namespace penumbra::render {

CameraModel cameraModel(const scene::Camera& camera, uint32_t width, uint32_t height) {
  CameraModel m;
  m.position = camera.position;
  m.forward = glm::normalize(glm::dvec3(camera.forward));
  m.right = glm::normalize(glm::cross(m.forward, glm::dvec3(camera.up)));
  m.up = glm::cross(m.right, m.forward);
  m.orthographic = camera.orthographic();
  m.filmHalfHeight = m.orthographic
                         ? 0.5 * double(camera.orthographicHeight)
                         : std::tan(glm::radians(double(camera.verticalFovDegrees)) * 0.5);
  m.aspect = double(width) / double(height);
  // Narrower than the frame the camera was set up for: keep its horizontal
  // field of view or width (scene::Camera::aspectRatio).
  if (camera.aspectRatio > 0.0f && m.aspect < double(camera.aspectRatio))
    m.filmHalfHeight *= double(camera.aspectRatio) / m.aspect;
  m.width = width;
  m.height = height;
  return m;
}

CameraRay cameraRay(const CameraModel& c, glm::dvec2 film) {
  const double sx = (2.0 * film.x / c.width - 1.0) * c.filmHalfHeight * c.aspect;
  const double sy = (1.0 - 2.0 * film.y / c.height) * c.filmHalfHeight;
  if (c.orthographic) return {c.position + sx * c.right + sy * c.up, c.forward};
  return {c.position, glm::normalize(c.forward + sx * c.right + sy * c.up)};
}

glm::dvec2 projectToFilm(const CameraModel& c, const glm::dvec3& point) {
  const glm::dvec3 d = point - c.position;
  const double depth = c.orthographic ? 1.0 : glm::dot(d, c.forward);
  const double sx = glm::dot(d, c.right) / depth / (c.filmHalfHeight * c.aspect);
  const double sy = glm::dot(d, c.up) / depth / c.filmHalfHeight;
  return {(sx + 1.0) * 0.5 * c.width, (1.0 - sy) * 0.5 * c.height};
}

}  // namespace penumbra::render
