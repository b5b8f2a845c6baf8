#include "scene/scene.h"

#include <fmt/format.h>

#include <cmath>

#include "util/error.h"

namespace penumbra::scene {

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

}  // namespace penumbra::scene
