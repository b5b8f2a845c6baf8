#pragma once
// Helpers of the renderer tests: render a scene on the test device; the
// pinhole camera of shaders/shared/camera.hlsli, in double precision.
#include <cmath>
#include <glm/glm.hpp>

#include "image/image.h"
#include "render/path_tracer.h"
#include "test_device.h"

namespace penumbra::test {

// Renders `spp` samples per pixel in frames of up to 16 and returns the mean.
inline image::Image renderScene(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                                uint32_t height, uint32_t spp,
                                const render::PathTracerSettings& settings = {}) {
  return render::renderImage(device, scene, width, height, spp, settings);
}

struct CameraFrame {
  glm::dvec3 position, right, up, forward;
  double tanHalfFov;
};

inline CameraFrame cameraFrame(const scene::Camera& c) {
  const glm::dvec3 f = glm::normalize(glm::dvec3(c.forward));
  const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(c.up)));
  return {glm::dvec3(c.position), r, glm::cross(r, f), f,
          std::tan(glm::radians(double(c.verticalFovDegrees)) * 0.5)};
}

// Film position (pixels, (0,0) the top-left corner) whose ray sees world point p.
inline glm::dvec2 projectToFilm(const scene::Camera& camera, glm::dvec3 p, uint32_t w, uint32_t h) {
  const CameraFrame c = cameraFrame(camera);
  const glm::dvec3 d = p - c.position;
  const double aspect = double(w) / double(h);
  const double sx = glm::dot(d, c.right) / glm::dot(d, c.forward) / (c.tanHalfFov * aspect);
  const double sy = glm::dot(d, c.up) / glm::dot(d, c.forward) / c.tanHalfFov;
  return {(sx + 1.0) * 0.5 * w, (1.0 - sy) * 0.5 * h};
}

// Unit direction of the camera ray through a film position.
inline glm::dvec3 cameraRayDirection(const scene::Camera& camera, glm::dvec2 film, uint32_t w,
                                     uint32_t h) {
  const CameraFrame c = cameraFrame(camera);
  const double aspect = double(w) / double(h);
  const double sx = (2.0 * film.x / w - 1.0) * c.tanHalfFov * aspect;
  const double sy = (1.0 - 2.0 * film.y / h) * c.tanHalfFov;
  return glm::normalize(c.forward + sx * c.right + sy * c.up);
}

}  // namespace penumbra::test
