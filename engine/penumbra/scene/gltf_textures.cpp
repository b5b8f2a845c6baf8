#include "penumbra/scene/gltf_textures.h"

#include <fmt/format.h>
#include <stb_image.h>
#ifdef PENUMBRA_HAVE_WEBP
#include <webp/decode.h>
#endif

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>

#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {
namespace {

std::string named(const char* kind, size_t index, const std::string& name) {
  return name.empty() ? fmt::format("{} {}", kind, index)
                      : fmt::format("{} {} '{}'", kind, index, name);
}

// tinygltf's Value::Get(key) asserts an object; extensions from a file may be anything.
const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
  return object.IsObject() && object.Has(key) ? &object.Get(key) : nullptr;
}

// A KHR_texture_transform number as a float: a larger one would become
// infinity in the texture transform. `where` names the texture info.
float transformFloat(double value, const char* key, const std::string& where) {
  if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max()))
    throw Error(
        fmt::format("{}: KHR_texture_transform {} {} does not fit a float", where, key, value));
  return float(value);
}

float number(const tinygltf::Value& object, const char* key, float fallback,
             const std::string& where) {
  const auto* v = member(object, key);
  return v && v->IsNumber() ? transformFloat(v->GetNumberAsDouble(), key, where) : fallback;
}

glm::vec2 vec2(const tinygltf::Value& object, const char* key, glm::vec2 fallback,
               const std::string& where) {
  const auto* v = member(object, key);
  if (!v || !v->IsArray() || v->ArrayLen() != 2) return fallback;
  glm::vec2 r;
  for (int i = 0; i < 2; ++i) {
    const auto& c = v->Get(i);
    r[i] = c.IsNumber() ? transformFloat(c.GetNumberAsDouble(), key, where) : fallback[i];
  }
  return r;
}

const tinygltf::Value* textureTransform(const tinygltf::ExtensionMap& extensions) {
  auto it = extensions.find("KHR_texture_transform");
  return it == extensions.end() ? nullptr : &it->second;
}

// The 8-bit value nearest to a 16-bit one: round(v * 255 / 65535).
uint8_t to8(uint16_t v) {
  return uint8_t((uint32_t(v) * 255u + 32767u) / 65535u);
}

// Why an image of this size may not be decoded, from its header: the
// decoder allocates what the header claims, however small the file.
std::optional<std::string> refusedSize(uint64_t width, uint64_t height, ImageDecoding& decoding) {
  const InputLimits& limits = decoding.limits;
  if (width > limits.maxImageSide || height > limits.maxImageSide)
    return fmt::format(
        "its header says {} x {} pixels, more than the limit {} per side "
        "(InputLimits::maxImageSide; docs/security.md)",
        width, height, limits.maxImageSide);
  if (width * height > limits.maxImagePixels)
    return fmt::format(
        "its header says {} x {} pixels, more than the limit {} pixels "
        "(InputLimits::maxImagePixels; docs/security.md)",
        width, height, limits.maxImagePixels);
  if (decoding.pixels + width * height > limits.maxTexturePixels)
    return fmt::format(
        "its {} x {} pixels would bring the file's images to {} pixels, more than the limit {} "
        "(InputLimits::maxTexturePixels; docs/security.md)",
        width, height, decoding.pixels + width * height, limits.maxTexturePixels);
  decoding.pixels += width * height;
  return std::nullopt;
}

