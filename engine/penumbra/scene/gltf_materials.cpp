#include "penumbra/scene/gltf_materials.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "penumbra/scene/gltf_textures.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {
namespace {

float clamp01(double v) {
  return std::isfinite(v) ? float(std::clamp(v, 0.0, 1.0)) : 0.0f;
}

// tinygltf's Value::Get(key) asserts an object; extensions from a file may be anything.
const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
  return object.Has(key) ? &object.Get(key) : nullptr;
}

double number(const tinygltf::Value& object, const char* key, double fallback) {
  const auto* v = member(object, key);
  return v && v->IsNumber() ? v->GetNumberAsDouble() : fallback;
}

glm::vec3 vec3(const tinygltf::Value& object, const char* key, glm::vec3 fallback) {
  const auto* v = member(object, key);
  if (!v || !v->IsArray() || v->ArrayLen() != 3) return fallback;
  glm::vec3 r;
  for (int i = 0; i < 3; ++i) {
    const auto& c = v->Get(i);
    r[i] = c.IsNumber() ? float(c.GetNumberAsDouble()) : fallback[i];
  }
  return r;
}

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
  auto it = m.extensions.find(name);
  return it == m.extensions.end() ? nullptr : &it->second;
}

void convertAlpha(const tinygltf::Material& src, float alpha, const std::string& where,
                  MaterialConversion& out, std::vector<std::string>& warnings) {
  Material& m = out.material;
  m.alpha = alpha;
  const bool textured = src.pbrMetallicRoughness.baseColorTexture.index >= 0;
  if (src.alphaMode == "MASK") {
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = std::isfinite(src.alphaCutoff) ? float(std::max(0.0, src.alphaCutoff)) : 0.5f;
    // With a texture the renderer cuts per texel (alpha factor x texel alpha).
    out.invisible = !textured && alpha < m.alphaCutoff;
  } else if (src.alphaMode == "BLEND") {
    // Rendered as stochastic coverage (alpha is the chance a ray stops), so
    // the image converges to the glTF "over" blend of surface and background.
    m.alphaMode = AlphaMode::Blend;
  } else if (src.alphaMode != "OPAQUE") {
    warnings.push_back(fmt::format("{}: alphaMode '{}' is not a glTF alpha mode; OPAQUE used",
                                   where, src.alphaMode));
  }
}

// Material extensions' textures that are not read (gltf_textures.h's
// extensionTextures lists those that are): only their factors apply.
void warnExtensionTextures(const tinygltf::Material& src, const std::string& where,
                           std::vector<std::string>& warnings) {
  auto read = [](const std::string& extension, const std::string& key) {
    for (const ExtensionTexture& t : extensionTextures())
      if (extension == t.extension && key == t.key) return true;
    return false;
  };
  for (const auto& [name, value] : src.extensions) {
    std::string textures;
    for (const auto& key : value.Keys())
      if (member(value.Get(key), "index") && !read(name, key))
        textures += (textures.empty() ? "" : ", ") + key;
    if (!textures.empty())
      warnings.push_back(fmt::format("{}: {} textures ({}) are not supported; factors used", where,
                                     name, textures));
  }
}

}  // namespace

const std::vector<std::string_view>& supportedExtensions() {
  static const std::vector<std::string_view> names{
      "KHR_materials_emissive_strength", "KHR_materials_transmission", "KHR_materials_ior",
      "KHR_materials_volume", "KHR_materials_clearcoat", "KHR_materials_specular",
      "KHR_materials_sheen", "KHR_materials_unlit", "KHR_materials_anisotropy",
      "KHR_materials_diffuse_transmission", "KHR_materials_iridescence", "KHR_materials_dispersion",
      "KHR_texture_transform",
      "KHR_materials_variants",   // Scene::materialVariants, --variant
      "KHR_lights_punctual",      // gltf_lights.h
      "EXT_mesh_gpu_instancing",  // gltf_instancing.h
      // gltf_accessors.h decodes every integer type
      "KHR_mesh_quantization",
#ifdef PENUMBRA_HAVE_MESHOPT
      "EXT_meshopt_compression",  // gltf_meshopt.h
#endif
#ifdef PENUMBRA_HAVE_WEBP
      "EXT_texture_webp",  // gltf_textures.h
#endif
#ifdef PENUMBRA_HAVE_DRACO
      "KHR_draco_mesh_compression",  // gltf_draco.h
#endif
  };
  return names;
}

bool isSupportedExtension(std::string_view name) {
  const auto& names = supportedExtensions();
  return std::find(names.begin(), names.end(), name) != names.end();
}

