// glTF textures, samplers and texture transforms against hand-made files
// (tests/data/gltf/make_gltf.py writes them and their PNGs). Expected texels
// are the values the generator writes; expected matrices follow the
// KHR_texture_transform specification, evaluated here on their own.
#include <webp/decode.h>
#include <webp/encode.h>

#include <algorithm>
#include <array>
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "gltf_test_files.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/gltf_textures.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"
#include "test_data.h"

using namespace penumbra;
using Catch::Approx;
using Catch::Matchers::ContainsSubstring;

namespace {

using Texel = std::array<int, 4>;

std::string gltf(const std::string& name) {
  return test::dataPath("gltf/" + name);
}

const scene::Material& materialNamed(const scene::Scene& s, const std::string& name) {
  for (const auto& m : s.materials)
    if (m.name == name) return m;
  FAIL("no material " << name);
  throw 0;
}

bool hasWarning(const scene::GltfImport& r, const std::string& part) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

const scene::TextureRef& ref(const scene::Scene& s, uint32_t slot) {
  REQUIRE(slot != scene::Material::kNoTexture);
  REQUIRE(slot < s.textureRefs.size());
  return s.textureRefs[slot];
}

const scene::Texture& texture(const scene::Scene& s, uint32_t slot) {
  const auto& r = ref(s, slot);
  REQUIRE(r.texture < s.textures.size());
  return s.textures[r.texture];
}

Texel texel(const scene::Texture& t, uint32_t x, uint32_t y) {
  REQUIRE(x < t.width);
  REQUIRE(y < t.height);
  const size_t i = (size_t(y) * t.width + x) * 4;
  return {t.rgba8.at(i), t.rgba8.at(i + 1), t.rgba8.at(i + 2), t.rgba8.at(i + 3)};
}

// The 2 x 2 image of textures.gltf and textures.glb (CHECKER_2X2).
void requireChecker2x2(const scene::Texture& t) {
  REQUIRE(t.width == 2u);
  REQUIRE(t.height == 2u);
  REQUIRE(t.rgba8.size() == 16u);
  REQUIRE(texel(t, 0, 0) == Texel{255, 0, 0, 255});
  REQUIRE(texel(t, 1, 0) == Texel{0, 255, 0, 128});
  REQUIRE(texel(t, 0, 1) == Texel{0, 0, 255, 0});
  REQUIRE(texel(t, 1, 1) == Texel{10, 20, 30, 40});
}

// uv' = transform * (u, v, 1) with the reference's columns.
glm::vec2 apply(const scene::TextureRef& r, glm::vec2 uv) {
  return r.transform0 * uv.x + r.transform1 * uv.y + r.transform2;
}

void requireNear(glm::vec2 a, glm::vec2 b, float eps = 1e-6f) {
  INFO("got (" << a.x << ", " << a.y << "), expected (" << b.x << ", " << b.y << ")");
  REQUIRE(glm::length(a - b) <= eps);
}

// A 3x3 matrix from its rows, as the extension writes them.
glm::mat3 rows(glm::vec3 r0, glm::vec3 r1, glm::vec3 r2) {
  return glm::transpose(glm::mat3(r0, r1, r2));
}

// KHR_texture_transform: translation * rotation * scale, rotation
// [cos sin; -sin cos] (rows).
glm::mat3 specMatrix(glm::vec2 offset, float rotation, glm::vec2 scale) {
  const float c = std::cos(rotation), s = std::sin(rotation);
  const glm::mat3 t = rows({1, 0, offset.x}, {0, 1, offset.y}, {0, 0, 1});
  const glm::mat3 r = rows({c, s, 0}, {-s, c, 0}, {0, 0, 1});
  const glm::mat3 k = rows({scale.x, 0, 0}, {0, scale.y, 0}, {0, 0, 1});
  return t * r * k;
}

void requireTransform(const scene::TextureRef& r, const glm::mat3& m) {
  requireNear(r.transform0, glm::vec2(m[0]));
  requireNear(r.transform1, glm::vec2(m[1]));
  requireNear(r.transform2, glm::vec2(m[2]));
  // Affine: the last row is (0, 0, 1).
  REQUIRE(m[0].z == 0.0f);
  REQUIRE(m[1].z == 0.0f);
  REQUIRE(m[2].z == 1.0f);
}

}  // namespace

TEST_CASE("glTF texture images decode to the RGBA8 texels written", "[gltf]") {
  const auto r = scene::importGltf(gltf("textures.gltf"));
  const auto& s = r.scene;
  // An external PNG file (textures_rgba.png).
  requireChecker2x2(texture(s, materialNamed(s, "painted").baseColorTexture));
  REQUIRE(texture(s, materialNamed(s, "painted").baseColorTexture).name == "checker");
  // Textures are now read: no "not supported" warning, and the extension is supported.
  REQUIRE_FALSE(hasWarning(r, "not supported yet"));
  REQUIRE_FALSE(hasWarning(r, "KHR_texture_transform"));
}