// stb_image (Debian's 2022-09 snapshot) copies a zero-length IDAT chunk
// that comes before any image data from a null buffer (memcpy(NULL, p, 0),
// undefined behaviour; found by fuzzing, tests/fuzz/corpus/image/
// finding-png-empty-idat). Such a PNG is legal but pointless; it is refused
// before stb sees it. stb acts on a chunk once its 8-byte header (length,
// type) is read, before its CRC, so the walk looks at every header that fits
// in the file, even one whose CRC is cut off (second finding,
// finding-png-empty-idat-truncated). It stops at the first chunk that
// overruns the file, which stb reports itself.
std::optional<std::string> pngProblem(const unsigned char* bytes, size_t size) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 8 || std::memcmp(bytes, kSignature, 8) != 0) return std::nullopt;
  constexpr size_t kChunkHeader = 8, kChunkCrc = 4;
  size_t at = 8;
  while (size - at >= kChunkHeader) {
    const uint32_t length = uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 |
                            uint32_t(bytes[at + 2]) << 8 | uint32_t(bytes[at + 3]);
    if (std::memcmp(bytes + at + 4, "IDAT", 4) == 0 && length == 0)
      return std::string("a PNG with an empty IDAT chunk (not supported)");
    const uint64_t chunk = uint64_t(kChunkHeader) + length + kChunkCrc;
    if (chunk > size - at) break;
    at += size_t(chunk);
  }
  return std::nullopt;
}

bool isWebp(const unsigned char* bytes, size_t size) {
  return size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0;
}

// A WebP image (EXT_texture_webp) as 8-bit RGBA, once its header's size passes
// the limits. libwebp decodes lossy and lossless files, with or without alpha.
std::optional<std::string> decodeWebpInto(tinygltf::Image& image, const unsigned char* bytes,
                                          size_t size, ImageDecoding& decoding) {
#ifdef PENUMBRA_HAVE_WEBP
  int width = 0, height = 0;
  if (!WebPGetInfo(bytes, size, &width, &height)) return std::string("not a valid WebP image");
  if (auto refused =
          refusedSize(uint64_t(std::max(width, 0)), uint64_t(std::max(height, 0)), decoding))
    return refused;
  uint8_t* pixels = WebPDecodeRGBA(bytes, size, &width, &height);
  if (!pixels) return std::string("the WebP image does not decode");
  image.width = width;
  image.height = height;
  image.component = 4;
  image.bits = 8;
  image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image.image.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
  WebPFree(pixels);
  return std::nullopt;
#else
  (void)image, (void)bytes, (void)size, (void)decoding;
  return std::string("a WebP image, which this build cannot decode (no libwebp)");
#endif
}

// Decodes an encoded image (PNG, JPEG, WebP, ...) into `image` with the
// file's channel count and bit depth, once its header's size passes the
// limits; returns why it failed, or nothing.
std::optional<std::string> decodeInto(tinygltf::Image& image, const unsigned char* bytes,
                                      size_t size, ImageDecoding& decoding) {
  if (size > size_t(INT_MAX)) return "larger than 2 GiB";
  if (isWebp(bytes, size)) return decodeWebpInto(image, bytes, size, decoding);
  const int length = int(size);
  int width = 0, height = 0, components = 0, bits = 8;
  if (auto problem = pngProblem(bytes, size)) return problem;
  // stb_image reads the same header to decode; a file whose header it cannot
  // read here it cannot decode either.
  if (!stbi_info_from_memory(bytes, length, &width, &height, &components)) {
    const char* reason = stbi_failure_reason();
    return std::string(reason ? reason : "unknown image format");
  }
  if (auto refused =
          refusedSize(uint64_t(std::max(width, 0)), uint64_t(std::max(height, 0)), decoding))
    return refused;
  const uint64_t claimed = uint64_t(width) * uint64_t(height);
  void* pixels = nullptr;
  // 16-bit PNGs keep their precision until toRgba8 rounds them.
  if (stbi_is_16_bit_from_memory(bytes, length)) {
    pixels = stbi_load_16_from_memory(bytes, length, &width, &height, &components, 0);
    bits = 16;
  }
  if (!pixels) {
    pixels = stbi_load_from_memory(bytes, length, &width, &height, &components, 0);
    bits = 8;
  }
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    return std::string(reason ? reason : "unknown image format");
  }
  if (uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0)) > claimed) {
    stbi_image_free(pixels);
    return std::string("decodes larger than its header says");
  }
  image.width = width;
  image.height = height;
  image.component = components;
  image.bits = bits;
  image.pixel_type =
      bits == 16 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  const size_t bytesOut = size_t(std::max(width, 0)) * size_t(std::max(height, 0)) *
                          size_t(components) * size_t(bits / 8);
  const auto* first = static_cast<const unsigned char*>(pixels);
  image.image.assign(first, first + bytesOut);
  stbi_image_free(pixels);
  return std::nullopt;
}

}  // namespace

