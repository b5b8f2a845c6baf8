#pragma once
// Paths of the checked-in test data (tests/data): PENUMBRA_TEST_DATA when
// ctest sets it, else the source tree the tests were built from.
#include <cstdlib>
#include <string>

namespace penumbra::test {

inline std::string dataPath(const std::string& relative) {
  const char* env = std::getenv("PENUMBRA_TEST_DATA");
  return std::string(env && *env ? env : PENUMBRA_TEST_DATA_DIR) + "/" + relative;
}

}  // namespace penumbra::test
