// libFuzzer target: the glTF importer (.gltf JSON or .glb binary, chosen by
// the "glTF" magic) with the default file-access policy (nothing outside the
// file's folder) and limits.
#include <cstring>

#include "fuzz_support.h"
#include "penumbra/scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace penumbra;
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string path = fuzz::writeInput(binary ? "input.glb" : "input.gltf", data, size);
  fuzz::expectCleanRejection([&] { (void)scene::loadGltf(path); });
  return 0;
}