bool decodeImage(tinygltf::Image* image, int index, std::string* /*err*/, std::string* /*warn*/,
                 int /*requiredWidth*/, int /*requiredHeight*/, const unsigned char* bytes,
                 int size, void* decoding) {
  // tinygltf hands over a buffer view's bytes without checking the view
  // against its buffer: TextureImporter decodes those once it has.
  if (image->bufferView >= 0) return true;
  auto& state = *static_cast<ImageDecoding*>(decoding);
  if (auto failure = decodeInto(*image, bytes, size_t(std::max(size, 0)), state))
    state.failures[index] = *failure;
  return true;
}

std::vector<uint8_t> toRgba8(const std::vector<unsigned char>& pixels, uint32_t width,
                             uint32_t height, int components, int bits, const std::string& where) {
  if (components < 1 || components > 4 || (bits != 8 && bits != 16))
    throw Error(fmt::format("{}: {} components of {} bits are not supported (1 to 4 of 8 or 16)",
                            where, components, bits));
  const size_t count = size_t(width) * size_t(height);
  const size_t stride = size_t(components);
  const size_t expected = count * stride * size_t(bits / 8);
  if (pixels.size() != expected)
    throw Error(
        fmt::format("{}: has {} bytes of pixels, {} x {} x {} components of {} bits need {}", where,
                    pixels.size(), width, height, components, bits, expected));
  auto channel = [&](size_t i) -> uint8_t {
    if (bits == 8) return pixels[i];
    uint16_t v;
    std::memcpy(&v, &pixels[2 * i], 2);  // stb_image returns native byte order
    return to8(v);
  };
  std::vector<uint8_t> out(count * 4);
  for (size_t p = 0; p < count; ++p) {
    const size_t in = p * stride;
    uint8_t* texel = &out[p * 4];
    if (components <= 2) {
      texel[0] = texel[1] = texel[2] = channel(in);  // grey
      texel[3] = components == 2 ? channel(in + 1) : 255;
    } else {
      for (size_t c = 0; c < 3; ++c) texel[c] = channel(in + c);
      texel[3] = components == 4 ? channel(in + 3) : 255;
    }
  }
  return out;
}

TextureSampler convertSampler(const tinygltf::Sampler& src, const std::string& where,
                              std::vector<std::string>& warnings) {
  TextureSampler out;
  auto filter = [&](int value, const char* what) {
    switch (value) {
      case -1:  // undefined: the implementation's choice
      case TINYGLTF_TEXTURE_FILTER_LINEAR:
      case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
        return TextureFilter::Linear;
      case TINYGLTF_TEXTURE_FILTER_NEAREST:
      case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
        return TextureFilter::Nearest;
      default:
        warnings.push_back(
            fmt::format("{}: {} {} is not a glTF filter; linear used", where, what, value));
        return TextureFilter::Linear;
    }
  };
  auto wrap = [&](int value, const char* what) {
    switch (value) {
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return TextureWrap::Repeat;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return TextureWrap::MirroredRepeat;
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return TextureWrap::ClampToEdge;
      default:
        warnings.push_back(
            fmt::format("{}: {} {} is not a glTF wrap mode; repeat used", where, what, value));
        return TextureWrap::Repeat;
    }
  };
  // Magnification only knows NEAREST and LINEAR; a mipmapped value there is
  // invalid, but its in-level filter is the evident intent.
  out.magFilter = filter(src.magFilter, "magFilter");
  out.minFilter = filter(src.minFilter, "minFilter");
  switch (src.minFilter) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      out.mipFilter = MipFilter::None;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      out.mipFilter = MipFilter::Nearest;
      break;
    default:
      out.mipFilter = MipFilter::Linear;
  }
  out.wrapU = wrap(src.wrapS, "wrapS");
  out.wrapV = wrap(src.wrapT, "wrapT");
  return out;
}

