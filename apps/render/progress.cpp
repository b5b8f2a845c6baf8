#include "progress.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace penumbra::app {

Progress::Progress(uint32_t totalSamples)
    : total_(totalSamples), start_(Clock::now()), lastPrint_(start_), terminal_(isatty(STDERR_FILENO)) {}

void Progress::update(uint32_t done) {
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0) return;  // short renders print nothing
  const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
  if (shown_ && done < total_ && sinceLast < (terminal_ ? 0.1 : 5.0)) return;
  lastPrint_ = now;
  shown_ = true;
  const double fraction = total_ ? double(done) / total_ : 1.0;
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  if (terminal_) {
    const int width = 30;
    const int filled = int(fraction * width);
    std::string bar(filled, '#');
    bar.append(width - filled, '.');
    std::fprintf(stderr, "\r[%s] %u/%u spp  %.1fs elapsed  ETA %.1fs ", bar.c_str(), done, total_,
                 elapsed, eta);
  } else {
    std::fprintf(stderr, "progress: %u/%u spp, %.1fs elapsed, ETA %.1fs\n", done, total_, elapsed, eta);
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (shown_ && terminal_) std::fprintf(stderr, "\n");
}

}  // namespace penumbra::app
