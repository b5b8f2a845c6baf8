#pragma once
// The API-neutral scene: meshes with materials, instances, a camera. Units are
// metres once loaded (scene files may state a unitScale).
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace penumbra::scene {

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};    // Lambertian reflectance
  glm::vec3 emission{0.0f};  // radiance from the counter-clockwise face
  bool isEmissive() const { return emission.x > 0 || emission.y > 0 || emission.z > 0; }
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise = front
  uint32_t material = 0;
  uint32_t triangleCount() const { return uint32_t(indices.size() / 3); }
};

struct Instance {
  uint32_t mesh = 0;
  glm::mat4 transform{1.0f};  // object to world
};

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, 1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float verticalFovDegrees = 45.0f;
};

struct Scene {
  std::string name;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  Camera camera;
  uint64_t triangleCount() const;
};

// Checks indices, materials and instances refer to things that exist and that
// positions are finite; throws penumbra::Error naming the scene and the part.
void validate(const Scene& scene);

}  // namespace penumbra::scene
