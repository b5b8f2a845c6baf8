// The one translation unit that compiles tinygltf and the stb_image decoder it
// reads images with (Debian ships tinygltf as a header; building it here keeps
// the binary free of another shared library and works for the cross build).
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
// stb_image's implementation has no include guard: tinygltf must not include it again.
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_IMPLEMENTATION
#include "penumbra/scene/tinygltf.h"
