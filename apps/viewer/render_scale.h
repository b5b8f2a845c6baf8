#pragma once
// Automatic render scale: on a slow device (lavapipe renders on the CPU) the
// path tracer renders fewer pixels so the window keeps answering. The image is
// rendered at scale * window size and stretched to the window.
namespace penumbra::viewer {

class RenderScaleController {
 public:
  static constexpr float kMinScale = 0.125f;
  static constexpr float kMaxScale = 1.0f;
  // Frames between changes: each change restarts the accumulation.
  static constexpr int kSettleFrames = 8;

  explicit RenderScaleController(float scale = 1.0f, bool automatic = true,
                                 double targetFrameSeconds = 1.0 / 30.0);
  // Feeds the time one frame took (render + display); returns whether the
  // scale changed. Manual mode never changes it.
  bool update(double frameSeconds);
  float scale() const { return scale_; }
  void setScale(float scale);  // also what manual mode uses
  bool automatic() const { return automatic_; }
  void setAutomatic(bool automatic);
  double targetFrameSeconds() const { return target_; }

 private:
  float scale_;
  bool automatic_;
  double target_;
  double average_ = 0;  // exponential moving average of frame times
  int frames_ = 0;      // since the last change
};

}  // namespace penumbra::viewer
