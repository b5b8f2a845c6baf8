// libFuzzer target: image decoding. The first byte picks the decoder, the
// rest is the file: 0 a glTF texture (stb_image: PNG, JPEG, and what else
// stb accepts, under the texture limits), 1 an environment map in Radiance
// .hdr, 2 one in OpenEXR (tinyexr).
#include "fuzz_support.h"
#include "penumbra/scene/environment.h"
#include "penumbra/scene/gltf_textures.h"
#include "penumbra/scene/tinygltf.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace penumbra;
  if (size < 1) return 0;
  const uint8_t kind = data[0] % 3;
  ++data;
  --size;
  if (kind == 0) {
    fuzz::expectCleanRejection([&] {
      tinygltf::Image image;
      scene::gltf::ImageDecoding decoding;
      std::string error, warning;
      scene::gltf::decodeImage(&image, 0, &error, &warning, 0, 0, data, int(size), &decoding);
    });
  } else {
    const std::string path = fuzz::writeInput(kind == 1 ? "input.hdr" : "input.exr", data, size);
    fuzz::expectCleanRejection([&] { (void)scene::loadEnvironmentMap(path); });
  }
  return 0;
}
