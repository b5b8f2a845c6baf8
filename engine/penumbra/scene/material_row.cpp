#include "penumbra/scene/material_row.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "penumbra/scene/mesh_builders.h"
#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

float* scalarParameter(Material& m, std::string_view name) {
  if (name == "metallic") return &m.metallic;
  if (name == "roughness") return &m.roughness;
  if (name == "anisotropic") return &m.anisotropic;
  if (name == "anisotropyStrength") return &m.anisotropyStrength;
  if (name == "anisotropyRotation") return &m.anisotropyRotation;
  if (name == "specular") return &m.specular;
  if (name == "specularTint") return &m.specularTint;
  if (name == "sheen") return &m.sheen;
  if (name == "sheenTint") return &m.sheenTint;
  if (name == "sheenRoughness") return &m.sheenRoughness;
  if (name == "clearcoat") return &m.clearcoat;
  if (name == "clearcoatGloss") return &m.clearcoatGloss;
  if (name == "specTrans") return &m.specTrans;
  if (name == "diffuseTransmission") return &m.diffuseTransmission;
  if (name == "iridescence") return &m.iridescence;
  if (name == "iridescenceIor") return &m.iridescenceIor;
  if (name == "iridescenceThickness") return &m.iridescenceThicknessMaximum;
  if (name == "dispersion") return &m.dispersion;
  if (name == "subsurface") return &m.subsurface;
  if (name == "ior") return &m.ior;
  return nullptr;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

float parseNumber(std::string_view text, std::string_view context) {
  float value = 0;
  const auto* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value))
    throw Error(fmt::format("--set: '{}' in '{}' is not a number", text, context));
  return value;
}

void assignRowMaterials(Scene& scene) {
  auto& row = *scene.materialRow;
  const size_t n = row.materials.size();
  for (size_t i = 0; i < n; ++i) {
    Material m = row.base;
    m.name = fmt::format("{} {}={:.3g}", row.base.name, row.vary,
                         n > 1 ? float(i) / float(n - 1) : 0.0f);
    *scalarParameter(m, row.vary) = n > 1 ? float(i) / float(n - 1) : 0.0f;
    scene.materials[row.materials[i]] = m;
  }
}

void checkVariable(std::string_view vary) {
  const auto& names = variableDisneyParameters();
  if (std::find(names.begin(), names.end(), vary) == names.end())
    throw Error(fmt::format("--vary '{}': not a Disney parameter with range 0..1 ({})", vary,
                            joined(names)));
}

}  // namespace

const std::vector<std::string>& variableDisneyParameters() {
  static const std::vector<std::string> names = {
      "metallic",  "roughness", "anisotropic",    "specular",  "specularTint", "sheen",
      "sheenTint", "clearcoat", "clearcoatGloss", "specTrans", "subsurface"};
  return names;
}

void setMaterialParameter(Material& m, std::string_view name, const std::vector<float>& values) {
  for (auto [colorName, color] :
       {std::pair{"baseColor", &m.baseColor}, std::pair{"emission", &m.emission},
        std::pair{"specularColor", &m.specularColor}, std::pair{"sheenColor", &m.sheenColor},
        std::pair{"diffuseTransmissionColor", &m.diffuseTransmissionColor}})
    if (name == colorName) {
      if (values.size() != 3) throw Error(fmt::format("--set {}: needs 3 numbers (r,g,b)", name));
      *color = {values[0], values[1], values[2]};
      return;
    }
  float* scalar = scalarParameter(m, name);
  if (!scalar)
    throw Error(
        fmt::format("--set: unknown material parameter '{}' (baseColor, emission, specularColor, "
                    "sheenColor, sheenRoughness, ior, anisotropyRotation, anisotropyStrength, "
                    "diffuseTransmission, diffuseTransmissionColor, iridescence, iridescenceIor, "
                    "iridescenceThickness, dispersion, {})",
                    name, joined(variableDisneyParameters())));
  if (values.size() != 1) throw Error(fmt::format("--set {}: needs 1 number", name));
  *scalar = values[0];
}

void addMaterialRow(Scene& scene, const MaterialRowDesc& desc) {
  checkVariable(desc.vary);
  if (desc.count < 1 || desc.count > 64) throw Error("material row: count must be 1..64");
  if (!(desc.radius > 0.0f)) throw Error("material row: radius must be positive");
  MaterialRow row;
  row.base = desc.base;
  row.vary = desc.vary;
  for (uint32_t i = 0; i < desc.count; ++i) {
    const float t = desc.count > 1 ? float(i) / float(desc.count - 1) : 0.0f;
    row.materials.push_back(uint32_t(scene.materials.size()));
    scene.materials.push_back(desc.base);
    Mesh sphere = makeIcosphere(desc.subdivisions, desc.radius, false, row.materials.back());
    sphere.name = fmt::format("material row sphere {}", i);
    Instance instance;
    instance.mesh = uint32_t(scene.meshes.size());
    instance.transform[3] = glm::vec4(glm::mix(desc.first, desc.last, t), 1.0f);
    scene.meshes.push_back(std::move(sphere));
    scene.instances.push_back(instance);
  }
  scene.materialRow = row;
  assignRowMaterials(scene);
}

void changeMaterialRow(Scene& scene, const std::string& vary, const std::string& assignments) {
  if (!scene.materialRow)
    throw Error(
        fmt::format("--vary/--set: scene '{}' has no material-test row (try --scene material-test)",
                    scene.name));
  auto& row = *scene.materialRow;
  if (!vary.empty()) {
    checkVariable(vary);
    row.vary = vary;
  }
  // "a=1,b=0.9,0.6,0.2": split at commas; a piece without '=' continues the
  // previous name's value list.
  std::string name;
  std::vector<float> values;
  auto flush = [&] {
    if (!name.empty()) setMaterialParameter(row.base, name, values);
  };
  size_t start = 0;
  while (!assignments.empty() && start <= assignments.size()) {
    size_t comma = assignments.find(',', start);
    if (comma == std::string::npos) comma = assignments.size();
    const std::string piece = assignments.substr(start, comma - start);
    const size_t eq = piece.find('=');
    if (eq != std::string::npos) {
      flush();
      name = piece.substr(0, eq);
      values = {parseNumber(piece.substr(eq + 1), assignments)};
    } else {
      if (name.empty()) throw Error(fmt::format("--set '{}': expected name=value", assignments));
      values.push_back(parseNumber(piece, assignments));
    }
    start = comma + 1;
  }
  flush();
  assignRowMaterials(scene);
}

}  // namespace penumbra::scene
