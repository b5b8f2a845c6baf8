// libFuzzer target: the glTF importer (.gltf JSON or .glb binary, chosen by
// the "glTF" magic) with the default file-access policy (nothing outside the
// file's folder) and limits, once as drawn by default and once with every
// animation at a time between keyframes (the animation samplers).
#include <cstring>

#include "fuzz_support.h"
#include "penumbra/scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace penumbra;
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string path = fuzz::writeInput(binary ? "input.glb" : "input.gltf", data, size);
  fuzz::expectCleanRejection([&] { (void)scene::loadGltf(path); });
  fuzz::expectCleanRejection([&] { (void)scene::loadGltf(path, {}, {}, {"all", 0.37}); });
  return 0;
}