TEST_CASE("glTF grey, grey-alpha, rgb and 16-bit PNGs become RGBA8", "[gltf]") {
  const auto s = scene::loadGltf(gltf("textures.gltf"));
  // Grey 8-bit 3 x 1: replicated into rgb, alpha 255.
  const auto& grey = texture(s, materialNamed(s, "grey").baseColorTexture);
  REQUIRE(grey.width == 3u);
  REQUIRE(grey.height == 1u);
  REQUIRE(texel(grey, 0, 0) == Texel{0, 0, 0, 255});
  REQUIRE(texel(grey, 1, 0) == Texel{128, 128, 128, 255});
  REQUIRE(texel(grey, 2, 0) == Texel{255, 255, 255, 255});
  // Grey + alpha: (50, 100), (200, 250).
  const auto& greyAlpha = texel(texture(s, materialNamed(s, "greyAlpha").baseColorTexture), 1, 0);
  REQUIRE(greyAlpha == Texel{200, 200, 200, 250});
  REQUIRE(texel(texture(s, materialNamed(s, "greyAlpha").baseColorTexture), 0, 0) ==
          Texel{50, 50, 50, 100});
  // RGB 1 x 2: alpha 255; the second row is texel (0, 1).
  const auto& rgb = texture(s, materialNamed(s, "rgb").baseColorTexture);
  REQUIRE(rgb.width == 1u);
  REQUIRE(rgb.height == 2u);
  REQUIRE(texel(rgb, 0, 0) == Texel{1, 2, 3, 255});
  REQUIRE(texel(rgb, 0, 1) == Texel{250, 251, 252, 255});
  // RGBA 16-bit, rounded: 65535 -> 255; 25829 * 255 / 65535 = 100.502 -> 101
  // (the high byte alone would be 100); 25828 -> 100.498 -> 100; 0 -> 0;
  // 257 -> 1; 32768 -> 127.502 -> 128; 32767 -> 127.498 -> 127.
  const auto& rgba16 = texture(s, materialNamed(s, "rgba16").baseColorTexture);
  REQUIRE(texel(rgba16, 0, 0) == Texel{255, 101, 100, 0});
  REQUIRE(texel(rgba16, 1, 0) == Texel{1, 128, 127, 255});
  // Grey 16-bit: 25829 -> 101.
  REQUIRE(texel(texture(s, materialNamed(s, "grey16").baseColorTexture), 0, 0) ==
          Texel{101, 101, 101, 255});
}

TEST_CASE("toRgba8 converts every layout and rejects bad ones", "[gltf]") {
  // 16-bit values in native byte order, as stb_image returns them.
  const uint16_t grey16[] = {25829, 65535};
  std::vector<unsigned char> bytes(sizeof grey16);
  std::memcpy(bytes.data(), grey16, sizeof grey16);
  REQUIRE(scene::gltf::toRgba8(bytes, 1, 1, 2, 16, "t") ==
          std::vector<uint8_t>{101, 101, 101, 255});
  REQUIRE(scene::gltf::toRgba8({7, 8, 9}, 1, 1, 3, 8, "t") == std::vector<uint8_t>{7, 8, 9, 255});
  REQUIRE_THROWS_WITH(scene::gltf::toRgba8({1, 2, 3}, 2, 1, 3, 8, "img"),
                      ContainsSubstring("img: has 3 bytes"));
  REQUIRE_THROWS_WITH(scene::gltf::toRgba8({1}, 1, 1, 1, 4, "img"),
                      ContainsSubstring("not supported"));
}

TEST_CASE("glTF textures: one per image and colour space, sRGB for colour", "[gltf]") {
  const auto s = scene::loadGltf(gltf("textures.gltf"));
  const auto& painted = materialNamed(s, "painted");
  // Base colour and emission read the checker as sRGB; metallic-roughness,
  // normal and occlusion as linear data: two textures of one image.
  const auto& base = ref(s, painted.baseColorTexture);
  REQUIRE(s.textures[base.texture].srgb);
  REQUIRE(ref(s, painted.emissiveTexture).texture == base.texture);
  const auto& data = ref(s, painted.metallicRoughnessTexture);
  REQUIRE(data.texture != base.texture);
  REQUIRE_FALSE(s.textures[data.texture].srgb);
  requireChecker2x2(s.textures[data.texture]);
  REQUIRE(ref(s, painted.normalTexture).texture == data.texture);
  REQUIRE(ref(s, painted.occlusionTexture).texture == data.texture);
  // glTF textures 0, 1 and 2 all show image 0: still two scene textures.
  REQUIRE(ref(s, materialNamed(s, "transformed").baseColorTexture).texture == base.texture);
  REQUIRE(std::count_if(s.textures.begin(), s.textures.end(),
                        [](const scene::Texture& t) { return t.name == "checker"; }) == 2);
  // The checker twice, grey, greyAlpha twice (sRGB as a base colour, linear
  // as 'layered''s specular strength), rgb, rgba16, grey16.
  REQUIRE(s.textures.size() == 8u);
  // Slots a material gives no texture stay empty.
  const auto& coated = materialNamed(s, "coated");
  for (uint32_t slot : {coated.baseColorTexture, coated.metallicRoughnessTexture,
                        coated.normalTexture, coated.emissiveTexture, coated.occlusionTexture,
                        coated.sheenColorTexture, coated.transmissionTexture})
    REQUIRE(slot == scene::Material::kNoTexture);
}

