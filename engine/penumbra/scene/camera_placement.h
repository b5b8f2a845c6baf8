#pragma once
// Where the view comes from when the scene does not say, or when the user
// says otherwise: the framing of a scene without cameras, and a placement
// given on the command line (render, viewer) over the scene's camera.
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// The view of a scene without cameras: it looks at the centre of the
// instances' world bounds from a three-quarter view -- 45 degrees round from
// +z (glTF's front) towards +x and 30 degrees up -- with a 45-degree field of
// view, far enough away that the bounds' sphere fits the frame at any image
// shape (aspectRatio 1: a narrow image keeps the horizontal field of view).
// A flat model is seen from above its plane, never edge on.
Camera framingCamera(const Scene& scene);

// A view given over the scene's camera. Each part given replaces that part
// of the camera: `name` picks one of the scene's cameras first (selectCamera,
// by name or index); then `position`; then `lookAt` turns the camera towards
// that point (keeping its up direction unless the new forward is parallel to
// it, then world +y, or +z when looking straight up or down); then the
// vertical field of view (a perspective camera) or the orthographic height
// (an orthographic one), which then holds at every image shape (the camera's
// aspectRatio is cleared).
struct CameraPlacement {
  std::string name;
  std::optional<glm::dvec3> position;  // world units (metres after a scene file's unitScale)
  std::optional<glm::dvec3> lookAt;
  std::optional<float> verticalFovDegrees;
  std::optional<float> orthographicHeight;  // world units
  bool empty() const {
    return name.empty() && !position && !lookAt && !verticalFovDegrees && !orthographicHeight;
  }
};

// The height of an orthographic view that shows the plane `distance` ahead
// as the perspective camera `camera` shows it: 2 distance tan(fov / 2). The
// viewer's switch to orthographic keeps the plane in focus this way.
float orthographicHeightAt(const Camera& camera, double distance);

// Applies `placement` to the scene's camera; throws penumbra::Error naming
// the part that is unusable (an unknown camera, a look-at point at the
// camera's position, a field of view outside (0, 180) degrees, an
// orthographic height <= 0, both of these, a non-finite coordinate).
void placeCamera(Scene& scene, const CameraPlacement& placement);
// The same on a camera of its own (a render record's); `name` is not used.
void placeCamera(Camera& camera, const CameraPlacement& placement);

}  // namespace penumbra::scene
