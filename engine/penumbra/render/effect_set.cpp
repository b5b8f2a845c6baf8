#include "penumbra/render/effect_set.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <utility>

#include "effects.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"
#include "penumbra_shaders.h"

namespace penumbra::render {
namespace {

uint32_t materialEffectsOf(const scene::Material& m) {
  uint32_t effects = 0;
  // Whitted reads the Phong fields of every material; the path tracer maps a
  // Phong material onto Disney (shaders/shared/material.hlsli: reflectivity ->
  // metallic, ks -> specular, transparency -> specTrans).
  if (m.reflectivity > 0.0f || m.ks > 0.0f) effects |= PT_EFFECT_SPECULAR;
  if (m.transparency > 0.0f) effects |= PT_EFFECT_TRANSMISSION;
  for (uint32_t ref : m.textures())
    if (ref != scene::Material::kNoTexture) effects |= PT_EFFECT_TEXTURES;
  if (alphaMasked(m)) effects |= PT_EFFECT_ALPHA_MASK;
  // An unlit material's code lives with the surface detail (effects.h).
  if (m.model == scene::MaterialModel::Unlit) return effects | PT_EFFECT_TEXTURES;
  if (m.model == scene::MaterialModel::Phong) return effects;
  if (m.metallic > 0.0f || m.specular > 0.0f) effects |= PT_EFFECT_SPECULAR;
  const bool greyF0 = m.specularColor == glm::vec3(1.0f) &&
                      m.specularColorTexture == scene::Material::kNoTexture &&
                      m.specularTint == 0.0f;
  // glTF's F90 = specularFactor, scaled by the specular texture's alpha.
  const bool fullF90 = m.specularF90 >= 1.0f && m.specularTexture == scene::Material::kNoTexture;
  // Even a metal: a metallic texture can leave parts of it dielectric.
  if (m.specular > 0.0f && !(greyF0 && fullF90)) effects |= PT_EFFECT_SPECULAR_COLOR;
  if (m.specTrans > 0.0f) effects |= PT_EFFECT_TRANSMISSION;
  // The lambert model (glTF's) has the extensions' coat and sheen
  // (MATERIAL_FLAG_GGX_COAT, MATERIAL_FLAG_CHARLIE_SHEEN); Disney has its own.
  const bool gltf = m.model == scene::MaterialModel::Lambert;
  if (m.clearcoat > 0.0f) effects |= PT_EFFECT_CLEARCOAT | (gltf ? PT_EFFECT_GLTF_COAT : 0u);
  if (m.sheen > 0.0f) effects |= PT_EFFECT_SHEEN | (gltf ? PT_EFFECT_GLTF_SHEEN : 0u);
  // glTF anisotropy turns the tangent frame (effects.h): surface detail.
  if (m.anisotropyStrength > 0.0f) effects |= PT_EFFECT_TEXTURES;
  // Its texture only scales the factor: a factor of 0 stays 0.
  if (m.diffuseTransmission > 0.0f) effects |= PT_EFFECT_DIFFUSE_TRANSMISSION;
  // The film colours the specular layer's reflectance: nothing without one.
  if (m.iridescence > 0.0f && (effects & PT_EFFECT_SPECULAR) != 0u)
    effects |= PT_EFFECT_IRIDESCENCE;
  // Only a volume's refraction bends each wavelength its own way.
  if (m.dispersion > 0.0f && m.specTrans > 0.0f && !m.thin) effects |= PT_EFFECT_DISPERSION;
  return effects;
}

struct EntryPointBits {
  std::string_view shader;
  uint32_t bits;
};
constexpr EntryPointBits kVariantBits[] = {{"path_trace.rgen", PT_PATH_TRACE_EFFECT_BITS},
                                           {"whitted.rgen", PT_WHITTED_EFFECT_BITS}};

}  // namespace

bool alphaMasked(const scene::Material& m, bool vertexAlpha) {
  const bool textured = m.baseColorTexture != scene::Material::kNoTexture;
  if (m.alphaMode == scene::AlphaMode::Mask) return textured || vertexAlpha;
  return m.alphaMode == scene::AlphaMode::Blend && (textured || vertexAlpha || m.alpha < 1.0f);
}

bool hasVertexAlpha(const scene::Mesh& mesh) {
  return std::any_of(mesh.colors.begin(), mesh.colors.end(),
                     [](const glm::vec4& c) { return c.a < 1.0f; });
}

uint32_t meshEffects(const scene::Mesh& mesh) {
  return mesh.colors.empty() ? 0u : uint32_t(PT_EFFECT_TEXTURES);
}

uint32_t deriveMaterialEffects(const scene::Material& material) {
  return materialEffectsOf(material);
}

uint32_t cameraEffects(const scene::Camera& camera) {
  return camera.orthographic() ? uint32_t(PT_EFFECT_ORTHOGRAPHIC) : 0u;
}

uint32_t deriveEffects(const scene::Scene& scene, const std::optional<scene::Camera>& camera) {
  uint32_t effects = cameraEffects(camera ? *camera : scene.camera);
  if (!scene.pointLights.empty()) effects |= PT_EFFECT_DELTA_LIGHTS;
  if (scene.environment.present()) effects |= PT_EFFECT_ENVIRONMENT;
  // Materials of meshes that are drawn, not every material the file lists.
  auto use = [&](uint32_t materialIndex) {
    const auto& material = scene.materials.at(materialIndex);
    effects |= materialEffectsOf(material);
    if (material.isEmissive()) effects |= PT_EFFECT_AREA_LIGHTS;
  };
  for (const auto& instance : scene.instances) {
    const scene::Mesh& mesh = scene.meshes.at(instance.mesh);
    use(mesh.material);
    effects |= meshEffects(mesh);
    if (alphaMasked(scene.materials.at(mesh.material), hasVertexAlpha(mesh)))
      effects |= PT_EFFECT_ALPHA_MASK;
  }
  for (const auto& object : scene.implicits) use(object.material);
  return effects;
}

namespace {
constexpr std::pair<uint32_t, const char*> kEffectNames[] = {
    {PT_EFFECT_AREA_LIGHTS, "area-lights"},
    {PT_EFFECT_DELTA_LIGHTS, "delta-lights"},
    {PT_EFFECT_SPECULAR, "specular"},
    {PT_EFFECT_TRANSMISSION, "transmission"},
    {PT_EFFECT_CLEARCOAT, "clearcoat"},
    {PT_EFFECT_SHEEN, "sheen"},
    {PT_EFFECT_TEXTURES, "textures"},
    {PT_EFFECT_ALPHA_MASK, "alpha-mask"},
    {PT_EFFECT_ENVIRONMENT, "environment"},
    {PT_EFFECT_ORTHOGRAPHIC, "orthographic"},
    {PT_EFFECT_SPECULAR_COLOR, "specular-color"},
    {PT_EFFECT_GLTF_COAT, "gltf-coat"},
    {PT_EFFECT_GLTF_SHEEN, "gltf-sheen"},
    {PT_EFFECT_DIFFUSE_TRANSMISSION, "diffuse-transmission"},
    {PT_EFFECT_IRIDESCENCE, "iridescence"},
    {PT_EFFECT_DISPERSION, "dispersion"}};
constexpr uint32_t namedEffects() {
  uint32_t bits = 0;
  for (const auto& [bit, name] : kEffectNames) bits |= bit;
  return bits;
}
// A bit added to effects.h gets a name here (--print-effects, the logs).
static_assert(namedEffects() == PT_EFFECTS_ALL, "every PT_EFFECT_* bit needs a name");
}  // namespace

std::vector<std::string> effectNames(uint32_t effects) {
  std::vector<std::string> names;
  for (const auto& [bit, name] : kEffectNames)
    if (effects & bit) names.emplace_back(name);
  return names;
}

uint32_t deriveFeatures(const scene::Scene& scene, const std::optional<scene::Camera>& camera) {
  uint32_t features = 0;
  for (const auto& light : scene.pointLights) {
    if (light.type == scene::LightType::Directional) features |= kFeatureDirectionalLights;
    if (light.type == scene::LightType::Directional && light.angularRadiusDegrees > 0.0f)
      features |= kFeatureSoftSun;
    if (light.type == scene::LightType::Spot) features |= kFeatureSpotLights;
  }
  const scene::Camera& view = camera ? *camera : scene.camera;
  if (view.apertureRadius > 0.0f) features |= kFeatureThinLens;
  if (view.apertureRadius > 0.0f && view.apertureBlades >= 3) features |= kFeatureLensBlades;
  auto absorbs = [&](uint32_t materialIndex) {
    const auto& m = scene.materials.at(materialIndex);
    const bool transmits =
        m.specTrans > 0.0f || m.transparency > 0.0f || m.diffuseTransmission > 0.0f;
    return transmits && !m.thin && std::isfinite(m.attenuationDistance);
  };
  for (const auto& instance : scene.instances)
    if (absorbs(scene.meshes.at(instance.mesh).material)) features |= kFeatureAbsorption;
  for (const auto& object : scene.implicits)
    if (absorbs(object.material)) features |= kFeatureAbsorption;
  return features;
}

std::vector<std::string> featureNames(uint32_t features) {
  static const char* const kNames[] = {"directional-lights", "soft-sun",    "spot-lights",
                                       "thin-lens",          "lens-blades", "absorption"};
  std::vector<std::string> names;
  for (int bit = 0; bit < int(std::size(kNames)); ++bit)
    if (features & (1u << bit)) names.emplace_back(kNames[bit]);
  return names;
}

std::string effectVariant(std::string_view shader, uint32_t effects) {
  for (const auto& entry : kVariantBits) {
    if (entry.shader != shader) continue;
    const uint32_t wanted = effects & entry.bits;
    const auto dot = shader.find('.');
    auto name = [&](uint32_t mask) {
      if (mask == entry.bits) return std::string(shader);
      return fmt::format("{}.e{}{}", shader.substr(0, dot), mask, shader.substr(dot));
    };
    // Only some subsets are built (shaders/effect_variants.cmake). Otherwise
    // the smallest built superset: every effect the scene needs, the fewest
    // it does not, and of those the least code. Supersets with as many extra
    // bits differ in what the extra bits hold, and where the megakernel runs
    // as one program its time follows its code (docs/results.md,
    // "Iridescence"). The full variant always exists.
    const uint32_t optional = entry.bits & ~wanted;
    uint32_t best = entry.bits;
    size_t bestWords = shaders::find(name(best)).size();
    // Every subset of the optional bits, in increasing order: (x - m) & m.
    for (uint32_t extra = 0;; extra = (extra - optional) & optional) {
      const uint32_t mask = wanted | extra;
      const int more = std::popcount(mask) - std::popcount(best);
      if (more <= 0) {
        const size_t words = shaders::find(name(mask)).size();
        if (words > 0 && (more < 0 || words < bestWords)) {
          best = mask;
          bestWords = words;
        }
      }
      if (extra == optional) break;
    }
    // The same image, a little less saved: a detail for whoever tunes the
    // variant list, not news on every render.
    if (best != wanted)
      log::debug("no {} variant is built for effects {:#x}; using {:#x}", shader, wanted, best);
    return name(best);
  }
  throw Error(fmt::format("no effect variants are built for shader '{}'", shader));
}

}  // namespace penumbra::render
