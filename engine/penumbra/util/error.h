#pragma once
#include <stdexcept>
#include <string>

namespace penumbra {
// The one exception type for user-facing failures: its message is a single
// line that says what went wrong and where. Apps print it and exit non-zero.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};
}  // namespace penumbra
