#include "scene/scene.h"

#include <fmt/format.h>

#include <cmath>

#include "util/error.h"

namespace penumbra::scene {

Material Material::lambert(std::string name, glm::vec3 albedo, glm::vec3 emission) {
  Material m;
  m.name = std::move(name);
  m.model = MaterialModel::Lambert;
  m.baseColor = albedo;
  m.emission = emission;
  m.specular = 0.0f;
  m.roughness = 1.0f;
  return m;
}

uint64_t Scene::triangleCount() const {
  uint64_t n = 0;
  for (const auto& inst : instances) n += meshes.at(inst.mesh).triangleCount();
  return n;
}

void validate(const Scene& scene) {
  auto fail = [&](const std::string& what) {
    throw Error(fmt::format("scene '{}': {}", scene.name, what));
  };
  if (scene.meshes.empty()) fail("has no meshes");
  for (const auto& mesh : scene.meshes) {
    if (mesh.material >= scene.materials.size())
      fail(fmt::format("mesh '{}' uses material {} of {}", mesh.name, mesh.material,
                       scene.materials.size()));
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
      fail(fmt::format("mesh '{}' has {} indices, not a positive multiple of 3", mesh.name,
                       mesh.indices.size()));
    for (uint32_t i : mesh.indices)
      if (i >= mesh.positions.size())
        fail(fmt::format("mesh '{}' has index {} but {} vertices", mesh.name, i,
                         mesh.positions.size()));
    for (const auto& p : mesh.positions)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(fmt::format("mesh '{}' has a non-finite vertex position", mesh.name));
    auto checkAttribute = [&](size_t count, bool finite, const char* what) {
      if (count != 0 && count != mesh.positions.size())
        fail(fmt::format("mesh '{}' has {} {} for {} vertices", mesh.name, count, what,
                         mesh.positions.size()));
      if (!finite) fail(fmt::format("mesh '{}' has non-finite {}", mesh.name, what));
    };
    auto finite = [](const auto& values) {
      for (const auto& v : values)
        for (int i = 0; i < v.length(); ++i)
          if (!std::isfinite(v[i])) return false;
      return true;
    };
    checkAttribute(mesh.normals.size(), finite(mesh.normals), "normals");
    checkAttribute(mesh.tangents.size(), finite(mesh.tangents), "tangents");
    checkAttribute(mesh.uv0.size(), finite(mesh.uv0), "texture coordinates");
  }
  for (const auto& m : scene.materials) {
    auto unit = [](float v) { return v >= 0.0f && v <= 1.0f; };
    for (int i = 0; i < 3; ++i)
      if (!unit(m.baseColor[i]) || !(m.emission[i] >= 0.0f))
        fail(fmt::format("material '{}': baseColor must lie in [0, 1] and emission be non-negative",
                         m.name));
    for (float v : {m.metallic, m.roughness, m.anisotropic, m.specular, m.specularTint, m.sheen,
                    m.sheenTint, m.clearcoat, m.clearcoatGloss, m.specTrans, m.subsurface,
                    m.reflectivity, m.transparency})
      if (!unit(v)) fail(fmt::format("material '{}': a parameter is outside [0, 1]", m.name));
    if (!(m.ior >= 1.0f && m.ior <= 4.0f))
      fail(fmt::format("material '{}': ior {} is outside [1, 4]", m.name, m.ior));
    if (!(m.exponent >= 0.0f)) fail(fmt::format("material '{}': negative Phong exponent", m.name));
  }
  for (const auto& inst : scene.instances)
    if (inst.mesh >= scene.meshes.size())
      fail(fmt::format("an instance refers to mesh {} of {}", inst.mesh, scene.meshes.size()));
  const auto& c = scene.camera;
  if (!(c.verticalFovDegrees > 0.0f && c.verticalFovDegrees < 180.0f))
    fail(fmt::format("camera vertical field of view {} is not in (0, 180)", c.verticalFovDegrees));
  if (glm::length(c.forward) == 0.0f || glm::length(glm::cross(c.forward, c.up)) == 0.0f)
    fail("camera forward and up must be non-zero and not parallel");
}

void selectCamera(Scene& scene, const std::string& name) {
  std::string names;
  for (const auto& c : scene.cameras) {
    if (c.name == name || (!c.nodeName.empty() && c.nodeName == name)) {
      scene.camera = c.camera;
      return;
    }
    names +=
        (names.empty() ? "" : ", ") + fmt::format("'{}'", c.name.empty() ? c.nodeName : c.name);
  }
  throw Error(fmt::format("scene '{}': no camera named '{}' ({})", scene.name, name,
                          names.empty() ? "the scene names no cameras" : "cameras: " + names));
}

}  // namespace penumbra::scene
