#include "penumbra/rhi/fault_injection.h"

#include <fmt/format.h>

#include <cstdlib>
#include <mutex>
#include <string>

#include "penumbra/util/error.h"

namespace penumbra::rhi::faults {
namespace {

struct Armed {
  bool active = false;
  Site site = Site::Allocation;
  uint64_t countdown = 0;
};

std::mutex gMutex;
Armed gArmed;
bool gEnvironmentRead = false;

// PENUMBRA_INJECT_FAULT=<allocation|submit>:<N>; anything else is an error,
// so a misspelt test setting cannot pass silently. Read once.
void readEnvironmentLocked() {
  if (gEnvironmentRead) return;
  gEnvironmentRead = true;
  const char* value = std::getenv("PENUMBRA_INJECT_FAULT");
  if (!value || !*value) return;
  const std::string spec(value);
  const size_t colon = spec.find(':');
  const std::string site = spec.substr(0, colon);
  char* end = nullptr;
  const unsigned long long n =
      colon == std::string::npos ? 0 : std::strtoull(spec.c_str() + colon + 1, &end, 10);
  if ((site != "allocation" && site != "submit") || n == 0 || !end || *end != '\0')
    throw Error(fmt::format(
        "PENUMBRA_INJECT_FAULT='{}': expected allocation:N or submit:N (N >= 1)", spec));
  gArmed = {true, site == "allocation" ? Site::Allocation : Site::Submit, n};
}

}  // namespace

void readEnvironment() {
  std::lock_guard lock(gMutex);
  readEnvironmentLocked();
}

void arm(Site site, uint64_t countdown) {
  std::lock_guard lock(gMutex);
  gEnvironmentRead = true;  // an explicit arm replaces the environment's
  gArmed = {countdown > 0, site, countdown};
}

bool shouldFail(Site site) {
  std::lock_guard lock(gMutex);
  readEnvironmentLocked();
  if (!gArmed.active || gArmed.site != site) return false;
  if (--gArmed.countdown > 0) return false;
  gArmed.active = false;
  return true;
}

}  // namespace penumbra::rhi::faults
