#include "penumbra/scene/camera_placement.h"

#include <fmt/format.h>

#include <cmath>

#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

void requireFinite(const glm::dvec3& v, const char* what) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(v[i]))
      throw Error(
          fmt::format("camera: {} ({}, {}, {}) is not a finite point", what, v.x, v.y, v.z));
}

// An up direction for `forward`: `preferred` unless parallel to it.
glm::vec3 upFor(const glm::dvec3& forward, const glm::vec3& preferred) {
  const glm::dvec3 f = glm::normalize(forward);
  for (const glm::dvec3 up : {glm::dvec3(preferred), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)})
    if (glm::length(up) > 0.0 && glm::length(glm::cross(f, glm::normalize(up))) > 1e-6)
      return glm::vec3(up);
  return glm::vec3(0, 0, 1);  // not reached: forward cannot be parallel to both +y and +z
}

}  // namespace

Camera framingCamera(const Scene& scene) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& inst : scene.instances)
    for (const auto& p : scene.meshes[inst.mesh].positions) {
      const glm::dvec3 w(inst.transform * glm::dvec4(glm::dvec3(p), 1.0));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  if (!(lo.x <= hi.x)) lo = hi = glm::dvec3(0.0);  // nothing drawn
  Camera c;
  c.verticalFovDegrees = 45.0f;
  c.aspectRatio = 1.0f;
  const glm::dvec3 center = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
  const double azimuth = glm::radians(45.0), elevation = glm::radians(30.0);
  const glm::dvec3 towardsCamera(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                 std::cos(azimuth) * std::cos(elevation));
  // The bounds' sphere subtends the half field of view at this distance.
  const double distance = radius / std::sin(glm::radians(0.5 * double(c.verticalFovDegrees)));
  c.position = center + distance * towardsCamera;
  c.forward = glm::vec3(-towardsCamera);
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  return c;
}

float orthographicHeightAt(const Camera& camera, double distance) {
  return float(2.0 * distance * std::tan(glm::radians(0.5 * double(camera.verticalFovDegrees))));
}

void placeCamera(Camera& camera, const CameraPlacement& placement) {
  if (placement.position) {
    requireFinite(*placement.position, "--camera-position");
    camera.position = *placement.position;
  }
  if (placement.lookAt) {
    requireFinite(*placement.lookAt, "--look-at");
    const glm::dvec3 forward = *placement.lookAt - camera.position;
    if (!(glm::length(forward) > 0.0))
      throw Error(fmt::format(
          "camera: --look-at ({}, {}, {}) is the camera's position; give a point in front of it",
          placement.lookAt->x, placement.lookAt->y, placement.lookAt->z));
    camera.up = upFor(forward, camera.up);
    camera.forward = glm::vec3(glm::normalize(forward));
  }
  if (placement.verticalFovDegrees && placement.orthographicHeight)
    throw Error("camera: give --fov (perspective) or --orthographic, not both");
  if (placement.verticalFovDegrees) {
    const float fov = *placement.verticalFovDegrees;
    if (!(fov > 0.0f && fov < 180.0f))
      throw Error(fmt::format("camera: --fov {} must lie in (0, 180) degrees", fov));
    camera.verticalFovDegrees = fov;
    camera.orthographicHeight = 0.0f;
    camera.aspectRatio = 0.0f;  // the field of view asked for, whatever the image's shape
  }
  if (placement.orthographicHeight) {
    const float height = *placement.orthographicHeight;
    if (!(height > 0.0f) || !std::isfinite(height))
      throw Error(fmt::format("camera: --orthographic {} must be finite and > 0", height));
    camera.orthographicHeight = height;
    camera.aspectRatio = 0.0f;
  }
}

void placeCamera(Scene& scene, const CameraPlacement& placement) {
  if (!placement.name.empty()) selectCamera(scene, placement.name);
  placeCamera(scene.camera, placement);
}

}  // namespace penumbra::scene
