#pragma once
// glTF images, samplers and material texture infos as scene Textures and
// TextureRefs (docs/materials.md, "Textures").
//
// - Images are decoded by stb_image through decodeImage (installed as
//   tinygltf's image loader), then converted to RGBA8.
// - One Texture per (image, colour space) pair a material uses: base colour
//   and emission are sRGB, metallic-roughness, normal and occlusion linear.
// - Each texture info becomes one TextureRef: the texture, its sampler, the
//   texture coordinate set and the KHR_texture_transform matrix.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene.h"

namespace tinygltf {
class Model;
struct Image;
struct Sampler;
struct Material;
struct Texture;
class Value;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// Why images failed to decode, by glTF image index; filled by decodeImage.
// Every image's size is read from its header and checked against `limits`
// (maxImageSide, maxImagePixels, and maxTexturePixels for `pixels`, the
// file's images so far) before it is decoded: a small file can claim a huge
// image, which stb_image would allocate (and fill) in full.
struct ImageDecoding {
  std::map<int, std::string> failures;
  InputLimits limits;
  uint64_t pixels = 0;
};

// tinygltf's LoadImageDataFunction (user data: an ImageDecoding). Decodes
// with stb_image keeping the file's channel count and bit depth. It never
// fails: an image it cannot decode, or whose header passes a limit, is left
// empty and its reason recorded, so the importer reports it naming the image
// (and the limit), and only if a material uses it. Images in buffer views
// are left for TextureImporter to decode, under the same limits.
bool decodeImage(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                 int requiredWidth, int requiredHeight, const unsigned char* bytes, int size,
                 void* decoding);

// width x height pixels of 1 (grey), 2 (grey, alpha), 3 (rgb) or 4 (rgba)
// components of 8 or 16 bits (native byte order) as RGBA8: grey is
// replicated into rgb, a missing alpha is 255 and 16-bit values are rounded
// to the nearest 8-bit one (v * 255 / 65535). Throws penumbra::Error
// prefixed by `where` when the format is not one of these or `pixels` has
// the wrong size.
std::vector<uint8_t> toRgba8(const std::vector<unsigned char>& pixels, uint32_t width,
                             uint32_t height, int components, int bits, const std::string& where);

// A glTF sampler (spec 3.8.4): minFilter's in-level filter and its filter
// between mip levels (none for NEAREST and LINEAR); absent filters are linear.
// Unknown values give a warning and the default.
TextureSampler convertSampler(const tinygltf::Sampler& sampler, const std::string& where,
                              std::vector<std::string>& warnings);

// The KHR_texture_transform matrix translation * rotation * scale, stored in
// `ref`'s columns: u' = cos r sx u + sin r sy v + ox,
// v' = -sin r sx u + cos r sy v + oy (counter-clockwise in uv space, whose
// v axis points down).
void setTextureTransform(TextureRef& ref, glm::vec2 offset, float rotation, glm::vec2 scale);

// The KHR_materials_* textures read, each with the Material slot it fills
// (scene.h says which channel scales which parameter) and its colour space.
// Others (thicknessTexture, those of extensions not read) are warned about
// and their factors used.
struct ExtensionTexture {
  const char* extension;
  const char* key;
  bool srgb;
  uint32_t Material::*slot;
};
const std::vector<ExtensionTexture>& extensionTextures();

// Builds the scene's textures and texture references from the materials'
// texture infos, deduplicating textures by (image, sRGB).
class TextureImporter {
 public:
  // `at` names the file in messages; textures go into `scene`.
  TextureImporter(const tinygltf::Model& model, ImageDecoding& decoding, std::string at,
                  Scene& scene, std::vector<std::string>& warnings);

  // Sets `material`'s five texture slots from `src`'s texture infos.
  // `where` names the material in errors.
  void attach(const tinygltf::Material& src, Material& material, const std::string& where);

  // Warns about images that no material uses and that could not be read.
  void warnUnusedBrokenImages();

 private:
  // `transform` is the texture info's KHR_texture_transform object, if any.
  uint32_t textureRef(int index, int texCoord, const tinygltf::Value* transform, bool srgb,
                      const std::string& where);
  uint32_t texture(int image, bool srgb, const std::string& where);
  TextureSampler sampler(int index, const std::string& where);
  uint32_t texCoordSet(int texCoord, const std::string& where);
  // The image a texture reads: EXT_texture_webp's where this build decodes WebP, else `source`.
  int textureSource(const tinygltf::Texture& src, const std::string& where) const;
  std::string describeImage(int index) const;
  // Image `image` (stored in a buffer view) decoded into `out`, its view
  // checked against its buffer first.
  const tinygltf::Image& decodeBufferView(int image, const std::string& what, tinygltf::Image& out);

  const tinygltf::Model& model_;
  ImageDecoding& decoding_;
  std::string at_;
  Scene& scene_;
  std::vector<std::string>& warnings_;
  std::map<std::pair<int, bool>, uint32_t> textures_;  // (image, srgb) -> Scene::textures
  std::map<int, TextureSampler> samplers_;
  std::vector<bool> imageUsed_;
};

}  // namespace penumbra::scene::gltf