void setTextureTransform(TextureRef& ref, glm::vec2 offset, float rotation, glm::vec2 scale) {
  // translation * rotation * scale with the extension's rotation
  // [cos sin; -sin cos] (rows): (1, 0) turns towards -v, counter-clockwise
  // as the uv map is drawn (v down). Its example, offset (0, 1), rotation
  // pi/2, scale 0.5, maps the unit square onto the lower-left quadrant.
  const float c = std::cos(rotation), s = std::sin(rotation);
  ref.transform0 = glm::vec2(c, -s) * scale.x;
  ref.transform1 = glm::vec2(s, c) * scale.y;
  ref.transform2 = offset;
}

const std::vector<ExtensionTexture>& extensionTextures() {
  static const std::vector<ExtensionTexture> table{
      {"KHR_materials_clearcoat", "clearcoatTexture", false, &Material::clearcoatTexture},
      {"KHR_materials_clearcoat", "clearcoatRoughnessTexture", false,
       &Material::clearcoatRoughnessTexture},
      {"KHR_materials_clearcoat", "clearcoatNormalTexture", false,
       &Material::clearcoatNormalTexture},
      {"KHR_materials_transmission", "transmissionTexture", false, &Material::transmissionTexture},
      {"KHR_materials_sheen", "sheenColorTexture", true, &Material::sheenColorTexture},
      {"KHR_materials_sheen", "sheenRoughnessTexture", false, &Material::sheenRoughnessTexture},
      {"KHR_materials_specular", "specularTexture", false, &Material::specularTexture},
      {"KHR_materials_specular", "specularColorTexture", true, &Material::specularColorTexture},
      {"KHR_materials_anisotropy", "anisotropyTexture", false, &Material::anisotropyTexture},
      {"KHR_materials_diffuse_transmission", "diffuseTransmissionTexture", false,
       &Material::diffuseTransmissionTexture},
      {"KHR_materials_diffuse_transmission", "diffuseTransmissionColorTexture", true,
       &Material::diffuseTransmissionColorTexture},
      {"KHR_materials_iridescence", "iridescenceTexture", false, &Material::iridescenceTexture},
      {"KHR_materials_iridescence", "iridescenceThicknessTexture", false,
       &Material::iridescenceThicknessTexture}};
  return table;
}

TextureImporter::TextureImporter(const tinygltf::Model& model, ImageDecoding& decoding,
                                 std::string at, Scene& scene, std::vector<std::string>& warnings)
    : model_(model),
      decoding_(decoding),
      at_(std::move(at)),
      scene_(scene),
      warnings_(warnings),
      imageUsed_(model.images.size(), false) {}

void TextureImporter::attach(const tinygltf::Material& src, Material& material,
                             const std::string& where) {
  auto slot = [&](const auto& info, const char* name, bool srgb) {
    if (info.index < 0) return Material::kNoTexture;
    return textureRef(info.index, info.texCoord, textureTransform(info.extensions), srgb,
                      fmt::format("{} {}", where, name));
  };
  const auto& pbr = src.pbrMetallicRoughness;
  // Colours are stored sRGB-encoded (glTF 3.9.2); data textures are linear.
  material.baseColorTexture = slot(pbr.baseColorTexture, "baseColorTexture", true);
  material.metallicRoughnessTexture =
      slot(pbr.metallicRoughnessTexture, "metallicRoughnessTexture", false);
  material.normalTexture = slot(src.normalTexture, "normalTexture", false);
  material.emissiveTexture = slot(src.emissiveTexture, "emissiveTexture", true);
  material.occlusionTexture = slot(src.occlusionTexture, "occlusionTexture", false);
  for (const ExtensionTexture& t : extensionTextures()) {
    const auto ext = src.extensions.find(t.extension);
    if (ext == src.extensions.end() || !ext->second.Get(t.key).IsObject()) continue;
    const tinygltf::Value& info = ext->second.Get(t.key);
    const std::string name = fmt::format("{} {}.{}", where, t.extension, t.key);
    auto whole = [&](const char* what, bool required) -> int {
      const tinygltf::Value& v = info.Get(what);
      if (!v.IsNumber() && !required) return 0;
      const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
      if (!(d >= 0.0 && d <= double(INT_MAX)) || std::floor(d) != d)
        throw Error(fmt::format("{}: {} is not a whole number from 0 to {}", name, what, INT_MAX));
      return int(d);
    };
    const int index = whole("index", true);
    const tinygltf::Value& infoExtensions = info.Get("extensions");
    const tinygltf::Value* transform =
        infoExtensions.IsObject() && infoExtensions.Has("KHR_texture_transform")
            ? &infoExtensions.Get("KHR_texture_transform")
            : nullptr;
    material.*t.slot = textureRef(index, whole("texCoord", false), transform, t.srgb, name);
  }
}

