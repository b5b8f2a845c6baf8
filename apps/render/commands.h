#pragma once
#include "render/denoiser.h"
// Subcommands of the `penumbra` CLI. Each registers its options on the app and
// returns the function that runs it.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

namespace penumbra::app {
using Command = std::function<int()>;
Command addRenderCommand(CLI::App& app);
Command addDevicesCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addStudyCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);
Command addFarmCommand(CLI::App& app);
// "512x512" -> (512, 512); penumbra::Error with the flag's name otherwise.
std::pair<uint32_t, uint32_t> parseImageSize(const std::string& text);

// The --denoise option (off | atrous | svgf) of `render` and `bench`.
void addDenoiseOption(CLI::App* command, render::DenoiseMode& mode, const std::string& description);
}  // namespace penumbra::app
