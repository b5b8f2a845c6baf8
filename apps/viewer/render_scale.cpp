#include "render_scale.h"

#include <algorithm>
#include <cmath>

namespace penumbra::viewer {

RenderScaleController::RenderScaleController(float scale, bool automatic, double targetFrameSeconds)
    : scale_(std::clamp(scale, kMinScale, kMaxScale)),
      automatic_(automatic),
      target_(targetFrameSeconds) {}

void RenderScaleController::setScale(float scale) {
  scale_ = std::clamp(scale, kMinScale, kMaxScale);
  frames_ = 0;
  average_ = 0;
}

void RenderScaleController::setAutomatic(bool automatic) {
  automatic_ = automatic;
  frames_ = 0;
  average_ = 0;
}

bool RenderScaleController::update(double frameSeconds) {
  if (!automatic_) return false;
  average_ = frames_ == 0 ? frameSeconds : 0.7 * average_ + 0.3 * frameSeconds;
  if (++frames_ < kSettleFrames) return false;
  // Only clear misses move the scale (a band of 0.5x..1.5x the target), so a
  // still camera keeps accumulating instead of restarting over small jitter.
  if (average_ < 1.5 * target_ && (average_ > 0.5 * target_ || scale_ >= kMaxScale)) return false;
  // Frame time grows with the pixel count, the square of the scale.
  const double wanted = scale_ * std::sqrt(target_ / std::max(average_, 1e-6));
  const float next = std::clamp(float(wanted), kMinScale, kMaxScale);
  if (std::abs(next - scale_) < 0.01f) return false;
  setScale(next);
  return true;
}

}  // namespace penumbra::viewer