uint32_t TextureImporter::textureRef(int index, int texCoord, const tinygltf::Value* transform,
                                     bool srgb, const std::string& where) {
  if (size_t(index) >= model_.textures.size())
    throw Error(fmt::format("{}: texture {} does not exist ({} textures)", where, index,
                            model_.textures.size()));
  const auto& src = model_.textures[size_t(index)];
  const std::string textureName =
      fmt::format("{} {}", at_, named("texture", size_t(index), src.name));
  TextureRef ref;
  ref.texture = texture(textureSource(src, textureName), srgb, textureName);
  if (src.sampler >= 0) ref.sampler = sampler(src.sampler, textureName);
  if (transform) {
    // The extension's texCoord overrides the texture info's.
    if (const auto* set = member(*transform, "texCoord"); set && set->IsNumber()) {
      // Range first: converting a double outside int's range is undefined.
      const double value = set->GetNumberAsDouble();
      if (!(value >= 0.0 && value <= double(INT_MAX)) || std::floor(value) != value)
        throw Error(fmt::format(
            "{}: KHR_texture_transform texCoord {} is not a texture coordinate set index "
            "(a whole number from 0 to {})",
            where, value, INT_MAX));
      texCoord = int(value);
    }
    setTextureTransform(ref, vec2(*transform, "offset", glm::vec2(0.0f), where),
                        number(*transform, "rotation", 0.0f, where),
                        vec2(*transform, "scale", glm::vec2(1.0f), where));
  }
  ref.texCoord = texCoordSet(texCoord, where);
  scene_.textureRefs.push_back(ref);
  return uint32_t(scene_.textureRefs.size() - 1);
}

int TextureImporter::textureSource(const tinygltf::Texture& src, const std::string& where) const {
#ifdef PENUMBRA_HAVE_WEBP
  // EXT_texture_webp's image is preferred where it is read; `source`, if
  // given, is the fallback for loaders without it.
  const auto ext = src.extensions.find("EXT_texture_webp");
  if (ext != src.extensions.end()) {
    const tinygltf::Value& source = ext->second.Get("source");
    if (!source.IsNumber() || source.GetNumberAsDouble() < 0.0 ||
        source.GetNumberAsDouble() > double(INT_MAX))
      throw Error(fmt::format("{}: EXT_texture_webp has no valid source", where));
    return int(source.GetNumberAsDouble());
  }
#else
  (void)where;
#endif
  return src.source;
}

uint32_t TextureImporter::texCoordSet(int texCoord, const std::string& where) {
  if (texCoord == 0 || texCoord == 1) return uint32_t(texCoord);
  warnings_.push_back(
      fmt::format("{}: texCoord {} is not supported (TEXCOORD_0 and TEXCOORD_1 are); "
                  "TEXCOORD_0 used",
                  where, texCoord));
  return 0;
}

TextureSampler TextureImporter::sampler(int index, const std::string& where) {
  if (size_t(index) >= model_.samplers.size())
    throw Error(fmt::format("{}: sampler {} does not exist ({} samplers)", where, index,
                            model_.samplers.size()));
  auto it = samplers_.find(index);
  if (it != samplers_.end()) return it->second;
  const auto& src = model_.samplers[size_t(index)];
  const TextureSampler converted = convertSampler(
      src, fmt::format("{} {}", at_, named("sampler", size_t(index), src.name)), warnings_);
  return samplers_.emplace(index, converted).first->second;
}

