#pragma once
// The one camera model: a scene::Camera looking through an image of width x
// height pixels as the shading core sees it (FrameConstants' camera rows,
// shaders/shared/camera.hlsli). The path tracer fills FrameConstants from it
// (cameraFrame), the viewer picks with it, the tests project with it.
// Film positions are in pixels, (0, 0) the image's top-left corner.
#include <glm/glm.hpp>

#include "penumbra/scene/scene.h"

namespace penumbra::render {

struct CameraModel {
  glm::dvec3 position{0.0};
  // A right-handed unit basis: right = forward x up, up = right x forward.
  glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1};
  bool orthographic = false;
  // Half the film's height: tan(vertical field of view / 2), the height at
  // unit distance ahead, for a perspective camera; world units for an
  // orthographic one (CameraData.filmHalfHeight).
  double filmHalfHeight = 1.0;
  double aspect = 1.0;  // width / height
  uint32_t width = 1, height = 1;
};

CameraModel cameraModel(const scene::Camera& camera, uint32_t width, uint32_t height);

// The pinhole ray through `film` (camera.hlsli's cameraRay; a thin lens bends
// it towards the focus plane from there).
struct CameraRay {
  glm::dvec3 origin;     // the position; orthographic: the film point
  glm::dvec3 direction;  // unit; orthographic: forward
};
CameraRay cameraRay(const CameraModel& camera, glm::dvec2 film);

// The film position whose pinhole ray passes through `point`, which must lie
// in front of the camera.
glm::dvec2 projectToFilm(const CameraModel& camera, const glm::dvec3& point);

}  // namespace penumbra::render
