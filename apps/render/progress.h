#pragma once
// Progress of a long render: a redrawn bar with samples done and ETA on a
// terminal, plain lines when stderr is not a terminal. Silent for renders
// that finish within a second.
#include <chrono>
#include <cstdint>

namespace penumbra::app {

class Progress {
 public:
  explicit Progress(uint32_t totalSamples);
  void update(uint32_t samplesDone);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  uint32_t total_;
  Clock::time_point start_;
  Clock::time_point lastPrint_;
  bool terminal_;
  bool shown_ = false;
};

}  // namespace penumbra::app
