#include "penumbra/util/log.h"

#include <atomic>
#include <cstdio>

namespace penumbra::log {
namespace {
std::atomic<Level> gMinimumLevel{Level::Info};
}

void setMinimumLevel(Level level) {
  gMinimumLevel = level;
}

void write(Level level, std::string_view message) {
  if (level < gMinimumLevel) return;
  const char* prefix = "";
  switch (level) {
    case Level::Debug:
      prefix = "debug: ";
      break;
    case Level::Info:
      prefix = "";
      break;
    case Level::Warning:
      prefix = "warning: ";
      break;
    case Level::Error:
      prefix = "error: ";
      break;
  }
  std::fprintf(stderr, "%s%.*s\n", prefix, static_cast<int>(message.size()), message.data());
}
}  // namespace penumbra::log
