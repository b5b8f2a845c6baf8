#pragma once
// What every fuzz target shares: the rule that a rejected input ends in
// penumbra::Error (one clear line for the user) and anything else is a
// finding, and a private folder for targets whose loaders read files.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "penumbra/util/error.h"

namespace penumbra::fuzz {

// Runs `load`; penumbra::Error is the expected way to refuse an input. Any
// other exception (std::bad_alloc, a JSON library's, std::out_of_range) is a
// bug that would reach the user as "internal error": abort so libFuzzer
// records the input.
template <class Load>
void expectCleanRejection(Load&& load) {
  try {
    load();
  } catch (const Error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz finding: unexpected exception: %s\n", e.what());
    std::abort();
  }
}

// A folder of this process's own under the system temp directory. Its name
// has the same length whatever the process id, so the paths in the loaders'
// messages, and the code that handles them, do not vary from run to run
// (run_fuzzer.sh's runs are reproducible).
inline const std::filesystem::path& workFolder() {
  static const std::filesystem::path folder = [] {
    char name[32];
    std::snprintf(name, sizeof(name), "penumbra-fuzz-%010ld", long(getpid()));
    auto path = std::filesystem::temp_directory_path() / name;
    std::filesystem::create_directories(path);
    return path;
  }();
  return folder;
}

// Writes the input to `name` in the work folder and returns its path.
inline std::string writeInput(const std::string& name, const uint8_t* data, size_t size) {
  const auto path = workFolder() / name;
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path.string();
}

}  // namespace penumbra::fuzz
