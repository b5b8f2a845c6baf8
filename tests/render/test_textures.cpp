// Material textures through the renderer: which texel each pixel shows
// (samplers, KHR_texture_transform, both texture-coordinate sets), each
// texture's effect against the untextured material it stands for, normal
// maps against the vertex normals they encode, alpha masks for camera and
// shadow rays, and textured emitters under next-event estimation.
#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "effects.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/mesh_builders.h"
#include "render_test_utils.h"
#include "test_data.h"

using namespace penumbra;

namespace {

constexpr uint32_t kSize = 32;

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// A texture of w x h texels, texel (x, y) = f(x, y) as RGBA8.
scene::Texture makeTexture(uint32_t w, uint32_t h, bool srgb,
                           const std::function<glm::u8vec4(uint32_t, uint32_t)>& f) {
  scene::Texture t;
  t.name = "test";
  t.width = w;
  t.height = h;
  t.srgb = srgb;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const glm::u8vec4 c = f(x, y);
      t.rgba8.insert(t.rgba8.end(), {c.r, c.g, c.b, c.a});
    }
  return t;
}

// A checker of distinct colours: every texel of a 4x4 texture differs.
glm::u8vec4 distinctTexel(uint32_t x, uint32_t y) {
  return {uint8_t(20 + 60 * x), uint8_t(30 + 50 * y), uint8_t(200 - 40 * ((x + y) % 4)), 255};
}

// A 2 x 2 quad in the z = 0 plane facing +z, uv0 as glTF lays an upright image
// on it: (u, v) = ((x + 1) / 2, (1 - y) / 2). uv1 is uv0 mirrored in u.
scene::Mesh texturedQuad(uint32_t material, float z = 0.0f, float halfSize = 1.0f) {
  scene::Mesh m;
  m.name = "textured quad";
  m.material = material;
  const float s = halfSize;
  m.positions = {{-s, -s, z}, {s, -s, z}, {s, s, z}, {-s, s, z}};
  m.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.uv1 = {{1, 1}, {0, 1}, {0, 0}, {1, 0}};
  m.normals.assign(4, glm::vec3(0, 0, 1));
  m.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

scene::Camera frontCamera() {
  scene::Camera c;
  c.position = {0, 0, 3};
  c.forward = {0, 0, -1};
  c.up = {0, 1, 0};
  c.verticalFovDegrees = 45.0f;  // the quad fills the middle 80 % of the image
  return c;
}

// One textured quad seen head-on, emitting its texture: a black Lambert
// material whose emission is white times the emissive texture.
scene::Scene emissiveTextureScene(scene::Texture texture, scene::TextureRef ref) {
  scene::Scene s;
  s.name = "emissive texture";
  auto m = scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(1.0f));
  m.emissiveTexture = 0;
  s.materials = {m};
  s.textures = {std::move(texture)};
  s.textureRefs = {ref};
  s.meshes = {texturedQuad(0)};
  s.instances = {{0, glm::mat4(1.0f)}};
  s.camera = frontCamera();
  return s;
}

float wrap(float t, scene::TextureWrap mode) {
  switch (mode) {
    case scene::TextureWrap::Repeat:
      return t - std::floor(t);
    case scene::TextureWrap::ClampToEdge:
      return std::clamp(t, 0.0f, 1.0f);
    case scene::TextureWrap::MirroredRepeat: {
      const float p = t - 2.0f * std::floor(t * 0.5f);  // [0, 2)
      return p <= 1.0f ? p : 2.0f - p;
    }
  }
  return t;
}

// The texel a nearest-filtered lookup of `ref` reads at the quad point
// (x, y), or nothing when the point lies within `margin` texels of a texel
// edge (where GPU rounding may pick either neighbour).
std::optional<glm::uvec2> nearestTexel(const scene::TextureRef& ref, const scene::Texture& tex,
                                       float x, float y, float margin = 0.02f) {
  glm::vec2 uv((x + 1.0f) * 0.5f, (1.0f - y) * 0.5f);
  if (ref.texCoord == 1) uv.x = 1.0f - uv.x;
  const glm::vec2 t = ref.transform0 * uv.x + ref.transform1 * uv.y + ref.transform2;
  const float u = wrap(t.x, ref.sampler.wrapU) * float(tex.width);
  const float v = wrap(t.y, ref.sampler.wrapV) * float(tex.height);
  for (float c : {u, v}) {
    const float f = c - std::floor(c);
    const bool clamped = c <= 0.0f || c >= float(tex.width);
    if (!clamped && (f < margin || f > 1.0f - margin)) return std::nullopt;
  }
  return glm::uvec2(std::min(uint32_t(u), tex.width - 1), std::min(uint32_t(v), tex.height - 1));
}

// What `classify` says of the z = 0 plane point each ray of pixel (x, y)'s
// footprint meets, when it says the same for all of them; nothing otherwise
// (the pixel straddles an edge, or some point is undecided).
template <class T, class Classify>
std::optional<T> sameOverFootprint(const scene::Camera& camera, uint32_t x, uint32_t y, uint32_t w,
                                   uint32_t h, Classify classify) {
  std::optional<T> result;
  for (glm::vec2 film : test::pixelFootprint(x, y)) {
    const glm::dvec3 d = test::cameraRayDirection(camera, glm::dvec2(film), w, h);
    const glm::dvec3 p = glm::dvec3(camera.position) + d * (-double(camera.position.z) / d.z);
    const std::optional<T> here = classify(p);
    if (!here || (result && *result != *here)) return std::nullopt;
    result = here;
  }
  return result;
}

// Checks every pixel whose footprint falls inside one texel of the quad shows
// exactly that texel (sRGB decoded); returns how many pixels were checked.
uint32_t checkEmittedTexels(const image::Image& img, const scene::Scene& s) {
  const auto& ref = s.textureRefs[0];
  const auto& tex = s.textures[0];
  uint32_t checked = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const auto texel = sameOverFootprint<glm::uvec2>(
          s.camera, x, y, img.width, img.height, [&](glm::dvec3 p) -> std::optional<glm::uvec2> {
            if (std::abs(p.x) >= 0.98 || std::abs(p.y) >= 0.98) return std::nullopt;
            return nearestTexel(ref, tex, float(p.x), float(p.y));
          });
      if (!texel) continue;
      const uint8_t* c = &tex.rgba8[(size_t(texel->y) * tex.width + texel->x) * 4];
      for (int ch = 0; ch < 3; ++ch) {
        const float expected = srgbToLinear(c[ch] / 255.0f);
        INFO("pixel " << x << "," << y << " texel " << texel->x << "," << texel->y << " channel "
                      << ch);
        REQUIRE(std::abs(img.pixel(x, y)[ch] - expected) <= 2e-3f + 2e-3f * expected);
      }
      ++checked;
    }
  return checked;
}

render::PathTracerSettings directOnly() {
  render::PathTracerSettings s;
  s.maxDepth = 0;  // emission seen by camera rays only
  return s;
}

}  // namespace