TEST_CASE("glTF samplers map onto filters and wrap modes", "[gltf]") {
  using F = scene::TextureFilter;
  using M = scene::MipFilter;
  using W = scene::TextureWrap;
  const auto s = scene::loadGltf(gltf("textures.gltf"));
  // Sampler 0: NEAREST, NEAREST_MIPMAP_LINEAR (-> nearest, linear between
  // levels), CLAMP_TO_EDGE, MIRRORED_REPEAT.
  const auto& a = ref(s, materialNamed(s, "painted").baseColorTexture).sampler;
  REQUIRE(a.magFilter == F::Nearest);
  REQUIRE(a.minFilter == F::Nearest);
  REQUIRE(a.mipFilter == M::Linear);
  REQUIRE(a.wrapU == W::ClampToEdge);
  REQUIRE(a.wrapV == W::MirroredRepeat);
  // Sampler 1: LINEAR, LINEAR_MIPMAP_NEAREST (-> linear, the nearest
  // level), MIRRORED_REPEAT, REPEAT.
  const auto& b = ref(s, materialNamed(s, "transformed").baseColorTexture).sampler;
  REQUIRE(b.magFilter == F::Linear);
  REQUIRE(b.minFilter == F::Linear);
  REQUIRE(b.mipFilter == M::Nearest);
  REQUIRE(b.wrapU == W::MirroredRepeat);
  REQUIRE(b.wrapV == W::Repeat);
  // No sampler, and an empty sampler: repeat, filters undefined -> linear,
  // trilinear between levels.
  const scene::TextureSampler defaults{F::Linear, F::Linear, M::Linear, W::Repeat, W::Repeat};
  REQUIRE(ref(s, materialNamed(s, "painted").metallicRoughnessTexture).sampler == defaults);
  REQUIRE(ref(s, materialNamed(s, "grey").baseColorTexture).sampler == defaults);
  // Sampler 3: only minFilter NEAREST_MIPMAP_NEAREST.
  const auto& c = ref(s, materialNamed(s, "greyAlpha").baseColorTexture).sampler;
  REQUIRE(c.magFilter == F::Linear);
  REQUIRE(c.minFilter == F::Nearest);
  REQUIRE(c.mipFilter == M::Nearest);
  REQUIRE(c.wrapU == W::Repeat);
}

TEST_CASE("KHR_texture_transform composes translation, rotation and scale as specified", "[gltf]") {
  const auto s = scene::loadGltf(gltf("textures.gltf"));
  const auto& transformed = materialNamed(s, "transformed");
  // offset (0.25, -0.5), rotation 0.5, scale (2, 3); its texCoord 1
  // overrides the texture info's 0.
  const auto& base = ref(s, transformed.baseColorTexture);
  requireTransform(base, specMatrix({0.25f, -0.5f}, 0.5f, {2.0f, 3.0f}));
  REQUIRE(base.texCoord == 1u);
  // A point through it: u' = 2 cos(0.5) u + 3 sin(0.5) v + 0.25,
  // v' = -2 sin(0.5) u + 3 cos(0.5) v - 0.5.
  const float c = std::cos(0.5f), sn = std::sin(0.5f);
  requireNear(apply(base, {0.5f, 0.25f}),
              {2 * c * 0.5f + 3 * sn * 0.25f + 0.25f, -2 * sn * 0.5f + 3 * c * 0.25f - 0.5f});

  // Rotation by 90 degrees alone: counter-clockwise in uv space (v down),
  // (1, 0) -> (0, -1) and (0, 1) -> (1, 0).
  const auto& emissive = ref(s, transformed.emissiveTexture);
  requireNear(apply(emissive, {1, 0}), {0, -1});
  requireNear(apply(emissive, {0, 1}), {1, 0});
  REQUIRE(emissive.texCoord == 0u);

  // Without the extension: the identity.
  const auto& plain = ref(s, materialNamed(s, "painted").baseColorTexture);
  REQUIRE(plain.transform0 == glm::vec2(1, 0));
  REQUIRE(plain.transform1 == glm::vec2(0, 1));
  REQUIRE(plain.transform2 == glm::vec2(0, 0));

  // The extension's example: offset (0, 1), rotation pi/2, scale 0.5 uses
  // "the lower left quadrant of the source image": the unit square's
  // corners land on (0, 1), (0, 0.5), (0.5, 0.5), (0.5, 1).
  scene::TextureRef example;
  scene::gltf::setTextureTransform(example, {0.0f, 1.0f}, 1.57079632679f, {0.5f, 0.5f});
  requireNear(apply(example, {0, 0}), {0, 1});
  requireNear(apply(example, {1, 0}), {0, 0.5f});
  requireNear(apply(example, {1, 1}), {0.5f, 0.5f});
  requireNear(apply(example, {0, 1}), {0.5f, 1});
}

TEST_CASE("glTF texCoord sets: TEXCOORD_1 is loaded, others fall back to 0", "[gltf]") {
  const auto r = scene::importGltf(gltf("textures.gltf"));
  const auto& s = r.scene;
  REQUIRE(s.meshes.size() == 2u);
  // Primitive 0 has TEXCOORD_1 (0.25, 0.75) (0.75, 0.75) (0.75, 0.25) (0.25, 0.25).
  const auto& painted = s.meshes[0];
  REQUIRE(painted.uv1.size() == 4u);
  REQUIRE(painted.uv1[0] == glm::vec2(0.25f, 0.75f));
  REQUIRE(painted.uv1[2] == glm::vec2(0.75f, 0.25f));
  REQUIRE(painted.uv0[0] == glm::vec2(0.0f, 1.0f));
  REQUIRE(ref(s, materialNamed(s, "painted").occlusionTexture).texCoord == 1u);
  // Primitive 1 has none, while its material reads set 1: a warning.
  REQUIRE(s.meshes[1].uv1.empty());
  REQUIRE(hasWarning(r, "primitive 1: material 'transformed' reads TEXCOORD_1"));
  REQUIRE_FALSE(hasWarning(r, "primitive 0: material"));
  // texCoord 5: warned about, TEXCOORD_0 used.
  REQUIRE(ref(s, materialNamed(s, "transformed").metallicRoughnessTexture).texCoord == 0u);
  REQUIRE(hasWarning(r, "'transformed' metallicRoughnessTexture: texCoord 5 is not supported"));
}

