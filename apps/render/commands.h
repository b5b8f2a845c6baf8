#pragma once
// Subcommands of the `penumbra` CLI. Each registers its options on the app and
// returns the function that runs it.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include "cli_options.h"

namespace penumbra::app {
using Command = std::function<int()>;
Command addRenderCommand(CLI::App& app);
Command addDevicesCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addStudyCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);
Command addFarmCommand(CLI::App& app);
}  // namespace penumbra::app