float f0FromIor(float ior) {
  const float r = (ior - 1.0f) / (ior + 1.0f);
  return r * r;
}

Material defaultMaterial() {
  Material m;
  m.name = "glTF default";
  m.model = MaterialModel::Lambert;
  m.baseColor = glm::vec3(1.0f);
  m.metallic = 1.0f;
  m.roughness = 1.0f;
  m.specular = f0FromIor(1.5f) / 0.08f;  // F0 0.04
  m.emissionIsLighting = false;
  return m;
}

MaterialConversion convertMaterial(const tinygltf::Material& src, const std::string& where,
                                   std::vector<std::string>& warnings) {
  MaterialConversion out;
  Material& m = out.material;
  m = defaultMaterial();
  m.name = src.name;
  const auto& pbr = src.pbrMetallicRoughness;
  float alpha = 1.0f;
  if (pbr.baseColorFactor.size() == 4) {
    for (int i = 0; i < 3; ++i) m.baseColor[i] = clamp01(pbr.baseColorFactor[size_t(i)]);
    alpha = clamp01(pbr.baseColorFactor[3]);
  }
  m.metallic = clamp01(pbr.metallicFactor);
  m.roughness = clamp01(pbr.roughnessFactor);
  if (src.emissiveFactor.size() == 3)
    for (int i = 0; i < 3; ++i)
      m.emission[i] = std::isfinite(src.emissiveFactor[size_t(i)])
                          ? float(std::max(0.0, src.emissiveFactor[size_t(i)]))
                          : 0.0f;

  convertAlpha(src, alpha, where, out, warnings);
  m.normalScale = std::isfinite(src.normalTexture.scale) ? float(src.normalTexture.scale) : 1.0f;
  m.occlusionStrength = clamp01(src.occlusionTexture.strength);
  warnExtensionTextures(src, where, warnings);

  if (const auto* e = extension(src, "KHR_materials_emissive_strength"))
    m.emission *= float(std::max(0.0, number(*e, "emissiveStrength", 1.0)));

  float ior = 1.5f;
  if (const auto* e = extension(src, "KHR_materials_ior")) {
    const double value = number(*e, "ior", 1.5);
    ior = float(std::clamp(value, 1.0, 4.0));
    if (ior != float(value))
      warnings.push_back(fmt::format("{}: ior {} clamped to {}", where, value, ior));
  }
  m.ior = ior;
  // The dielectric F0 = min(F0(ior) * specularColorFactor, 1) * specularFactor
  // (KHR_materials_specular), through the Disney F0 = specular * min(0.08 *
  // specularColor, 1); its F90 = specularFactor.
  float factor = 1.0f;
  glm::vec3 colorFactor(1.0f);
  if (const auto* e = extension(src, "KHR_materials_specular")) {
    factor = clamp01(number(*e, "specularFactor", 1.0));
    colorFactor = vec3(*e, "specularColorFactor", glm::vec3(1.0f));
    for (int i = 0; i < 3; ++i)
      if (!(colorFactor[i] >= 0.0f) || !std::isfinite(colorFactor[i]))
        throw Error(fmt::format(
            "{}: KHR_materials_specular specularColorFactor must be finite and non-negative",
            where));
  }
  m.specularF90 = factor;
  const glm::vec3 f0 = colorFactor * f0FromIor(ior);
  // A grey F0 that `specular` alone reaches (<= 0.08) is written as `specular`
  // with specularColor 1: a scene of such materials builds without the
  // coloured F0's code (PT_EFFECT_SPECULAR_COLOR) unless specularFactor
  // (F90) is below 1 or a specular texture scales it. A specular colour texture
  // (<= 1) cannot push it past the clamp then, so both forms agree under it.
  if (f0.x == f0.y && f0.y == f0.z && f0.x <= 1.0f && factor * f0.x <= 0.08f) {
    m.specular = factor * f0.x / 0.08f;
    m.specularColor = glm::vec3(1.0f);
  } else {
    m.specular = factor;
    m.specularColor = f0 / 0.08f;
  }

  if (const auto* e = extension(src, "KHR_materials_transmission"))
    m.specTrans = clamp01(number(*e, "transmissionFactor", 0.0));
  // glTF transmission is thin-walled unless a volume gives it thickness.
  m.thin = true;
  if (const auto* e = extension(src, "KHR_materials_volume")) {
    m.thin = !(number(*e, "thicknessFactor", 0.0) > 0.0);
    const double distance = number(*e, "attenuationDistance", INFINITY);
    if (!(distance > 0.0))
      throw Error(fmt::format("{}: KHR_materials_volume attenuationDistance must be > 0", where));
    m.attenuationDistance = float(distance);
    if (const tinygltf::Value& c = e->Get("attenuationColor"); c.IsArray() && c.ArrayLen() == 3)
      for (int k = 0; k < 3; ++k) m.attenuationColor[k] = clamp01(c.Get(k).GetNumberAsDouble());
    if (m.thin && std::isfinite(distance))
      warnings.push_back(
          fmt::format("{}: volume attenuation needs thicknessFactor > 0 (a thin surface has no "
                      "inside); ignored",
                      where));
  }

  if (const auto* e = extension(src, "KHR_materials_dispersion")) {
    const double value = number(*e, "dispersion", 0.0);
    if (!(value >= 0.0) || !std::isfinite(value))
      throw Error(fmt::format(
          "{}: KHR_materials_dispersion dispersion must be a finite number >= 0", where));
    m.dispersion = float(std::min(value, 10.0));
    if (m.dispersion != float(value))
      warnings.push_back(fmt::format("{}: dispersion {} clamped to 10", where, value));
    // The extension builds on KHR_materials_volume: only a volume refracts.
    if (m.dispersion > 0.0f && (m.thin || m.specTrans == 0.0f))
      warnings.push_back(fmt::format(
          "{}: dispersion needs transmission through a volume (KHR_materials_transmission and "
          "KHR_materials_volume's thicknessFactor > 0); ignored",
          where));
  }

  if (const auto* e = extension(src, "KHR_materials_clearcoat")) {
    m.clearcoat = clamp01(number(*e, "clearcoatFactor", 0.0));
    // The Lambert model's coat is this extension's: alpha = (1 - gloss)^2.
    m.clearcoatGloss = 1.0f - clamp01(number(*e, "clearcoatRoughnessFactor", 0.0));
    const tinygltf::Value& normal = e->Get("clearcoatNormalTexture");
    if (normal.IsObject()) {
      const float scale = float(number(normal, "scale", 1.0));
      m.clearcoatNormalScale = std::isfinite(scale) ? scale : 1.0f;
    }
  }

  if (const auto* e = extension(src, "KHR_materials_sheen")) {
    const glm::vec3 color = glm::clamp(vec3(*e, "sheenColorFactor", glm::vec3(0.0f)), 0.0f, 1.0f);
    m.sheen = std::max({color.x, color.y, color.z});
    m.sheenTint = 0.0f;
    if (m.sheen > 0.0f) m.sheenColor = color / m.sheen;
    m.sheenRoughness = clamp01(number(*e, "sheenRoughnessFactor", 0.0));
  }

  if (const auto* e = extension(src, "KHR_materials_diffuse_transmission")) {
    m.diffuseTransmission = clamp01(number(*e, "diffuseTransmissionFactor", 0.0));
    m.diffuseTransmissionColor =
        glm::clamp(vec3(*e, "diffuseTransmissionColorFactor", glm::vec3(1.0f)), 0.0f, 1.0f);
  }

  if (const auto* e = extension(src, "KHR_materials_iridescence")) {
    m.iridescence = clamp01(number(*e, "iridescenceFactor", 0.0));
    m.iridescenceIor = float(std::clamp(number(*e, "iridescenceIor", 1.3), 1.0, 4.0));
    auto thickness = [&](const char* key, double fallback) {
      const double t = number(*e, key, fallback);
      return float(std::isfinite(t) ? std::clamp(t, 0.0, 1e5) : fallback);
    };
    m.iridescenceThicknessMinimum = thickness("iridescenceThicknessMinimum", 100.0);
    m.iridescenceThicknessMaximum = thickness("iridescenceThicknessMaximum", 400.0);
  }

  if (const auto* e = extension(src, "KHR_materials_anisotropy")) {
    m.anisotropyStrength = clamp01(number(*e, "anisotropyStrength", 0.0));
    const double rotation = number(*e, "anisotropyRotation", 0.0);
    if (!std::isfinite(rotation))
      throw Error(
          fmt::format("{}: KHR_materials_anisotropy anisotropyRotation is not a number", where));
    m.anisotropyRotation = float(std::remainder(rotation, 2.0 * std::numbers::pi));
  }

  // Only the base colour (factor, texture, COLOR_0) of an unlit material
  // counts; its emission would otherwise be tabulated as a light.
  if (extension(src, "KHR_materials_unlit")) {
    m.model = MaterialModel::Unlit;
    m.emission = glm::vec3(0.0f);
  }
  return out;
}

}  // namespace penumbra::scene::gltf