TEST_CASE("textures: a nearest-filtered emissive texture shows each texel where the host predicts",
          "[render][gpu][textures]") {
  auto device = test::makeTestDevice();
  const auto texture = makeTexture(4, 4, true, distinctTexel);
  scene::TextureRef ref;
  ref.sampler = {scene::TextureFilter::Nearest, scene::TextureFilter::Nearest,
                 scene::MipFilter::Linear, scene::TextureWrap::ClampToEdge,
                 scene::TextureWrap::ClampToEdge};

  SECTION("identity transform, clamped") {}
  SECTION("KHR_texture_transform: offset, 90-degree rotation and scale, repeated") {
    // uv' = T * R * S * uv with the extension's R = [cos sin; -sin cos].
    const float scale = 2.0f, angle = glm::radians(90.0f);
    const glm::vec2 offset(0.25f, 0.125f);
    ref.transform0 = glm::vec2(std::cos(angle), -std::sin(angle)) * scale;
    ref.transform1 = glm::vec2(std::sin(angle), std::cos(angle)) * scale;
    ref.transform2 = offset;
    ref.sampler.wrapU = ref.sampler.wrapV = scene::TextureWrap::Repeat;
  }
  SECTION("mirrored repeat") {
    ref.transform0 = {3.0f, 0.0f};
    ref.transform1 = {0.0f, 2.0f};
    ref.sampler.wrapU = ref.sampler.wrapV = scene::TextureWrap::MirroredRepeat;
  }
  SECTION("TEXCOORD_1") {
    ref.texCoord = 1;
  }

  const auto s = emissiveTextureScene(texture, ref);
  const auto img = test::renderScene(*device, s, kSize, kSize, 4, directOnly());
  const uint32_t checked = checkEmittedTexels(img, s);
  INFO("pixels checked " << checked);
  REQUIRE(checked >= 100);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {

// A quad seen head-on and lit by a point light off to the side, one bounce:
// each pixel is the light's direct contribution alone, a deterministic
// function of the material at the hit (what the textures change).
scene::Scene litQuadScene(const scene::Material& material) {
  scene::Scene s;
  s.name = "lit quad";
  s.materials = {material};
  s.meshes = {texturedQuad(0)};
  s.instances = {{0, glm::mat4(1.0f)}};
  scene::PointLight light;
  light.position = {1.5f, 1.0f, 2.0f};
  light.intensity = glm::vec3(6.0f);
  s.pointLights = {light};
  s.camera = frontCamera();
  return s;
}

render::PathTracerSettings oneBounce() {
  render::PathTracerSettings s;
  s.maxDepth = 1;
  s.russianRoulette = false;
  return s;
}

// Largest channel difference relative to the brightest pixel of `b`.
float relativeMaxDifference(const image::Image& a, const image::Image& b) {
  float peak = 0.0f, diff = 0.0f;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        peak = std::max(peak, b.pixel(x, y)[c]);
        diff = std::max(diff, std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]));
      }
  return peak > 0.0f ? diff / peak : diff;
}

scene::Material glossyMaterial() {
  auto m = scene::Material::lambert("glossy", glm::vec3(0.8f, 0.7f, 0.6f));
  m.specular = 0.5f;
  m.roughness = 0.4f;
  m.metallic = 0.3f;
  return m;
}

}  // namespace