std::string TextureImporter::describeImage(int index) const {
  const auto& image = model_.images[size_t(index)];
  const std::string name = named("image", size_t(index), image.name);
  if (!image.uri.empty()) return fmt::format("{} (file '{}')", name, image.uri);
  if (image.bufferView >= 0) return fmt::format("{} (buffer view {})", name, image.bufferView);
  return fmt::format("{} (data URI)", name);
}

uint32_t TextureImporter::texture(int image, bool srgb, const std::string& where) {
  if (image < 0)
    throw Error(fmt::format(
        "{}: has no source image (images only in extensions, such as KHR_texture_basisu, are "
        "not supported)",
        where));
  if (size_t(image) >= model_.images.size())
    throw Error(fmt::format("{}: source image {} does not exist ({} images)", where, image,
                            model_.images.size()));
  const auto key = std::make_pair(image, srgb);
  if (auto it = textures_.find(key); it != textures_.end()) return it->second;
  imageUsed_[size_t(image)] = true;

  const std::string what = fmt::format("{}: {}", at_, describeImage(image));
  tinygltf::Image fromView;
  const auto& src = model_.images[size_t(image)].bufferView >= 0
                        ? decodeBufferView(image, what, fromView)
                        : model_.images[size_t(image)];
  if (src.image.empty()) {
    // tinygltf only warns about an image file it cannot read; a file that
    // names an image it does not ship is broken.
    auto failure = decoding_.failures.find(image);
    if (failure != decoding_.failures.end())
      throw Error(fmt::format("{} cannot be decoded ({})", what, failure->second));
    if (src.width > 0 && src.height > 0) throw Error(fmt::format("{} has no pixel data", what));
    throw Error(fmt::format("{} cannot be read (missing, empty or unreadable file)", what));
  }
  if (src.width <= 0 || src.height <= 0)
    throw Error(fmt::format("{} has size {} x {}", what, src.width, src.height));

  Texture t;
  t.name = !src.name.empty()  ? src.name
           : !src.uri.empty() ? std::filesystem::path(src.uri).filename().string()
                              : fmt::format("image{}", image);
  t.width = uint32_t(src.width);
  t.height = uint32_t(src.height);
  t.rgba8 = toRgba8(src.image, t.width, t.height, src.component, src.bits, what);
  t.srgb = srgb;
  scene_.textures.push_back(std::move(t));
  return textures_.emplace(key, uint32_t(scene_.textures.size() - 1)).first->second;
}

const tinygltf::Image& TextureImporter::decodeBufferView(int image, const std::string& what,
                                                         tinygltf::Image& out) {
  const int index = model_.images[size_t(image)].bufferView;
  if (size_t(index) >= model_.bufferViews.size())
    throw Error(fmt::format("{}: buffer view {} does not exist ({} buffer views)", what, index,
                            model_.bufferViews.size()));
  const auto& view = model_.bufferViews[size_t(index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
    throw Error(fmt::format("{}: buffer view {} uses buffer {} of {}", what, index, view.buffer,
                            model_.buffers.size()));
  const auto& buffer = model_.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    throw Error(fmt::format("{}: bytes {} to {} lie outside buffer {} ({} bytes)", what,
                            view.byteOffset, view.byteOffset + view.byteLength, view.buffer,
                            buffer.size()));
  if (auto failure = decodeInto(out, buffer.data() + view.byteOffset, view.byteLength, decoding_))
    throw Error(fmt::format("{} cannot be decoded ({})", what, *failure));
  return out;
}

void TextureImporter::warnUnusedBrokenImages() {
  // Images in buffer views are only decoded when used.
  for (size_t i = 0; i < model_.images.size(); ++i)
    if (!imageUsed_[i] && model_.images[i].bufferView < 0 && model_.images[i].image.empty()) {
      auto failure = decoding_.failures.find(int(i));
      warnings_.push_back(fmt::format(
          "{}: {} is not used by any material and cannot be {}; ignored", at_,
          describeImage(int(i)),
          failure == decoding_.failures.end() ? "read" : "decoded (" + failure->second + ")"));
    }
}

}  // namespace penumbra::scene::gltf
