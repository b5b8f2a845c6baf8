#pragma once
// Helpers of the renderer tests: render a scene on the test device, and the
// camera rays the renderer traces for a pixel.
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

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

// The direction of the camera ray through film position `film` (pixels, (0,0)
// the top-left corner), exactly as shaders/shared/camera.hlsli computes it
// from the frame constants PathTracer::renderFrame derives from the camera.
inline glm::vec3 cameraRayDirection(const scene::Camera& c, uint32_t width, uint32_t height,
                                    glm::vec2 film) {
  const glm::vec3 forward = glm::normalize(c.forward);
  const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tanHalfFov = std::tan(glm::radians(c.verticalFovDegrees) * 0.5f);
  const float aspect = float(width) / float(height);
  const float sx = (2.0f * film.x / float(width) - 1.0f) * tanHalfFov * aspect;
  const float sy = (1.0f - 2.0f * film.y / float(height)) * tanHalfFov;
  return glm::normalize(forward + sx * right + sy * up);
}

// The rays a pixel's jittered samples can take lie between its corners; a
// 3 x 3 grid over the footprint (corners, edge midpoints, centre) stands for
// them when deciding whether the whole pixel sees one thing.
inline std::vector<glm::vec2> pixelFootprint(uint32_t x, uint32_t y) {
  std::vector<glm::vec2> points;
  for (float fy : {0.0f, 0.5f, 1.0f})
    for (float fx : {0.0f, 0.5f, 1.0f}) points.push_back({float(x) + fx, float(y) + fy});
  return points;
}

}  // namespace penumbra::test