TEST_CASE(
    "textures: base-colour and metallic-roughness textures scale their factors channel by channel",
    "[render][gpu][textures]") {
  auto device = test::makeTestDevice();
  scene::Material plain = glossyMaterial();
  scene::Material textured = plain;
  scene::Texture texture;
  SECTION("base colour: sRGB rgb times the factor") {
    const glm::u8vec4 texel(188, 90, 255, 255);
    texture = makeTexture(2, 2, true, [&](uint32_t, uint32_t) { return texel; });
    textured.baseColorTexture = 0;
    for (int c = 0; c < 3; ++c) plain.baseColor[c] *= srgbToLinear(texel[c] / 255.0f);
  }
  SECTION("metallic from blue, roughness from green, red ignored") {
    const glm::u8vec4 texel(7, 128, 200, 255);
    texture = makeTexture(2, 2, false, [&](uint32_t, uint32_t) { return texel; });
    textured.metallic = 0.9f;
    textured.roughness = 0.8f;
    textured.metallicRoughnessTexture = 0;
    plain.metallic = 0.9f * (200.0f / 255.0f);
    plain.roughness = 0.8f * (128.0f / 255.0f);
  }
  auto withTexture = litQuadScene(textured);
  withTexture.textures = {texture};
  withTexture.textureRefs = {scene::TextureRef{}};
  const auto reference =
      test::renderScene(*device, litQuadScene(plain), kSize, kSize, 4, oneBounce());
  const auto image = test::renderScene(*device, withTexture, kSize, kSize, 4, oneBounce());
  // 8-bit and sRGB decoding on the GPU against the host's float arithmetic.
  REQUIRE(relativeMaxDifference(image, reference) < 2e-3f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: KHR_materials_* textures scale their parameters as a factor would",
          "[render][gpu][textures]") {
  // Each case: the textured material against the same material with the
  // parameter scaled on the host as docs/materials.md says the texture
  // scales it, and against the material with the texture ignored, which must
  // look different (so a texture the shader skips fails).
  auto device = test::makeTestDevice();
  scene::Material plain = glossyMaterial();
  std::vector<scene::Texture> textures;
  std::function<void(scene::Material&)> attach;
  std::function<void(scene::Scene&)> stage = [](scene::Scene&) {};
  auto uniform = [](glm::u8vec4 texel, bool srgb) {
    return makeTexture(2, 2, srgb, [=](uint32_t, uint32_t) { return texel; });
  };
  scene::Material untextured;
  SECTION("clearcoat from red") {
    plain.clearcoat = 1.0f;
    plain.clearcoatGloss = 0.9f;
    untextured = plain;
    textures = {uniform({60, 250, 250, 255}, false)};
    attach = [](scene::Material& m) { m.clearcoatTexture = 0; };
    plain.clearcoat *= 60.0f / 255.0f;
  }
  SECTION("the coat's roughness from green") {
    plain.clearcoat = 1.0f;
    plain.clearcoatGloss = 0.2f;
    untextured = plain;
    textures = {uniform({255, 40, 255, 255}, false)};
    attach = [](scene::Material& m) { m.clearcoatRoughnessTexture = 0; };
    // The Lambert (glTF) model's coat: clearcoatGloss g stands for the
    // coat's roughness r = 1 - g; glTF scales r by the texture's green.
    const float r = (1.0f - 0.2f) * (40.0f / 255.0f);
    plain.clearcoatGloss = 1.0f - r;
  }
  SECTION("transmission from red") {
    plain.specTrans = 0.9f;
    plain.thin = true;
    untextured = plain;
    textures = {uniform({30, 255, 255, 255}, false)};
    attach = [](scene::Material& m) { m.transmissionTexture = 0; };
    plain.specTrans *= 30.0f / 255.0f;
  }
  // Sheen is a grazing effect (the Lambert model's is glTF's, Charlie
  // fibres): the camera and the light low over opposite edges of the quad.
  auto grazing = [](scene::Scene& s) {
    s.camera.position = {2.5, 0.0, 0.5};
    s.camera.forward = glm::normalize(glm::vec3(-2.5f, 0.0f, -0.5f));
    s.pointLights[0].position = {-3.0, 0.0, 0.3};
    s.pointLights[0].intensity = glm::vec3(40.0f);
  };
  SECTION("sheenColor per channel from the sheen colour texture (sRGB)") {
    stage = grazing;
    plain.sheen = 1.0f;
    plain.sheenTint = 0.0f;
    plain.sheenRoughness = 0.5f;
    plain.baseColor = glm::vec3(0.05f);
    plain.specular = 0.0f;  // no glossy highlight, which the grazing light would put in view
    plain.metallic = 0.0f;
    untextured = plain;
    textures = {uniform({20, 188, 40, 255}, true)};
    attach = [](scene::Material& m) { m.sheenColorTexture = 0; };
    plain.sheenColor *= glm::vec3(srgbToLinear(20.0f / 255.0f), srgbToLinear(188.0f / 255.0f),
                                  srgbToLinear(40.0f / 255.0f));
  }
  SECTION("sheenRoughness from the sheen roughness texture's alpha") {
    stage = grazing;
    plain.sheen = 1.0f;
    plain.sheenTint = 0.0f;
    plain.sheenRoughness = 0.9f;
    plain.baseColor = glm::vec3(0.05f);
    plain.specular = 0.0f;
    plain.metallic = 0.0f;
    untextured = plain;
    textures = {uniform({255, 255, 255, 80}, false)};
    attach = [](scene::Material& m) { m.sheenRoughnessTexture = 0; };
    plain.sheenRoughness *= 80.0f / 255.0f;
  }
  SECTION(
      "specular from the specular texture's alpha, specularColor per channel from the colour "
      "texture") {
    plain.specular = 1.0f;
    plain.metallic = 0.0f;
    untextured = plain;
    textures = {uniform({255, 255, 255, 90}, false), uniform({30, 140, 60, 255}, true)};
    attach = [](scene::Material& m) {
      m.specularTexture = 0;
      m.specularColorTexture = 1;
    };
    plain.specular *= 90.0f / 255.0f;
    plain.specularF90 *= 90.0f / 255.0f;  // glTF: F90 = specularFactor x the alpha too
    plain.specularColor *= glm::vec3(srgbToLinear(30.0f / 255.0f), srgbToLinear(140.0f / 255.0f),
                                     srgbToLinear(60.0f / 255.0f));
  }
  // glTF anisotropy on a smooth metal, whose stretched highlight shows both
  // the strength and the direction. The texture's direction is 8-bit: red
  // 255 and green 128 are (1, 1/255), not quite the tangent, so the host
  // reference turns by that angle too.
  SECTION("anisotropy strength from blue") {
    plain.metallic = 1.0f;
    plain.roughness = 0.2f;
    plain.anisotropyStrength = 0.9f;
    untextured = plain;
    textures = {uniform({255, 128, 70, 255}, false)};
    attach = [](scene::Material& m) { m.anisotropyTexture = 0; };
    plain.anisotropyStrength *= 70.0f / 255.0f;
    plain.anisotropyRotation = std::atan2(1.0f / 255.0f, 1.0f);
  }
  SECTION("anisotropy direction from red and green, turned by the rotation") {
    plain.metallic = 1.0f;
    plain.roughness = 0.2f;
    plain.anisotropyStrength = 0.9f;
    plain.anisotropyRotation = 0.3f;
    untextured = plain;
    // About 60 degrees from the tangent, off both axes, so a wrong sign of
    // either channel turns the streak by a large angle.
    textures = {uniform({191, 238, 255, 255}, false)};
    attach = [](scene::Material& m) { m.anisotropyTexture = 0; };
    plain.anisotropyRotation +=
        std::atan2(2.0f * 238.0f / 255.0f - 1.0f, 2.0f * 191.0f / 255.0f - 1.0f);
  }
  // Diffuse transmission, lit from behind: what the camera sees in front is
  // the transmitted share alone.
  SECTION(
      "diffuseTransmission from its texture's alpha, its colour per channel from the colour "
      "texture (sRGB)") {
    stage = [](scene::Scene& s) { s.pointLights[0].position = {1.5, 1.0, -2.0}; };
    plain.diffuseTransmission = 0.9f;
    plain.diffuseTransmissionColor = {1.0f, 0.9f, 0.8f};
    untextured = plain;
    // Mid-range colour texels: the image is this dim share alone; with a
    // dark texel (30) the difference came to 2.2e-3 of its peak, just past
    // the tolerance (not looked into further).
    textures = {uniform({255, 255, 255, 70}, false), uniform({120, 200, 160, 255}, true)};
    attach = [](scene::Material& m) {
      m.diffuseTransmissionTexture = 0;
      m.diffuseTransmissionColorTexture = 1;
    };
    plain.diffuseTransmission *= 70.0f / 255.0f;
    plain.diffuseTransmissionColor *=
        glm::vec3(srgbToLinear(120.0f / 255.0f), srgbToLinear(200.0f / 255.0f),
                  srgbToLinear(160.0f / 255.0f));
  }
  // A thin film on a glossy plastic: the factor from red, the thickness
  // picked between its minimum and maximum by green.
  SECTION("iridescence from red, the film's thickness from green") {
    plain.model = scene::MaterialModel::Lambert;
    plain.specular = 1.0f;
    plain.metallic = 0.3f;
    plain.iridescence = 1.0f;
    plain.iridescenceThicknessMinimum = 150.0f;
    plain.iridescenceThicknessMaximum = 650.0f;
    untextured = plain;
    textures = {uniform({120, 255, 255, 255}, false), uniform({255, 100, 255, 255}, false)};
    attach = [](scene::Material& m) {
      m.iridescenceTexture = 0;
      m.iridescenceThicknessTexture = 1;
    };
    plain.iridescence *= 120.0f / 255.0f;
    plain.iridescenceThicknessMaximum = 150.0f + 500.0f * (100.0f / 255.0f);
  }
  scene::Material textured = untextured;
  attach(textured);
  auto staged = [&](const scene::Material& m) {
    auto s = litQuadScene(m);
    stage(s);
    return s;
  };
  auto withTextures = staged(textured);
  withTextures.textures = textures;
  for (uint32_t i = 0; i < textures.size(); ++i) {
    scene::TextureRef ref;
    ref.texture = i;
    withTextures.textureRefs.push_back(ref);
  }
  const auto reference = test::renderScene(*device, staged(plain), kSize, kSize, 4, oneBounce());
  const auto ignored = test::renderScene(*device, staged(untextured), kSize, kSize, 4, oneBounce());
  const auto image = test::renderScene(*device, withTextures, kSize, kSize, 4, oneBounce());
  const float difference = relativeMaxDifference(image, reference);
  const float ignoredDifference = relativeMaxDifference(ignored, reference);
  INFO("textured against host-scaled: " << difference
                                        << "; texture ignored: " << ignoredDifference);
  // 8-bit and sRGB decoding on the GPU against the host's float arithmetic,
  // as for the core textures; ignoring the texture is 10x that or more.
  REQUIRE(difference < 2e-3f);
  REQUIRE(ignoredDifference > 2e-2f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: a normal map shades as the vertex normals it encodes",
          "[render][gpu][textures]") {
  auto device = test::makeTestDevice();
  const glm::u8vec4 texel(200, 100, 230, 255);
  float handedness = 1.0f;
  float scale = 0.7f;
  SECTION("right-handed tangent frame") {}
  SECTION("left-handed tangent frame (tangent w = -1) mirrors the bitangent") {
    handedness = -1.0f;
  }
  SECTION("normal scale 0 leaves the surface normal") {
    scale = 0.0f;
  }
  // The encoded tangent-space normal, xy scaled (glTF normalTexture.scale);
  // on the quad the tangent is +x, the normal +z, the bitangent +y * w.
  glm::vec3 m = glm::vec3(texel) / 255.0f * 2.0f - 1.0f;
  m.x *= scale;
  m.y *= scale;
  const glm::vec3 encoded = glm::normalize(glm::vec3(m.x, m.y * handedness, m.z));

  auto material = glossyMaterial();
  auto reference = litQuadScene(material);
  reference.meshes[0].normals.assign(4, encoded);
  auto mapped = litQuadScene(material);
  mapped.materials[0].normalTexture = 0;
  mapped.materials[0].normalScale = scale;
  mapped.meshes[0].tangents.assign(4, glm::vec4(1, 0, 0, handedness));
  mapped.textures = {makeTexture(1, 1, false, [&](uint32_t, uint32_t) { return texel; })};
  mapped.textureRefs = {scene::TextureRef{}};
  const auto expected = test::renderScene(*device, reference, kSize, kSize, 4, oneBounce());
  const auto image = test::renderScene(*device, mapped, kSize, kSize, 4, oneBounce());
  REQUIRE(relativeMaxDifference(image, expected) < 2e-3f);
  // And the map changes the image at all: the flat quad differs.
  const auto flat =
      test::renderScene(*device, litQuadScene(material), kSize, kSize, 4, oneBounce());
  if (scale > 0.0f) REQUIRE(relativeMaxDifference(image, flat) > 0.05f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: glTF's coat normal map shades the coat as the vertex normals it encodes",
          "[render][gpu][textures]") {
  // A black base without a specular layer under a rough glTF coat: the
  // point light's highlight is the coat's alone. KHR_materials_clearcoat:
  // the coat follows clearcoatNormalTexture (xy x its scale), else the
  // vertex normal, never the base's normal map.
  auto device = test::makeTestDevice();
  const glm::u8vec4 texel(200, 100, 230, 255);
  const float scale = 0.7f;
  glm::vec3 m = glm::vec3(texel) / 255.0f * 2.0f - 1.0f;
  m.x *= scale;
  m.y *= scale;
  const glm::vec3 encoded = glm::normalize(m);

  auto coat = scene::Material::lambert("coat", glm::vec3(0.0f));
  coat.specular = 0.0f;
  coat.clearcoat = 1.0f;
  coat.clearcoatGloss = 0.6f;
  auto withMap = [&](scene::Scene s) {
    s.meshes[0].tangents.assign(4, glm::vec4(1, 0, 0, 1));
    s.textures = {makeTexture(1, 1, false, [&](uint32_t, uint32_t) { return texel; })};
    s.textureRefs = {scene::TextureRef{}};
    return s;
  };
  auto reference = litQuadScene(coat);
  reference.meshes[0].normals.assign(4, encoded);
  auto mapped = withMap(litQuadScene(coat));
  mapped.materials[0].clearcoatNormalTexture = 0;
  mapped.materials[0].clearcoatNormalScale = scale;
  auto baseMapOnly = withMap(litQuadScene(coat));
  baseMapOnly.materials[0].normalTexture = 0;
  baseMapOnly.materials[0].normalScale = scale;
  const auto expected = test::renderScene(*device, reference, kSize, kSize, 4, oneBounce());
  const auto image = test::renderScene(*device, mapped, kSize, kSize, 4, oneBounce());
  const auto flat = test::renderScene(*device, litQuadScene(coat), kSize, kSize, 4, oneBounce());
  const auto baseMapped = test::renderScene(*device, baseMapOnly, kSize, kSize, 4, oneBounce());
  INFO("coat map vs vertex normals " << relativeMaxDifference(image, expected) << ", vs flat "
                                     << relativeMaxDifference(image, flat)
                                     << "; base map only vs flat "
                                     << relativeMaxDifference(baseMapped, flat));
  REQUIRE(relativeMaxDifference(image, expected) < 2e-3f);
  REQUIRE(relativeMaxDifference(image, flat) > 0.05f);
  // The base's normal map leaves the coat (and this black base) as it was.
  REQUIRE(relativeMaxDifference(baseMapped, flat) < 2e-3f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {

// 4x4 base-colour texture, mid grey, alpha alternating 0 and 255 per texel.
scene::Texture alphaChecker() {
  return makeTexture(4, 4, true, [](uint32_t x, uint32_t y) {
    return glm::u8vec4(128, 128, 128, (x + y) % 2 == 0 ? 0 : 255);
  });
}

scene::TextureRef nearestRef() {
  scene::TextureRef ref;
  ref.sampler = {scene::TextureFilter::Nearest, scene::TextureFilter::Nearest,
                 scene::MipFilter::Linear, scene::TextureWrap::ClampToEdge,
                 scene::TextureWrap::ClampToEdge};
  return ref;
}

scene::Material maskedBlack(scene::AlphaMode mode) {
  auto m = scene::Material::lambert("masked", glm::vec3(0.0f));
  m.baseColorTexture = 0;
  m.alphaMode = mode;
  m.alphaCutoff = 0.5f;
  return m;
}

// Whether the alpha checker is opaque at quad point (x, y), or nothing near a
// texel edge.
std::optional<bool> checkerOpaque(float x, float y) {
  if (std::abs(x) >= 0.98f || std::abs(y) >= 0.98f) return std::nullopt;
  const auto tex = alphaChecker();
  const auto texel = nearestTexel(nearestRef(), tex, x, y, 0.05f);
  if (!texel) return std::nullopt;
  return (texel->x + texel->y) % 2 != 0;
}

}  // namespace

namespace {

// A bumpy normal map: 8 x 8 texels, each tilted `tiltDegrees` from the
// surface normal towards its own azimuth (texel i: i x 137.5 degrees, the
// golden angle, so neighbours point every way).
scene::Texture bumpyNormalMap(float tiltDegrees) {
  const float tilt = glm::radians(tiltDegrees);
  return makeTexture(8, 8, false, [&](uint32_t x, uint32_t y) {
    const float azimuth = glm::radians(137.5f * float(y * 8 + x));
    const glm::vec3 n(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth),
                      std::cos(tilt));
    const glm::vec3 encoded = (n * 0.5f + 0.5f) * 255.0f + 0.5f;
    return glm::u8vec4(uint8_t(encoded.x), uint8_t(encoded.y), uint8_t(encoded.z), 255);
  });
}

// A large normal-mapped quad (z = 0, facing +z) filling the whole image,
// seen 60 degrees from its normal, under a uniform white environment: a
// white furnace, where every surface that loses no energy shows exactly 1.
scene::Scene normalMappedFurnace(const scene::Material& material, float tiltDegrees) {
  scene::Scene s;
  s.name = "normal-mapped furnace";
  s.materials = {material};
  s.materials[0].normalTexture = 0;
  s.textures = {bumpyNormalMap(tiltDegrees)};
  // Repeated every 0.8 units (the quad is 100 across): about a dozen texels
  // across the view, each seen whole.
  scene::TextureRef tiled;
  tiled.transform0 = {125.0f, 0.0f};
  tiled.transform1 = {0.0f, 125.0f};
  s.textureRefs = {tiled};
  s.meshes = {texturedQuad(0, 0.0f, 50.0f)};
  s.instances = {{0, glm::mat4(1.0f)}};
  s.environment = scene::constantEnvironment(glm::vec3(1.0f));
  s.camera.position = {0.0, -std::sqrt(3.0) * 2.0, 2.0};
  s.camera.forward = glm::normalize(glm::vec3(0.0f, std::sqrt(3.0f), -1.0f));
  s.camera.up = {0, 0, 1};
  s.camera.verticalFovDegrees = 20.0f;
  return s;
}

}  // namespace

TEST_CASE("textures: a normal-mapped mirror has no dark rims, and the furnace gains no light",
          "[render][gpu][textures]") {
  // Reflections about a normal tilted away from the viewer fall below the
  // geometric surface; a renderer that ends those paths draws black rims
  // around every bump. The shading normal is bent just enough for the mirror
  // direction to leave the surface (surface_hit.hlsli), so a white metal
  // mirror reflects the white sky everywhere: 1 at every pixel.
  auto device = test::makeTestDevice();
  render::PathTracerSettings settings;
  settings.russianRoulette = false;
  auto mirror = scene::Material::lambert("mirror", glm::vec3(1.0f));
  mirror.model = scene::MaterialModel::Disney;
  mirror.metallic = 1.0f;
  mirror.roughness = 0.0f;
  const auto mirrored =
      test::renderScene(*device, normalMappedFurnace(mirror, 50.0f), 48, 48, 4, settings);
  REQUIRE(image::countNonFinite(mirrored) == 0);
  uint32_t dark = 0;
  float lowest = 1e9f, highest = 0.0f;
  for (uint32_t y = 0; y < mirrored.height; ++y)
    for (uint32_t x = 0; x < mirrored.width; ++x) {
      const float v = mirrored.pixel(x, y)[1];
      dark += v < 0.9f;
      lowest = std::min(lowest, v);
      highest = std::max(highest, v);
    }
  INFO("mirror: " << dark << " pixels below 0.9, range " << lowest << " .. " << highest);
  CHECK(dark == 0u);
  // A perfect white mirror in a white furnace: 1, and never more (1 %: the
  // GPU's rounding of the near-delta lobe).
  CHECK(highest <= 1.01f);
  CHECK(std::abs(image::meanRgb(mirrored).g - 1.0) < 0.01);

  // A white Lambertian surface with the same map: it may lose the samples
  // that the shading normal sends below the surface, but never gains; its
  // mean stays within 2 % (the noise of 64 spp x 2304 pixels is ~0.2 %)
  // of the 1 it would show with a flat normal.
  const auto diffuse = test::renderScene(
      *device, normalMappedFurnace(scene::Material::lambert("white", glm::vec3(1.0f)), 50.0f), 48,
      48, 64, settings);
  REQUIRE(image::countNonFinite(diffuse) == 0);
  const double mean = image::meanRgb(diffuse).g;
  INFO("diffuse mean " << mean);
  CHECK(mean <= 1.005);
  CHECK(mean > 0.9);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("vertex colours: COLOR_0 multiplies the base colour and, for MASK, the alpha",
          "[render][gpu][textures]") {
  auto device = test::makeTestDevice();
  const glm::vec4 color(0.2f, 0.6f, 0.9f, 1.0f);
  // The same colour as the material's factor: the images agree.
  auto material = glossyMaterial();
  auto coloured = litQuadScene(material);
  coloured.meshes[0].colors.assign(4, color);
  auto factor = litQuadScene(material);
  factor.materials[0].baseColor *= glm::vec3(color);
  const auto expected = test::renderScene(*device, factor, kSize, kSize, 4, oneBounce());
  const auto image = test::renderScene(*device, coloured, kSize, kSize, 4, oneBounce());
  CHECK(relativeMaxDifference(image, expected) < 2e-3f);
  // And the colour changes the image at all.
  const auto plain =
      test::renderScene(*device, litQuadScene(material), kSize, kSize, 4, oneBounce());
  CHECK(relativeMaxDifference(image, plain) > 0.05f);

  // Interpolated across each triangle: colours affine in position,
  // c = (0.5 + 0.4 x, 0.5 + 0.4 y, 0.3) at the corners (x, y = +-1), are
  // that affine function everywhere on both triangles. A Lambert surface's
  // radiance is its albedo times the white surface's, so the ratio to a
  // white render at each pixel is c at its centre: frontCamera sees
  // +-3 tan(22.5 deg) at z = 0, so pixel (i, j)'s centre is at
  // x = (2 (i + 0.5) / size - 1) 3 tan(22.5 deg), y the same for -j. The two
  // renders share their sample positions, so the ratio is c averaged over
  // them: within 0.4 x half a pixel (0.016) of the centre's; 0.025 passes
  // that and fails a wrong corner (an error of 0.4 or more).
  {
    auto white = litQuadScene(scene::Material::lambert("white", glm::vec3(1.0f)));
    auto affine = white;
    for (size_t v = 0; v < 4; ++v) {
      const glm::vec3 p = affine.meshes[0].positions[v];
      affine.meshes[0].colors.emplace_back(0.5f + 0.4f * p.x, 0.5f + 0.4f * p.y, 0.3f, 1.0f);
    }
    const auto lit = test::renderScene(*device, white, kSize, kSize, 16, oneBounce());
    const auto tinted = test::renderScene(*device, affine, kSize, kSize, 16, oneBounce());
    uint32_t checked = 0;
    for (uint32_t j = 8; j < kSize - 8; ++j)
      for (uint32_t i = 8; i < kSize - 8; ++i) {
        const float halfView = 3.0f * std::tan(glm::radians(22.5f));
        const float x = (2.0f * (float(i) + 0.5f) / float(kSize) - 1.0f) * halfView;
        const float y = -(2.0f * (float(j) + 0.5f) / float(kSize) - 1.0f) * halfView;
        const glm::vec3 c(0.5f + 0.4f * x, 0.5f + 0.4f * y, 0.3f);
        const float w = lit.pixel(i, j)[1];
        if (w < 0.05f) continue;
        for (int k = 0; k < 3; ++k)
          CHECK(std::abs(tinted.pixel(i, j)[k] / lit.pixel(i, j)[k] - c[k]) < 0.025f);
        ++checked;
      }
    CHECK(checked > 200);
  }

  // Alpha MASK at cutoff 0.5: a vertex alpha of 0.3 cuts the quad away (the
  // camera sees the black background), 0.8 keeps it.
  auto masked = litQuadScene(material);
  masked.materials[0].alphaMode = scene::AlphaMode::Mask;
  masked.materials[0].alphaCutoff = 0.5f;
  masked.meshes[0].colors.assign(4, glm::vec4(1.0f, 1.0f, 1.0f, 0.3f));
  const auto cut = test::renderScene(*device, masked, kSize, kSize, 4, oneBounce());
  CHECK(image::meanRgb(cut).g == 0.0);
  masked.meshes[0].colors.assign(4, glm::vec4(1.0f, 1.0f, 1.0f, 0.8f));
  const auto kept = test::renderScene(*device, masked, kSize, kSize, 4, oneBounce());
  CHECK(relativeMaxDifference(kept, plain) < 2e-3f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: alpha MASK cuts camera rays through transparent texels",
          "[render][gpu][textures]") {
  auto device = test::makeTestDevice();
  scene::Scene s;
  s.name = "mask in front of an emitter";
  s.materials = {maskedBlack(scene::AlphaMode::Mask),
                 scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(1.0f))};
  s.textures = {alphaChecker()};
  s.textureRefs = {nearestRef()};
  s.meshes = {texturedQuad(0), texturedQuad(1, -1.0f, 3.0f)};
  s.instances = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
  s.camera = frontCamera();
  bool masked = true;
  SECTION("MASK") {}
  SECTION("OPAQUE: the same texture's alpha is ignored") {
    s.materials[0].alphaMode = scene::AlphaMode::Opaque;
    masked = false;
  }
  const auto img = test::renderScene(*device, s, kSize, kSize, 4, directOnly());
  uint32_t seenThrough = 0, blocked = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const auto opaque = sameOverFootprint<bool>(s.camera, x, y, kSize, kSize, [](glm::dvec3 p) {
        return checkerOpaque(float(p.x), float(p.y));
      });
      if (!opaque) continue;
      const float expected = (*opaque || !masked) ? 0.0f : 1.0f;
      INFO("pixel " << x << "," << y);
      REQUIRE(std::abs(img.pixel(x, y)[1] - expected) < 1e-4f);
      (expected > 0.0f ? seenThrough : blocked) += 1;
    }
  REQUIRE(blocked >= 100);
  if (masked) REQUIRE(seenThrough >= 100);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: alpha MASK lets shadow rays through transparent texels",
          "[render][gpu][textures]") {
  // A floor at z = 0, a masked quad at z = 1 over it, a point light above and
  // the camera looking down: each pixel sees the floor through a hole or the
  // black mask, and a floor point is lit if its ray to the light passes a
  // hole. The host predicts both per pixel.
  auto device = test::makeTestDevice();
  scene::Scene s;
  s.name = "mask shadow";
  const float albedo = 0.8f;
  s.materials = {maskedBlack(scene::AlphaMode::Mask),
                 scene::Material::lambert("floor", glm::vec3(albedo))};
  s.materials[1].specular = 0.0f;
  s.textures = {alphaChecker()};
  s.textureRefs = {nearestRef()};
  s.meshes = {texturedQuad(0, 1.0f), texturedQuad(1, 0.0f, 4.0f)};
  s.instances = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
  scene::PointLight light;
  light.position = {0.3f, 0.2f, 2.5f};
  light.intensity = glm::vec3(5.0f);
  s.pointLights = {light};
  s.camera.position = {-0.2f, 0.1f, 4.0f};
  s.camera.forward = {0, 0, -1};
  s.camera.up = {0, 1, 0};
  s.camera.verticalFovDegrees = 30.0f;

  render::PathTracerSettings settings = oneBounce();
  const auto img = test::renderScene(*device, s, kSize, kSize, 4, settings);
  uint32_t lit = 0, shadowed = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      // Per footprint point: nothing (ambiguous), or the radiance expected.
      float lo = 1e30f, hi = -1.0f;
      bool decided = true;
      for (glm::vec2 film : test::pixelFootprint(x, y)) {
        const glm::dvec3 o(s.camera.position);
        const glm::dvec3 d = test::cameraRayDirection(s.camera, glm::dvec2(film), kSize, kSize);
        const glm::dvec3 atMask = o + d * ((1.0 - o.z) / d.z);
        const auto maskOpaque = checkerOpaque(float(atMask.x), float(atMask.y));
        if (!maskOpaque) {
          decided = false;
          break;
        }
        float value = 0.0f;
        if (!*maskOpaque) {
          const glm::dvec3 floor = o + d * (-o.z / d.z);
          const glm::dvec3 toLight = glm::dvec3(light.position) - floor;
          const glm::dvec3 crossing = floor + toLight * (1.0 / toLight.z);
          const auto shadowOpaque = checkerOpaque(float(crossing.x), float(crossing.y));
          if (!shadowOpaque) {
            decided = false;
            break;
          }
          const double dist = glm::length(toLight);
          value = *shadowOpaque ? 0.0f
                                : float(albedo / std::numbers::pi * light.intensity.y *
                                        (toLight.z / dist) / (dist * dist));
        }
        lo = std::min(lo, value);
        hi = std::max(hi, value);
      }
      if (!decided || (lo == 0.0f) != (hi == 0.0f)) continue;
      INFO("pixel " << x << "," << y << " expected " << lo << ".." << hi);
      const float v = img.pixel(x, y)[1];
      REQUIRE(v >= lo * 0.999f - 1e-5f);
      REQUIRE(v <= hi * 1.001f + 1e-5f);
      (hi > 0.0f ? lit : shadowed) += 1;
    }
  INFO("lit " << lit << " shadowed " << shadowed);
  REQUIRE(lit >= 40);
  REQUIRE(shadowed >= 40);

  // The full pipeline (every effect, the any-hit in every pipeline) renders
  // the same image as the one specialized for this scene.
  render::PipelineOptions all;
  all.allEffects = true;
  const auto full = render::renderImage(*device, s, kSize, kSize, 4, settings, 16, all);
  REQUIRE(relativeMaxDifference(full, img) < 1e-5f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: next-event estimation samples a textured emitter's texture",
          "[render][gpu][textures]") {
  // An emitter over a floor whose texture is white on its left half and black
  // on its right renders like an untextured emitter of the left half alone.
  auto device = test::makeTestDevice();
  auto makeScene = [](bool textured) {
    scene::Scene s;
    s.name = textured ? "half-textured emitter" : "half emitter";
    auto emitter = scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(4.0f));
    s.materials = {scene::Material::lambert("floor", glm::vec3(0.6f)), emitter};
    s.meshes = {texturedQuad(0, 0.0f, 3.0f)};
    if (textured) {
      s.materials[1].emissiveTexture = 0;
      s.textures = {makeTexture(2, 1, true, [](uint32_t x, uint32_t) {
        return x == 0 ? glm::u8vec4(255, 255, 255, 255) : glm::u8vec4(0, 0, 0, 255);
      })};
      s.textureRefs = {nearestRef()};
      // Facing down: the quad turned half a turn about x (x stays, so the
      // texture's left half is still at x < 0), lifted to z = 1.
      auto quad = texturedQuad(1);
      for (auto& p : quad.positions) p = {p.x, -p.y, 1.0f};
      for (auto& n : quad.normals) n = {0, 0, -1};
      s.meshes.push_back(quad);
    } else {
      s.meshes.push_back(scene::makeQuad({-1, -1, 1}, {0, 2, 0}, {1, 0, 0}, 1));
    }
    s.instances = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
    s.camera.position = {0.0f, -3.0f, 0.6f};
    s.camera.forward = glm::normalize(glm::vec3(0.0f, 1.0f, -0.35f));
    s.camera.up = {0, 0, 1};
    s.camera.verticalFovDegrees = 50.0f;
    return s;
  };
  render::PathTracerSettings settings;
  settings.maxDepth = 1;
  SECTION("NEE alone") {
    settings.strategy = render::SamplingStrategy::Nee;
  }
  SECTION("MIS") {
    settings.strategy = render::SamplingStrategy::Mis;
  }
  const auto textured = test::renderScene(*device, makeScene(true), 24, 24, 64, settings);
  const auto reference = test::renderScene(*device, makeScene(false), 24, 24, 64, settings);
  // Mean over the lower half (the floor): noise averages out over 288 pixels.
  auto floorMean = [](const image::Image& img) {
    double sum = 0;
    for (uint32_t y = img.height / 2; y < img.height; ++y)
      for (uint32_t x = 0; x < img.width; ++x) sum += img.pixel(x, y)[1];
    return sum / (img.width * img.height / 2);
  };
  const double a = floorMean(textured), b = floorMean(reference);
  INFO("textured " << a << " reference " << b);
  REQUIRE(b > 0.01);
  REQUIRE(std::abs(a - b) < 0.03 * b);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: glTF files render their textures and alpha masks",
          "[render][gpu][textures][gltf]") {
  auto device = test::makeTestDevice();
  SECTION("an emissive checker texture, texel by texel") {
    auto s = scene::loadGltf(test::dataPath("gltf/textured_quad.gltf"));
    s.camera = frontCamera();
    const auto img = test::renderScene(*device, s, kSize, kSize, 4, directOnly());
    REQUIRE(checkEmittedTexels(img, s) >= 100);
  }
  SECTION("an alpha-masked quad over an emitter shows the emitter through transparent texels") {
    auto s = scene::loadGltf(test::dataPath("gltf/alpha_mask_quad.gltf"));
    s.camera = frontCamera();
    s.materials.push_back(scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(1.0f)));
    s.meshes.push_back(texturedQuad(uint32_t(s.materials.size() - 1), -1.0f, 3.0f));
    s.instances.push_back({uint32_t(s.meshes.size() - 1), glm::mat4(1.0f)});
    const auto img = test::renderScene(*device, s, kSize, kSize, 4, directOnly());
    // The file's texture is alpha 255 where x + y is even: the opposite
    // parity of alphaChecker(), so opaque here is transparent there.
    uint32_t seenThrough = 0, blocked = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const auto checkerSaysOpaque = sameOverFootprint<bool>(
            s.camera, x, y, kSize, kSize,
            [](glm::dvec3 p) { return checkerOpaque(float(p.x), float(p.y)); });
        if (!checkerSaysOpaque) continue;
        // Transparent texels show the emitter (1); opaque ones the quad's own
        // colour under no light (its emission is 0).
        const bool opaque = !*checkerSaysOpaque;
        INFO("pixel " << x << "," << y);
        if (opaque) {
          REQUIRE(img.pixel(x, y)[1] < 1e-4f);
          ++blocked;
        } else {
          REQUIRE(std::abs(img.pixel(x, y)[1] - 1.0f) < 1e-4f);
          ++seenThrough;
        }
      }
    REQUIRE(blocked >= 100);
    REQUIRE(seenThrough >= 100);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: an occlusion texture darkens Whitted's ambient term only",
          "[render][gpu][textures]") {
  // No lights, ambient 1: every pixel of the quad is kd * ambient * occlusion,
  // occlusion = 1 + strength * (r - 1).
  auto device = test::makeTestDevice();
  auto material = scene::Material::lambert("matte", glm::vec3(0.5f));
  auto plain = litQuadScene(material);
  plain.pointLights.clear();
  plain.ambient = glm::vec3(1.0f);
  auto occluded = plain;
  occluded.materials[0].occlusionTexture = 0;
  occluded.materials[0].occlusionStrength = 0.75f;
  occluded.textures = {
      makeTexture(2, 2, false, [](uint32_t, uint32_t) { return glm::u8vec4(64, 200, 200, 255); })};
  occluded.textureRefs = {scene::TextureRef{}};
  render::PathTracerSettings whitted;
  whitted.integrator = render::Integrator::Whitted;
  whitted.maxDepth = 0;
  const auto reference = test::renderScene(*device, plain, kSize, kSize, 1, whitted);
  const auto image = test::renderScene(*device, occluded, kSize, kSize, 1, whitted);
  const float occlusion = 1.0f + 0.75f * (64.0f / 255.0f - 1.0f);
  uint32_t quadPixels = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const float r = reference.pixel(x, y)[1];
      if (r <= 0.0f) continue;  // background
      INFO("pixel " << x << "," << y);
      REQUIRE(std::abs(image.pixel(x, y)[1] - r * occlusion) <= 1e-4f * r);
      ++quadPixels;
    }
  REQUIRE(quadPixels >= 400);
  // The path tracer computes occlusion itself and ignores the texture.
  render::PathTracerSettings path = oneBounce();
  auto lit = litQuadScene(material);
  auto litOccluded = lit;
  litOccluded.materials = occluded.materials;
  litOccluded.textures = occluded.textures;
  litOccluded.textureRefs = occluded.textureRefs;
  REQUIRE(relativeMaxDifference(test::renderScene(*device, litOccluded, kSize, kSize, 4, path),
                                test::renderScene(*device, lit, kSize, kSize, 4, path)) < 1e-6f);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("textures: alpha BLEND covers alpha of what lies behind, for camera and shadow rays",
          "[render][gpu][textures]") {
  auto device = test::makeTestDevice();
  // Camera rays: a black BLEND quad in front of an emitter of radiance 1.
  float alpha = 0.0f;
  scene::Scene s;
  s.name = "blend in front of an emitter";
  auto blend = scene::Material::lambert("blend", glm::vec3(0.0f));
  blend.alphaMode = scene::AlphaMode::Blend;
  s.materials = {blend, scene::Material::lambert("emitter", glm::vec3(0.0f), glm::vec3(1.0f))};
  SECTION("alpha from a base-colour texture") {
    s.materials[0].baseColorTexture = 0;
    s.textures = {
        makeTexture(2, 2, true, [](uint32_t, uint32_t) { return glm::u8vec4(90, 90, 90, 64); })};
    s.textureRefs = {nearestRef()};
    alpha = 64.0f / 255.0f;
  }
  SECTION("alpha from the factor alone") {
    s.materials[0].alpha = 0.6f;
    alpha = 0.6f;
  }
  s.meshes = {texturedQuad(0), texturedQuad(1, -1.0f, 3.0f)};
  s.instances = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
  s.camera = frontCamera();
  const uint32_t spp = 64;
  const auto img = test::renderScene(*device, s, 16, 16, spp, directOnly());
  // Pixels well inside the quad (it spans the middle 80 %): each sample sees
  // the emitter with probability 1 - alpha.
  double sum = 0;
  uint32_t n = 0;
  for (uint32_t y = 4; y < 12; ++y)
    for (uint32_t x = 4; x < 12; ++x, ++n) {
      const float v = img.pixel(x, y)[1];
      INFO("pixel " << x << "," << y << " " << v);
      // Per pixel: binomial(64, 1 - alpha) / 64, within 5 standard deviations.
      const double sd = std::sqrt(alpha * (1.0 - alpha) / spp);
      REQUIRE(std::abs(v - (1.0 - alpha)) < 5.0 * sd);
      sum += v;
    }
  // Over 64 pixels: 4096 samples, standard deviation < 0.008.
  INFO("mean " << sum / n << " expected " << 1.0 - alpha);
  REQUIRE(std::abs(sum / n - (1.0 - alpha)) < 0.03);

  // Shadow rays: a point light over a floor, the BLEND quad between them,
  // seen from the side (camera rays never cross it). Where the floor's shadow
  // ray crosses the quad it is lit (1 - alpha) as bright as without the quad.
  auto shadowScene = [&](bool withQuad) {
    scene::Scene f;
    f.name = withQuad ? "blend shadow" : "no blocker";
    f.materials = {s.materials[0], scene::Material::lambert("floor", glm::vec3(0.8f))};
    f.textures = s.textures;
    f.textureRefs = s.textureRefs;
    f.meshes = {texturedQuad(1, 0.0f, 3.0f)};
    if (withQuad) f.meshes.push_back(texturedQuad(0, 1.0f, 0.4f));
    for (uint32_t m = 0; m < f.meshes.size(); ++m) f.instances.push_back({m, glm::mat4(1.0f)});
    scene::PointLight light;
    light.position = {0.0f, 0.0f, 2.0f};
    light.intensity = glm::vec3(4.0f);
    f.pointLights = {light};
    f.camera.position = {0.0f, -3.0f, 0.5f};
    f.camera.forward = glm::normalize(glm::vec3(0.0f, 3.0f, -0.5f));
    f.camera.up = {0, 0, 1};
    f.camera.verticalFovDegrees = 40.0f;
    return f;
  };
  const auto blocked = shadowScene(true);
  const auto shadowed = test::renderScene(*device, blocked, 24, 24, spp, oneBounce());
  const auto open = test::renderScene(*device, shadowScene(false), 24, 24, spp, oneBounce());
  double ratioSum = 0;
  uint32_t inShadow = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      bool allBehindQuad = true;
      for (glm::vec2 film : test::pixelFootprint(x, y)) {
        const glm::dvec3 o(blocked.camera.position);
        const glm::dvec3 d = test::cameraRayDirection(blocked.camera, glm::dvec2(film), 24, 24);
        if (d.z >= 0.0) {
          allBehindQuad = false;
          break;
        }
        const glm::dvec3 floor = o + d * (-o.z / d.z);
        // The shadow ray to (0, 0, 2) crosses z = 1 half way.
        const glm::dvec2 crossing = glm::dvec2(floor) * 0.5;
        if (std::abs(crossing.x) > 0.35 || std::abs(crossing.y) > 0.35) allBehindQuad = false;
      }
      if (!allBehindQuad) continue;
      REQUIRE(open.pixel(x, y)[1] > 0.0f);
      ratioSum += shadowed.pixel(x, y)[1] / open.pixel(x, y)[1];
      ++inShadow;
    }
  INFO("pixels in the blend's shadow " << inShadow << ", mean ratio " << ratioSum / inShadow);
  REQUIRE(inShadow >= 20);
  REQUIRE(std::abs(ratioSum / inShadow - (1.0 - alpha)) < 0.04);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE(
    "anisotropy: glTF's strength stretches a highlight along the tangent turned by the rotation",
    "[render][gpu][textures]") {
  // A smooth metal quad (tangent +x, bitangent +y) seen head-on, lit from
  // the camera: with full strength the GGX alpha along the anisotropy
  // direction is 1 and across it 0.04, so the highlight is a streak along
  // that direction. Its shape is measured by the luminance-weighted second
  // moments of the image in world axes (x right, y up), so the expectation
  // comes from the geometry, not from the shader: at rotation 0 the streak
  // lies along x, at a quarter turn along y, and at an eighth of a turn
  // (counter-clockwise, from the tangent towards the bitangent) along
  // x = y. Isotropic, the moments are equal.
  auto device = test::makeTestDevice();
  constexpr uint32_t kShape = 48;
  auto moments = [&](float strength, float rotation) {
    auto m = scene::Material::lambert("brushed", glm::vec3(0.9f));
    m.metallic = 1.0f;
    m.roughness = 0.2f;
    m.anisotropyStrength = strength;
    m.anisotropyRotation = rotation;
    auto s = litQuadScene(m);
    s.pointLights[0].position = {0.0, 0.0, 3.0};
    const auto image = test::renderScene(*device, s, kShape, kShape, 16, oneBounce());
    double w = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
    for (uint32_t row = 0; row < kShape; ++row)
      for (uint32_t col = 0; col < kShape; ++col) {
        const auto p = image.pixel(col, row);
        const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        const double x = col + 0.5 - kShape / 2.0, y = kShape / 2.0 - (row + 0.5);
        w += l;
        mx += l * x;
        my += l * y;
        xx += l * x * x;
        yy += l * y * y;
        xy += l * x * y;
      }
    mx /= w;
    my /= w;
    struct {
      double xx, yy, xy;
    } c{xx / w - mx * mx, yy / w - my * my, xy / w - mx * my};
    return c;
  };
  const auto isotropic = moments(0.0f, 0.0f);
  const auto alongX = moments(1.0f, 0.0f);
  const auto alongY = moments(1.0f, float(std::numbers::pi / 2));
  const auto diagonal = moments(1.0f, float(std::numbers::pi / 4));
  INFO("isotropic xx " << isotropic.xx << " yy " << isotropic.yy << " xy " << isotropic.xy);
  INFO("rotation 0: xx " << alongX.xx << " yy " << alongX.yy << " xy " << alongX.xy);
  INFO("quarter turn: xx " << alongY.xx << " yy " << alongY.yy << " xy " << alongY.xy);
  INFO("eighth turn: xx " << diagonal.xx << " yy " << diagonal.yy << " xy " << diagonal.xy);
  // Round within the noise of 16 spp: the spreads agree to 10 %.
  REQUIRE(std::abs(isotropic.xx - isotropic.yy) < 0.1 * isotropic.xx);
  REQUIRE(std::abs(isotropic.xy) < 0.05 * isotropic.xx);
  // A streak: at least twice as long as wide, in the stated direction.
  REQUIRE(alongX.xx > 2.0 * alongX.yy);
  REQUIRE(alongY.yy > 2.0 * alongY.xx);
  REQUIRE(alongX.xx > 1.5 * isotropic.xx);
  // Along x = y: a correlation of at least a half, positive.
  REQUIRE(diagonal.xy > 0.5 * std::sqrt(diagonal.xx * diagonal.yy));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
