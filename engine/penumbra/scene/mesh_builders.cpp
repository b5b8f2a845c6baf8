#include "penumbra/scene/mesh_builders.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace penumbra::scene {

Mesh makeIcosphere(uint32_t subdivisions, float radius, bool inwardFacing, uint32_t material) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : v) p = glm::normalize(p);
  std::vector<uint32_t> f = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                             4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                             6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (uint32_t level = 0; level < subdivisions; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      v.push_back(glm::normalize(v[a] + v[b]));
      return midpoints[key] = uint32_t(v.size() - 1);
    };
    std::vector<uint32_t> next;
    for (size_t i = 0; i < f.size(); i += 3) {
      uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
      uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f = std::move(next);
  }
  Mesh mesh;
  mesh.name = "icosphere";
  mesh.material = material;
  for (auto& p : v) mesh.positions.push_back(p * radius);
  // The icosahedron above winds counter-clockwise seen from outside.
  if (inwardFacing)
    for (size_t i = 0; i < f.size(); i += 3) std::swap(f[i + 1], f[i + 2]);
  mesh.indices = std::move(f);
  return mesh;
}

Mesh makeQuad(glm::vec3 origin, glm::vec3 edgeU, glm::vec3 edgeV, uint32_t material) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.material = material;
  mesh.positions = {origin, origin + edgeU, origin + edgeU + edgeV, origin + edgeV};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

Mesh makeBox(glm::vec3 minCorner, glm::vec3 maxCorner, bool inwardFacing, uint32_t material) {
  Mesh mesh;
  mesh.name = "box";
  mesh.material = material;
  // Corner i takes maxCorner's x, y, z where bit 0, 1, 2 of i is set (exact
  // coordinates, no minCorner + size rounding).
  for (uint32_t i = 0; i < 8; ++i)
    mesh.positions.push_back({(i & 1) ? maxCorner.x : minCorner.x,
                              (i & 2) ? maxCorner.y : minCorner.y,
                              (i & 4) ? maxCorner.z : minCorner.z});
  // Faces -x, +x, -y, +y, -z, +z, each counter-clockwise seen from outside.
  const uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    if (inwardFacing)
      mesh.indices.insert(mesh.indices.end(), {f[0], f[2], f[1], f[0], f[3], f[2]});
    else
      mesh.indices.insert(mesh.indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
  }
  return mesh;
}

Scene makeFurnaceScene(float albedo, float emission, uint32_t subdivisions) {
  Scene scene;
  scene.name = "furnace";
  scene.materials.push_back(Material::lambert("furnace", glm::vec3(albedo), glm::vec3(emission)));
  scene.meshes.push_back(makeIcosphere(subdivisions, 1.0f, true, 0));
  scene.instances.push_back({0, glm::mat4(1.0f)});
  scene.camera.position = glm::vec3(0.0f);
  scene.camera.forward = glm::vec3(0, 0, 1);
  scene.camera.up = glm::vec3(0, 1, 0);
  scene.camera.verticalFovDegrees = 90.0f;
  validate(scene);
  return scene;
}

}  // namespace penumbra::scene