TEST_CASE("glTF alpha modes, normal scale and occlusion strength", "[gltf]") {
  const auto r = scene::importGltf(gltf("textures.gltf"));
  const auto& s = r.scene;
  const auto& painted = materialNamed(s, "painted");
  REQUIRE(painted.alphaMode == scene::AlphaMode::Mask);
  REQUIRE(painted.alphaCutoff == Approx(0.3f));
  REQUIRE(painted.alpha == Approx(0.2f));
  // Its factor alpha is below the cutoff, but the texture's alpha varies
  // across the surface: the primitive is kept for the renderer to cut.
  REQUIRE(s.materials[s.meshes[0].material].name == "painted");
  REQUIRE(painted.normalScale == Approx(0.75f));
  REQUIRE(painted.occlusionStrength == Approx(0.25f));
  // Defaults.
  const auto& transformed = materialNamed(s, "transformed");
  REQUIRE(transformed.alphaMode == scene::AlphaMode::Opaque);
  REQUIRE(transformed.alpha == 1.0f);
  REQUIRE(transformed.alphaCutoff == 0.5f);
  REQUIRE(transformed.normalScale == 1.0f);
  REQUIRE(transformed.occlusionStrength == 1.0f);
  // BLEND is kept (the renderer treats alpha as coverage), without a warning.
  REQUIRE(materialNamed(s, "blend").alphaMode == scene::AlphaMode::Blend);
  for (const auto& w : r.warnings) REQUIRE(w.find("BLEND") == std::string::npos);
}

TEST_CASE("glTF KHR_materials_* textures fill their slots; unread ones are warned about",
          "[gltf]") {
  const auto r = scene::importGltf(gltf("textures.gltf"));
  const auto& s = r.scene;
  // 'coated': clearcoat, its roughness and its normal map from texture 1
  // (image 0), linear; the normal map reads TEXCOORD_1, scaled by 0.6. The
  // volume's thickness texture is not read.
  const auto& coated = materialNamed(s, "coated");
  CHECK(coated.clearcoat == Approx(0.5f));
  for (uint32_t slot :
       {coated.clearcoatTexture, coated.clearcoatRoughnessTexture, coated.clearcoatNormalTexture}) {
    requireChecker2x2(texture(s, slot));
    CHECK_FALSE(texture(s, slot).srgb);
  }
  CHECK(ref(s, coated.clearcoatNormalTexture).texCoord == 1u);
  CHECK(coated.clearcoatNormalScale == Approx(0.6f));
  CHECK(materialNamed(s, "layered").clearcoatNormalScale == 1.0f);
  CHECK_FALSE(hasWarning(r, "KHR_materials_clearcoat textures"));
  CHECK(hasWarning(r,
                   "material 8 'coated': KHR_materials_volume textures "
                   "(thicknessTexture) are not supported; factors used"));
  // 'layered': sheen and specular colour are colours (sRGB), the specular
  // strength and transmission data; the transmission's texCoord and
  // transform are its own.
  const auto& layered = materialNamed(s, "layered");
  CHECK(texture(s, layered.sheenColorTexture).srgb);
  CHECK(texture(s, layered.specularColorTexture).srgb);
  CHECK_FALSE(texture(s, layered.specularTexture).srgb);
  CHECK_FALSE(texture(s, layered.transmissionTexture).srgb);
  CHECK(texture(s, layered.sheenColorTexture).name ==
        texture(s, materialNamed(s, "grey").baseColorTexture).name);
  CHECK(texture(s, layered.specularTexture).name ==
        texture(s, materialNamed(s, "greyAlpha").baseColorTexture).name);
  CHECK(texture(s, layered.specularColorTexture).name ==
        texture(s, materialNamed(s, "rgb").baseColorTexture).name);
  const auto& transmission = ref(s, layered.transmissionTexture);
  CHECK(transmission.texCoord == 1u);
  CHECK(transmission.transform2 == glm::vec2(0.5f, 0.0f));
  CHECK(transmission.transform0 == glm::vec2(1.0f, 0.0f));
  CHECK(layered.specTrans == Approx(1.0f));
  // The sheen roughness texture (its alpha scales the roughness) is linear.
  CHECK_FALSE(texture(s, layered.sheenRoughnessTexture).srgb);
  CHECK(texture(s, layered.sheenRoughnessTexture).name ==
        texture(s, materialNamed(s, "coated").clearcoatTexture).name);
  CHECK_FALSE(hasWarning(r, "KHR_materials_sheen textures"));
  CHECK_FALSE(hasWarning(r, "KHR_materials_specular textures"));
  CHECK_FALSE(hasWarning(r, "KHR_materials_transmission textures"));
  // KHR_materials_diffuse_transmission: the factor's texture (alpha) is
  // data, the colour's sRGB.
  CHECK(layered.diffuseTransmission == Approx(0.25f));
  CHECK(layered.diffuseTransmissionColor == glm::vec3(0.5f, 1.0f, 1.0f));
  CHECK_FALSE(texture(s, layered.diffuseTransmissionTexture).srgb);
  CHECK(texture(s, layered.diffuseTransmissionTexture).name ==
        texture(s, materialNamed(s, "greyAlpha").baseColorTexture).name);
  CHECK(texture(s, layered.diffuseTransmissionColorTexture).srgb);
  CHECK(texture(s, layered.diffuseTransmissionColorTexture).name ==
        texture(s, materialNamed(s, "rgb").baseColorTexture).name);
  CHECK_FALSE(hasWarning(r, "KHR_materials_diffuse_transmission"));
  // 'brushed': KHR_materials_anisotropy's strength, its rotation brought
  // into (-pi, pi] (7 rad is 7 - 2 pi), and its direction texture, linear,
  // reading TEXCOORD_1.
  const auto& brushed = materialNamed(s, "brushed");
  CHECK(brushed.anisotropyStrength == Approx(0.6f));
  CHECK(brushed.anisotropyRotation == Approx(7.0 - 2.0 * std::numbers::pi));
  requireChecker2x2(texture(s, brushed.anisotropyTexture));
  CHECK_FALSE(texture(s, brushed.anisotropyTexture).srgb);
  CHECK(ref(s, brushed.anisotropyTexture).texCoord == 1u);
  CHECK_FALSE(hasWarning(r, "KHR_materials_anisotropy"));
  // ...and a thin film (KHR_materials_iridescence): its factors, and both
  // textures as data (the factor's red, the thickness's green), each a
  // texture the file already reads as data (the count above stays).
  CHECK(brushed.iridescence == Approx(0.7f));
  CHECK(brushed.iridescenceIor == Approx(1.8f));
  CHECK(brushed.iridescenceThicknessMinimum == 50.0f);
  CHECK(brushed.iridescenceThicknessMaximum == 600.0f);
  CHECK_FALSE(texture(s, brushed.iridescenceTexture).srgb);
  CHECK(texture(s, brushed.iridescenceTexture).name ==
        texture(s, materialNamed(s, "greyAlpha").baseColorTexture).name);
  requireChecker2x2(texture(s, brushed.iridescenceThicknessTexture));
  CHECK_FALSE(texture(s, brushed.iridescenceThicknessTexture).srgb);
  CHECK(ref(s, brushed.iridescenceThicknessTexture).texCoord == 1u);
  CHECK_FALSE(hasWarning(r, "KHR_materials_iridescence"));
  // Its defaults: index 1.3, 100 to 400 nm.
  CHECK(materialNamed(s, "layered").iridescence == 0.0f);
  CHECK(materialNamed(s, "layered").iridescenceIor == 1.3f);
  CHECK(materialNamed(s, "layered").iridescenceThicknessMinimum == 100.0f);
  CHECK(materialNamed(s, "layered").iridescenceThicknessMaximum == 400.0f);
}

