#pragma once
// tinygltf with this project's configuration. Every file that includes
// tiny_gltf.h must see the same macros (they change the TinyGLTF class), so
// they include this header instead. Images are decoded with stb_image; the
// writer is not needed.
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
