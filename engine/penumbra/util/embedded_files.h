#pragma once
// Text files compiled into the binary (the built-in scenes), so `penumbra`
// runs from any directory and on machines that have only the executable.
#include <optional>
#include <string_view>
#include <vector>

namespace penumbra::embedded {
std::optional<std::string_view> find(std::string_view fileName);
std::vector<std::string_view> names();
}  // namespace penumbra::embedded
