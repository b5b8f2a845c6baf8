#pragma once
// The API-neutral scene: meshes with materials, instances, a camera. Units are
// metres once loaded (scene files may state a unitScale).
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::scene {

// Which shading model a material uses (docs/materials.md).
enum class MaterialModel {
  Disney,   // the principled BSDF with Burley diffuse
  Lambert,  // Disney parameters, but Lambertian diffuse (glTF, the Cornell box)
  Phong,    // Whitted's Phong model; the path tracer maps it onto Disney
};

struct Material {
  std::string name;
  MaterialModel model = MaterialModel::Disney;
  glm::vec3 baseColor{0.8f};
  glm::vec3 emission{0.0f};  // radiance from the counter-clockwise face
  // Disney (Burley 2012/2015).
  float metallic = 0.0f;
  float roughness = 0.5f;
  float anisotropic = 0.0f;
  float specular = 0.5f;
  float specularTint = 0.0f;
  float sheen = 0.0f;
  float sheenTint = 0.5f;
  float clearcoat = 0.0f;
  float clearcoatGloss = 1.0f;
  float specTrans = 0.0f;
  float ior = 1.5f;
  float subsurface = 0.0f;
  bool thin = false;
  // Phong (Whitted): kd = baseColor.
  float ks = 0.0f;
  float exponent = 32.0f;
  float reflectivity = 0.0f;
  float transparency = 0.0f;

  bool isEmissive() const { return emission.x > 0 || emission.y > 0 || emission.z > 0; }
  // A Lambertian surface of the given reflectance (no specular layer).
  static Material lambert(std::string name, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f));
};

// A delta light for NEE and Whitted: a point light, or a spot light when
// outerConeDegrees < 180.
struct PointLight {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};  // radiant intensity, W/sr per channel
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  float innerConeDegrees = 180.0f;
  float outerConeDegrees = 180.0f;
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise = front
  uint32_t material = 0;
  // Optional per-vertex attributes: each is empty or has one entry per
  // position. Without normals the renderer shades with the geometric normal.
  std::vector<glm::vec3> normals;   // unit, object space
  std::vector<glm::vec4> tangents;  // xyz unit, w = +-1: bitangent = cross(normal, xyz) * w
  std::vector<glm::vec2> uv0;       // glTF convention: (0, 0) is the image's top-left corner
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

// The material-test row (scene/material_row.h): which materials belong to
// its spheres, the base they share and the Disney parameter they vary.
struct MaterialRow {
  Material base;
  std::string vary;
  std::vector<uint32_t> materials;  // one per sphere, first to last
};

// A camera a scene file names (glTF cameras), selectable by name.
struct NamedCamera {
  std::string name;      // the camera's own name
  std::string nodeName;  // the name of the node that places it (glTF), may be empty
  Camera camera;
};

struct Scene {
  std::string name;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<PointLight> pointLights;
  glm::vec3 ambient{0.0f};           // Whitted's ambient term
  Camera camera;                     // the view rendered
  std::vector<NamedCamera> cameras;  // alternatives for selectCamera
  std::optional<MaterialRow> materialRow;
  uint64_t triangleCount() const;
};

// Makes the camera named `name` (its own name or its node's) the scene's view;
// throws penumbra::Error listing the names there are.
void selectCamera(Scene& scene, const std::string& name);

// Checks indices, materials and instances refer to things that exist and that
// positions are finite; throws penumbra::Error naming the scene and the part.
void validate(const Scene& scene);

}  // namespace penumbra::scene
