#pragma once
// Subcommands of the `penumbra` CLI. Each registers its options on the app and
// returns the function that runs it.
#include <CLI/CLI.hpp>
#include <functional>

namespace penumbra::app {
using Command = std::function<int()>;
Command addRenderCommand(CLI::App& app);
Command addDevicesCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
}  // namespace penumbra::app