TEST_CASE("glTF images in a .glb buffer view and in data URIs", "[gltf]") {
  const auto glb = scene::loadGltf(gltf("textures.glb"));
  REQUIRE(glb.textures.size() == 1u);
  requireChecker2x2(texture(glb, materialNamed(glb, "painted").baseColorTexture));

  // textured.gltf: a 2 x 2 data URI (red, green / blue, white) on a
  // triangle without TEXCOORD_0.
  const auto r = scene::importGltf(gltf("textured.gltf"));
  const auto& t = texture(r.scene, r.scene.materials[0].baseColorTexture);
  REQUIRE(texel(t, 0, 0) == Texel{255, 0, 0, 255});
  REQUIRE(texel(t, 1, 0) == Texel{0, 255, 0, 255});
  REQUIRE(texel(t, 0, 1) == Texel{0, 0, 255, 255});
  REQUIRE(texel(t, 1, 1) == Texel{255, 255, 255, 255});
  REQUIRE(r.scene.materials[0].baseColor == glm::vec3(0.5f));
  REQUIRE(hasWarning(r, "material 'painted' reads TEXCOORD_0, which the primitive does not have"));
}

TEST_CASE("the renderer's textured quad", "[gltf]") {
  const auto r = scene::importGltf(gltf("textured_quad.gltf"));
  REQUIRE(r.warnings.empty());
  const auto& s = r.scene;
  REQUIRE(s.meshes.size() == 1u);
  REQUIRE(s.cameras.empty());
  const auto& mesh = s.meshes[0];
  REQUIRE(mesh.positions == std::vector<glm::vec3>{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  REQUIRE(mesh.uv0 == std::vector<glm::vec2>{{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  // The file's two triangles in the loader's Morton order (triangle_order.h),
  // worked by hand: (0, 1, 2) has its centroid at the high end of x and the
  // low end of y, (0, 2, 3) the reverse; x holds the higher bit of each
  // Morton triple, so (0, 2, 3) comes first.
  REQUIRE(mesh.indices == std::vector<uint32_t>{0, 2, 3, 0, 1, 2});
  for (const auto& n : mesh.normals) REQUIRE(n == glm::vec3(0, 0, 1));
  for (const auto& t : mesh.tangents) REQUIRE(t == glm::vec4(1, 0, 0, 1));
  const auto& m = s.materials[mesh.material];
  REQUIRE(m.baseColor == glm::vec3(0.0f));
  REQUIRE(m.emission == glm::vec3(1.0f));
  REQUIRE(m.baseColorTexture == scene::Material::kNoTexture);
  const auto& emissive = ref(s, m.emissiveTexture);
  // minFilter NEAREST: no mipmapping.
  REQUIRE(emissive.sampler ==
          scene::TextureSampler{scene::TextureFilter::Nearest, scene::TextureFilter::Nearest,
                                scene::MipFilter::None, scene::TextureWrap::ClampToEdge,
                                scene::TextureWrap::ClampToEdge});
  const auto& checker = s.textures[emissive.texture];
  REQUIRE(checker.srgb);
  REQUIRE(checker.width == 4u);
  REQUIRE(checker.height == 4u);
  // Texel (x, y): (levels[x], levels[y], 255 if x + y is odd else 0, 255).
  const int levels[] = {0, 85, 170, 255};
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      REQUIRE(texel(checker, x, y) == Texel{levels[x], levels[y], (x + y) % 2 ? 255 : 0, 255});
}

TEST_CASE("the renderer's alpha-masked quad", "[gltf]") {
  const auto r = scene::importGltf(gltf("alpha_mask_quad.gltf"));
  REQUIRE(r.warnings.empty());
  const auto& s = r.scene;
  REQUIRE(s.meshes.size() == 1u);
  const auto& m = s.materials[s.meshes[0].material];
  REQUIRE(m.alphaMode == scene::AlphaMode::Mask);
  REQUIRE(m.alphaCutoff == 0.5f);
  REQUIRE(m.alpha == 1.0f);
  const auto& base = ref(s, m.baseColorTexture);
  REQUIRE(base.sampler.magFilter == scene::TextureFilter::Nearest);
  REQUIRE(base.sampler.minFilter == scene::TextureFilter::Nearest);
  const auto& t = s.textures[base.texture];
  REQUIRE(t.srgb);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      REQUIRE(texel(t, x, y) == Texel{128, 128, 128, (x + y) % 2 ? 0 : 255});
}

TEST_CASE("bad glTF textures give one clear error naming the file", "[gltf]") {
  struct Case {
    const char* file;
    const char* part;
  };
  const Case cases[] = {
      {"invalid_missing_image.gltf", "image 0 (file 'missing.png') cannot be read"},
      {"invalid_undecodable_image.gltf", "image 0 (file 'undecodable.png') cannot be decoded"},
      {"invalid_empty_image.gltf", "empty.png"},
      {"invalid_texture_source.gltf", "texture 0: source image 3 does not exist (1 images)"},
      {"invalid_texture_no_source.gltf", "texture 0: has no source image"},
      {"invalid_texture_index.gltf", "baseColorTexture: texture 4 does not exist (1 textures)"},
      {"invalid_image_view.glb",
       "image 0 (buffer view 2): bytes 44 to 1114 lie outside buffer 0 (114 bytes)"},
  };
  for (const auto& c : cases) {
    INFO(c.file);
    try {
      scene::importGltf(gltf(c.file));
      FAIL("no error");
    } catch (const Error& e) {
      const std::string message = e.what();
      INFO(message);
      REQUIRE(message.find(c.file) != std::string::npos);
      REQUIRE(message.find(c.part) != std::string::npos);
      REQUIRE(message.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("scene validation checks textures and texture references", "[gltf]") {
  const auto good = scene::loadGltf(gltf("textures.gltf"));
  REQUIRE_NOTHROW(scene::validate(good));
  auto broken = [&](auto change) {
    scene::Scene s = good;
    change(s);
    return s;
  };
  REQUIRE_THROWS_WITH(
      scene::validate(broken([](scene::Scene& s) { s.textures[0].rgba8.pop_back(); })),
      ContainsSubstring("texture 0 'checker' is 2 x 2 but has 15 bytes"));
  REQUIRE_THROWS_WITH(scene::validate(broken([](scene::Scene& s) { s.textures[1].width = 0; })),
                      ContainsSubstring("texture 1"));
  REQUIRE_THROWS_WITH(
      scene::validate(broken([](scene::Scene& s) { s.textureRefs[0].texture = 99; })),
      ContainsSubstring("texture reference 0 uses texture 99 of 8"));
  REQUIRE_THROWS_WITH(
      scene::validate(broken([](scene::Scene& s) { s.textureRefs[2].transform1.y = NAN; })),
      ContainsSubstring("texture reference 2 has a non-finite texture transform"));
  REQUIRE_THROWS_WITH(
      scene::validate(broken([](scene::Scene& s) { s.materials[0].normalTexture = 1000; })),
      ContainsSubstring("material 'painted' uses texture reference 1000"));
  REQUIRE_THROWS_WITH(scene::validate(broken([](scene::Scene& s) { s.meshes[0].uv1.pop_back(); })),
                      ContainsSubstring("has 3 second texture coordinates for 4 vertices"));
}

// Image sizes come from the headers and are checked before decoding
// (scene/input_limits.h, docs/security.md): stb_image allocates what a header
// claims, so a few hundred bytes could ask for gigabytes.
namespace {

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

constexpr const char* kTexturedMaterial =
    R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";

}  // namespace

TEST_CASE("glTF images whose headers claim too many pixels are refused undecoded", "[gltf]") {
  test::TempFolder folder("gltf-images");
  folder.write("tri.bin", test::trianglePositions());
  // A 26-byte PSD header claiming 16384 x 16384 (1 GiB of RGBA8), a 190-byte
  // TGA claiming 16000 x 16000 (stb_image took seconds and gigabytes to fill
  // it from nothing) and one 20000 pixels wide.
  folder.write("big.psd", test::psdHeader(16384, 16384));
  folder.write("big.tga", test::tgaHeader(16000, 16000));
  folder.write("wide.tga", test::tgaHeader(20000, 1));
  struct Case {
    const char* image;
    const char* reason;
  };
  const Case cases[] = {
      {"big.psd",
       "image 0 (file 'big.psd') cannot be decoded (its header says 16384 x 16384 pixels, more "
       "than the limit 67108864 pixels (InputLimits::maxImagePixels"},
      {"big.tga",
       "image 0 (file 'big.tga') cannot be decoded (its header says 16000 x 16000 pixels, more "
       "than the limit 67108864 pixels (InputLimits::maxImagePixels"},
      {"wide.tga",
       "image 0 (file 'wide.tga') cannot be decoded (its header says 20000 x 1 pixels, more than "
       "the limit 16384 per side (InputLimits::maxImageSide"},
  };
  for (const auto& c : cases) {
    INFO(c.image);
    const std::string path =
        folder.write("image.gltf", test::triangleGltf("tri.bin", kTexturedMaterial,
                                                      std::string(R"({"uri":")") + c.image + "\"}",
                                                      R"({"source":0})"));
    CHECK_THAT(test::gltfRefusal(path), ContainsSubstring(c.reason));
  }
  // The same PSD in a .glb's binary chunk, decoded by the importer itself.
  const std::string psd = test::psdHeader(16384, 16384);
  const std::string json =
      R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" + std::to_string(36 + psd.size()) +
      R"(}],
      "bufferViews":[{"buffer":0,"byteLength":36},
                     {"buffer":0,"byteOffset":36,"byteLength":)" +
      std::to_string(psd.size()) + R"(}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
      "materials":[)" +
      kTexturedMaterial +
      R"(],"images":[{"bufferView":1,"mimeType":"image/png"}],"textures":[{"source":0}],
      "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
  const std::string glb =
      folder.write("image.glb", test::glb(json, test::trianglePositions() + psd));
  CHECK_THAT(test::gltfRefusal(glb),
             ContainsSubstring("image 0 (buffer view 1) cannot be decoded (its "
                               "header says 16384 x 16384 pixels") &&
                 ContainsSubstring("InputLimits::maxImagePixels"));
}

TEST_CASE("glTF image limits: an image at the limit loads, one pixel more does not", "[gltf]") {
  // textured_quad.gltf's one image is 4 x 4.
  struct Case {
    uint64_t scene::InputLimits::*limit;
    uint64_t needed;
    const char* message;
  };
  const Case cases[] = {
      {&scene::InputLimits::maxImageSide, 4, "the limit 3 per side (InputLimits::maxImageSide"},
      {&scene::InputLimits::maxImagePixels, 16, "the limit 15 pixels (InputLimits::maxImagePixels"},
      {&scene::InputLimits::maxTexturePixels, 16,
       "bring the file's images to 16 pixels, more than the limit 15 "
       "(InputLimits::maxTexturePixels"},
  };
  for (const auto& c : cases) {
    INFO(c.message);
    scene::InputLimits limits;
    limits.*c.limit = c.needed;
    const auto s = scene::importGltf(gltf("textured_quad.gltf"), {}, limits).scene;
    REQUIRE(s.textures.size() == 1u);
    CHECK(s.textures[0].width == 4u);
    limits.*c.limit = c.needed - 1;
    CHECK_THAT(test::gltfRefusal(gltf("textured_quad.gltf"), limits),
               ContainsSubstring(
                   "image 0 'checker' (file 'textured_quad_checker.png') cannot be decoded") &&
                   ContainsSubstring(c.message));
  }
}

TEST_CASE("KHR_texture_transform numbers out of range are refused naming the texture info",
          "[gltf]") {
  test::TempFolder folder("gltf-transform");
  folder.write("tri.bin", test::trianglePositions());
  folder.write("checker.png", fileBytes(gltf("textured_quad_checker.png")));
  auto withTransform = [&](const std::string& transform) {
    return folder.write(
        "transform.gltf",
        test::triangleGltf("tri.bin",
                           R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0,
                               "extensions":{"KHR_texture_transform":)" +
                               transform + "}}}}",
                           R"({"uri":"checker.png"})", R"({"source":0})"));
  };
  // texCoord 1e30 was converted to int: undefined behaviour.
  for (const char* texCoord : {"1e30", "-1", "1.5"}) {
    INFO(texCoord);
    CHECK_THAT(test::gltfRefusal(withTransform(std::string(R"({"texCoord":)") + texCoord + "}")),
               ContainsSubstring("material 0 baseColorTexture: KHR_texture_transform texCoord") &&
                   ContainsSubstring("is not a texture coordinate set index"));
  }
  // Past a float: an infinite texture transform.
  CHECK_THAT(test::gltfRefusal(withTransform(R"({"offset":[1e39,0]})")),
             ContainsSubstring("baseColorTexture: KHR_texture_transform offset 1e+39 does not fit "
                               "a float"));
  CHECK_THAT(test::gltfRefusal(withTransform(R"({"rotation":-1e300})")),
             ContainsSubstring("KHR_texture_transform rotation -1e+300 does not fit a float"));
  // In range, texCoord 1 is used, and 7 falls back to 0 with a warning as before.
  const auto one = scene::importGltf(withTransform(R"({"texCoord":1,"scale":[2,2]})"));
  REQUIRE(one.scene.textureRefs.size() == 1u);
  CHECK(one.scene.textureRefs[0].texCoord == 1u);
  const auto seven = scene::importGltf(withTransform(R"({"texCoord":7})"));
  CHECK(seven.scene.textureRefs[0].texCoord == 0u);
  CHECK(hasWarning(seven, "texCoord 7 is not supported"));
}

namespace {

// Decodes `bytes` as glTF image `index`: no pixels, and one failure that
// says `reason`.
void checkRefusedBeforeDecoding(const unsigned char* bytes, size_t size, int index,
                                const char* reason) {
  tinygltf::Image image;
  scene::gltf::ImageDecoding decoding;
  std::string error, warning;
  scene::gltf::decodeImage(&image, index, &error, &warning, 0, 0, bytes, int(size), &decoding);
  CHECK(image.image.empty());
  REQUIRE(decoding.failures.count(index) == 1);
  CHECK_THAT(decoding.failures[index], ContainsSubstring(reason));
}

}  // namespace

// A fuzz finding (tests/fuzz/corpus/image/finding-png-empty-idat): a PNG
// whose first IDAT chunk is empty made stb_image memcpy from a null pointer
// (undefined behaviour; the sanitizer build aborts on it). Penumbra refuses
// such a PNG before stb sees it, naming why.
TEST_CASE("a PNG with an empty IDAT chunk is refused before decoding", "[gltf]") {
  const unsigned char png[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
      0x52, 0x00, 0x00, 0x01, 0x04, 0x00, 0x00, 0x00, 0x04, 0x08, 0x06, 0x00, 0x00, 0x00, 0x68,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x15, 0xcb,
      0x81, 0x09, 0x00, 0x00, 0x08, 0x02, 0xc1, 0x5f, 0xb2, 0x25, 0x5d, 0xf2, 0x53, 0x08, 0x8c,
      0xbc, 0x00, 0x3c, 0x34, 0x4d, 0x37, 0x9c, 0x5e, 0x2f, 0x69, 0xae, 0x81, 0x54, 0xa4, 0x22,
      0x63, 0x13, 0x2b, 0x6a, 0xbb, 0xbb, 0x9f, 0x07, 0xb3, 0xc8, 0x27, 0xd9, 0x90, 0xe6, 0x4a,
      0xa1, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  checkRefusedBeforeDecoding(png, sizeof(png), 3, "empty IDAT chunk");
}

// The second finding (finding-png-empty-idat-truncated): the same empty IDAT
// chunk as the file's last bytes, its CRC cut off. stb acts on the chunk's
// header alone, so the check must look at a header whose chunk does not fit.
TEST_CASE("a PNG ending in an empty IDAT header without its CRC is refused before decoding",
          "[gltf]") {
  const unsigned char png[] = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00,
                               0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x01, 0x04, 0x00, 0x00,
                               0x00, 0x04, 0x08, 0x06, 0x00, 0x00, 0x00, 0x68, 0x00, 0x00, 0x00,
                               0x00, 0x00, 0x00, 0x00, 0x49, 0x44, 0x41, 0x54, 0x78, 0x60, 0x82};
  checkRefusedBeforeDecoding(png, sizeof(png), 2, "empty IDAT chunk");
}

namespace {

// A lossless WebP of `rgba` (width x height), made by libwebp's encoder.
std::string losslessWebp(const std::vector<uint8_t>& rgba, int width, int height) {
  uint8_t* out = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(rgba.data(), width, height, width * 4, &out);
  REQUIRE(size > 0);
  std::string bytes(reinterpret_cast<const char*>(out), size);
  WebPFree(out);
  return bytes;
}

std::string requiringWebp(std::string gltfJson) {
  const std::string asset = R"({"asset":{"version":"2.0"},)";
  REQUIRE(gltfJson.rfind(asset, 0) == 0);
  return asset +
         R"("extensionsUsed":["EXT_texture_webp"],"extensionsRequired":["EXT_texture_webp"],)" +
         gltfJson.substr(asset.size());
}

}  // namespace

TEST_CASE("glTF EXT_texture_webp: the WebP image is read, before the PNG fallback", "[gltf]") {
  test::TempFolder folder("gltf-webp");
  folder.write("tri.bin", test::trianglePositions());
  folder.write("checker.png", fileBytes(gltf("textured_quad_checker.png")));
  // 3 x 2 texels, every channel different, alpha included (not 0: the
  // encoder need not keep the colour of a transparent texel).
  const std::vector<uint8_t> rgba = {255, 0,  0,  255, 0,  255, 0,  128, 0,   0,   255, 1,
                                     10,  20, 30, 40,  50, 60,  70, 80,  200, 150, 100, 255};
  folder.write("image.webp", losslessWebp(rgba, 3, 2));
  auto check = [&](const scene::GltfImport& r) {
    const auto& t = texture(r.scene, r.scene.materials.at(0).baseColorTexture);
    REQUIRE(t.width == 3u);
    REQUIRE(t.height == 2u);
    CHECK(t.rgba8 == rgba);
  };
  // With a PNG fallback as `source`, and alone in a file that requires the extension.
  check(scene::importGltf(folder.write(
      "fallback.gltf",
      test::triangleGltf("tri.bin", kTexturedMaterial,
                         R"({"uri":"checker.png"},{"uri":"image.webp"})",
                         R"({"source":0,"extensions":{"EXT_texture_webp":{"source":1}}})"))));
  check(scene::importGltf(folder.write(
      "required.gltf",
      requiringWebp(test::triangleGltf("tri.bin", kTexturedMaterial, R"({"uri":"image.webp"})",
                                       R"({"extensions":{"EXT_texture_webp":{"source":0}}})")))));
  // In a .glb's buffer view.
  const std::string webp = losslessWebp(rgba, 3, 2);
  const std::string json =
      R"({"asset":{"version":"2.0"},"extensionsUsed":["EXT_texture_webp"],
      "buffers":[{"byteLength":)" +
      std::to_string(36 + webp.size()) + R"(}],
      "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":)" +
      std::to_string(webp.size()) + R"(}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
      "images":[{"bufferView":1,"mimeType":"image/webp"}],
      "textures":[{"extensions":{"EXT_texture_webp":{"source":0}}}],
      "materials":[)" +
      std::string(kTexturedMaterial) + R"(],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
      "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
  check(scene::importGltf(
      folder.write("view.glb", test::glb(json, test::trianglePositions() + webp))));
}

TEST_CASE("glTF EXT_texture_webp: a broken or oversized WebP is refused naming the image",
          "[gltf]") {
  test::TempFolder folder("gltf-webp-bad");
  folder.write("tri.bin", test::trianglePositions());
  const std::string webp = losslessWebp(std::vector<uint8_t>(64 * 32 * 4, 77), 64, 32);
  folder.write("cut.webp", webp.substr(0, webp.size() / 2));
  folder.write("wide.webp", webp);
  auto file = [&](const char* image) {
    return folder.write(
        "image.gltf", requiringWebp(test::triangleGltf(
                          "tri.bin", kTexturedMaterial, std::string(R"({"uri":")") + image + "\"}",
                          R"({"extensions":{"EXT_texture_webp":{"source":0}}})")));
  };
  CHECK_THAT(test::gltfRefusal(file("cut.webp")),
             ContainsSubstring("image 0 (file 'cut.webp') cannot be decoded"));
  scene::InputLimits limits;
  limits.maxImageSide = 63;
  CHECK_THAT(test::gltfRefusal(file("wide.webp"), limits),
             ContainsSubstring("image 0 (file 'wide.webp') cannot be decoded (its header says 64 x "
                               "32 pixels, more than the limit 63 per side"));
  REQUIRE(scene::importGltf(file("wide.webp")).scene.textures.at(0).width == 64u);
}
