#include "camera_controller.h"

#include <algorithm>
#include <cmath>

namespace penumbra::viewer {

CameraController::CameraController(const scene::Camera& home, float speed)
    : home_(home), camera_(home), speed_(speed) {}

// The path tracer's convention (path_tracer.cpp): right = forward x up.
glm::vec3 CameraController::right() const {
  return glm::normalize(glm::cross(glm::normalize(camera_.forward), camera_.up));
}

bool CameraController::update(const CameraInput& input, float seconds) {
  bool changed = false;
  // Moving along a parallel view changes nothing in it: there the wheel
  // zooms, each notch forward showing 1 / 1.25 of the height.
  if (input.scrollSteps != 0 && camera_.orthographic()) {
    // Kept within what a camera may hold (scene::validateCamera: at most
    // 1e9) and short of 0, which would turn the view perspective.
    const float height = camera_.orthographicHeight / std::pow(kSpeedStepFactor, input.scrollSteps);
    const float bounded = std::isnan(height)
                              ? camera_.orthographicHeight
                              : std::clamp(height, kMinOrthographicHeight, kMaxOrthographicHeight);
    changed = bounded != camera_.orthographicHeight;
    camera_.orthographicHeight = bounded;
  } else if (input.scrollSteps != 0) {
    speed_ *= std::pow(kSpeedStepFactor, input.scrollSteps);
  }
  if (input.turn != glm::vec2(0.0f)) {
    turn(input.turn.x * kDegreesPerPixel, -input.turn.y * kDegreesPerPixel);
    changed = true;
  }
  if (input.move != glm::vec3(0.0f) && seconds > 0) {
    move(input.move * (speed_ * seconds));
    changed = true;
  }
  return changed;
}

void CameraController::move(glm::vec3 metres) {
  const glm::vec3 forward = glm::normalize(camera_.forward);
  const glm::vec3 up = glm::normalize(camera_.up);
  camera_.position += right() * metres.x + up * metres.y + forward * metres.z;
}

void CameraController::focusOn(glm::vec3 target) {
  const glm::vec3 direction = target - glm::vec3(camera_.position);
  glm::vec3 forward = glm::normalize(camera_.forward);
  if (camera_.orthographic()) {
    camera_.position += glm::dvec3(direction - forward * glm::dot(direction, forward));
  } else if (glm::length(direction) > 0.0f) {
    // Straight along up the right vector (forward x up) would vanish: the
    // direction stays, the focus still moves.
    const glm::vec3 facing = glm::normalize(direction);
    if (glm::length(glm::cross(facing, glm::normalize(camera_.up))) >= 1e-4f)
      camera_.forward = forward = facing;
  }
  const float depth = glm::dot(target - glm::vec3(camera_.position), forward);
  if (depth > 0.0f) camera_.focusDistance = depth;
}

void CameraController::turn(float yawDegrees, float pitchDegrees) {
  const glm::vec3 up = glm::normalize(camera_.up);
  glm::vec3 forward = glm::normalize(camera_.forward);
  const float yaw = glm::radians(yawDegrees);
  forward = glm::normalize(forward * std::cos(yaw) + right() * std::sin(yaw));
  // Pitch as a change of elevation above the horizon, clamped short of the
  // poles where forward x up (the right vector) would vanish.
  const float elevation = std::asin(std::clamp(glm::dot(forward, up), -1.0f, 1.0f));
  const float limit = glm::radians(kMaxElevationDegrees);
  const float target = std::clamp(elevation + glm::radians(pitchDegrees), -limit, limit);
  const glm::vec3 horizontal = glm::normalize(forward - up * glm::dot(forward, up));
  camera_.forward = horizontal * std::cos(target) + up * std::sin(target);
}

}  // namespace penumbra::viewer
