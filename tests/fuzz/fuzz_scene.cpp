// libFuzzer target: Penumbra's scene files (.json), parsed from memory.
#include <string_view>

#include "fuzz_support.h"
#include "penumbra/scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace penumbra;
  const std::string_view json(reinterpret_cast<const char*>(data), size);
  fuzz::expectCleanRejection([&] { (void)scene::parseScene(json, "fuzz.json"); });
  return 0;
}
