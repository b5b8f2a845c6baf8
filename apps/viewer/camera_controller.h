#pragma once
// First-person camera control for the viewer, free of any window code so it
// can be tested on its own: WASD/QE move, mouse drag turns, the wheel scales
// the speed (an orthographic camera's height instead: zoom). An unchanged controller returns the
// scene camera bit for bit, so a screenshot taken before moving matches a headless render of the
// scene.
#include <glm/glm.hpp>

#include "penumbra/scene/scene.h"

namespace penumbra::viewer {

struct CameraInput {
  glm::vec3 move{0.0f};   // right, up, forward, each in [-1, 1] (D-A, E-Q, W-S)
  glm::vec2 turn{0.0f};   // mouse movement while dragging, pixels (x right, y down)
  float scrollSteps = 0;  // wheel notches, positive = faster (orthographic: zoom in)
};

class CameraController {
 public:
  static constexpr float kDegreesPerPixel = 0.2f;
  static constexpr float kSpeedStepFactor = 1.25f;  // per wheel notch (speed or zoom)
  static constexpr float kMaxElevationDegrees = 89.0f;
  // The wheel's zoom of an orthographic camera stays within these heights.
  static constexpr float kMinOrthographicHeight = 1e-6f;
  static constexpr float kMaxOrthographicHeight = 1e9f;

  // `speed`: metres per second at the start (the viewer derives it from the scene's size).
  CameraController(const scene::Camera& home, float speed);

  // Applies `seconds` of input; returns whether the camera changed.
  bool update(const CameraInput& input, float seconds);
  // Moves by metres along the camera's right, the world up, and forward.
  void move(glm::vec3 metres);
  // Turns right by `yawDegrees` and up by `pitchDegrees` (elevation clamped).
  void turn(float yawDegrees, float pitchDegrees);
  // Brings `target` (a picked point) to the image's centre and into focus: a
  // perspective camera turns to face it (position and up stay), an
  // orthographic one slides across its film plane (direction and up stay;
  // turning would swing the whole parallel view about its position). The
  // plane in focus is then the one through the target.
  void focusOn(glm::vec3 target);
  void reset() { camera_ = home_; }
  void setCamera(const scene::Camera& camera) { camera_ = camera; }
  void setHome(const scene::Camera& home) { home_ = camera_ = home; }

  const scene::Camera& camera() const { return camera_; }
  float speed() const { return speed_; }
  void setSpeed(float metresPerSecond) { speed_ = metresPerSecond; }

 private:
  glm::vec3 right() const;
  scene::Camera home_;
  scene::Camera camera_;
  float speed_;
};

}  // namespace penumbra::viewer
