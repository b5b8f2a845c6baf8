#pragma once
// Helpers of the renderer tests: render a scene on the test device, the
// camera rays the renderer traces for a pixel (the engine's camera model).
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "penumbra/image/image.h"
#include "penumbra/render/camera_model.h"
#include "penumbra/render/path_tracer.h"
#include "test_device.h"

namespace penumbra::test {

// Renders `spp` samples per pixel in frames of up to 16 and returns the mean.
inline image::Image renderScene(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                                uint32_t height, uint32_t spp,
                                const render::PathTracerSettings& settings = {}) {
  return render::renderImage(device, scene, width, height, spp, settings);
}

// The direction of the camera ray through film position `film` (pixels, (0,0)
// the top-left corner): the engine's one camera model (render/camera_model.h),
// which fills the frame constants shaders/shared/camera.hlsli reads.
inline glm::vec3 cameraRayDirection(const scene::Camera& c, uint32_t width, uint32_t height,
                                    glm::vec2 film) {
  return glm::vec3(render::cameraRay(render::cameraModel(c, width, height), film).direction);
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

// Film position (pixels, (0,0) the top-left corner) whose ray sees world point p.
inline glm::dvec2 projectToFilm(const scene::Camera& camera, glm::dvec3 p, uint32_t w, uint32_t h) {
  return render::projectToFilm(render::cameraModel(camera, w, h), p);
}

// Unit direction of the camera ray through a film position, in double.
inline glm::dvec3 cameraRayDirection(const scene::Camera& camera, glm::dvec2 film, uint32_t w,
                                     uint32_t h) {
  return render::cameraRay(render::cameraModel(camera, w, h), film).direction;
}

// A bright spot on black: its flux (the sum of the pixels' red channel,
// covered pixels for radiance 1), flux-weighted centroid and mean squared
// distance from it. An image without flux has all three 0.
struct Spot {
  double flux = 0;
  double cx = 0, cy = 0;  // pixels
  double meanSquare = 0;  // pixels^2
};

inline Spot measureSpot(const image::Image& img) {
  Spot s;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const double v = img.pixel(x, y)[0];
      s.flux += v;
      s.cx += v * (x + 0.5);
      s.cy += v * (y + 0.5);
    }
  if (!(s.flux > 0.0)) return Spot{};
  s.cx /= s.flux;
  s.cy /= s.flux;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const double dx = x + 0.5 - s.cx, dy = y + 0.5 - s.cy;
      s.meanSquare += img.pixel(x, y)[0] * (dx * dx + dy * dy);
    }
  s.meanSquare /= s.flux;
  return s;
}

}  // namespace penumbra::test
