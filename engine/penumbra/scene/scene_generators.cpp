#include "penumbra/scene/scene_generators.h"

#include <fmt/format.h>

#include "penumbra/scene/json_reading.h"
#include "penumbra/scene/mesh_builders.h"
#include "penumbra/scene/terrain.h"
#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

uint32_t materialOf(const json& entry, const char* key,
                    const std::map<std::string, uint32_t>& index, const std::string& where) {
  const json& name = require(entry, key, where);
  if (!name.is_string()) throw Error(fmt::format("{}: \"{}\" must be a material name", where, key));
  auto it = index.find(name.get<std::string>());
  if (it == index.end())
    throw Error(fmt::format("{}: unknown material '{}'", where, name.get<std::string>()));
  return it->second;
}

uint32_t readCount(const json& entry, const char* key, uint32_t fallback, uint32_t max,
                   const std::string& where) {
  return uint32_t(readInteger(entry, key, fallback, 1, max, where));
}

// The "count" array and the product of its counts (what the entry makes).
std::vector<uint32_t> readCounts(const json& entry, size_t n, uint32_t max,
                                 const std::string& where, uint64_t& product) {
  const json& v = require(entry, "count", where);
  if (!v.is_array() || v.size() != n)
    throw Error(fmt::format("{}: \"count\" must be an array of {} integers", where, n));
  std::vector<uint32_t> counts;
  product = 1;
  for (size_t i = 0; i < n; ++i) {
    counts.push_back(uint32_t(toInteger(v[i], where, fmt::format("count[{}]", i), 1, max)));
    product *= counts.back();
  }
  return counts;
}

void addTerrain(Scene& scene, const json& e, const std::map<std::string, uint32_t>& materials,
                float scale, const std::string& where, const InputLimits& limits) {
  TerrainDesc desc;
  desc.resolution = uint32_t(readInteger(e, "resolution", desc.resolution, 0, UINT32_MAX, where));
  if (desc.resolution < 2) throw Error(where + ": \"resolution\" must be at least 2");
  // Checked here, before makeTerrain allocates (resolution^2 vertices).
  requireAtMost(desc.resolution, limits.maxTerrainResolution, "maxTerrainResolution",
                where + " \"resolution\"");
  const uint64_t cells = uint64_t(desc.resolution - 1) * (desc.resolution - 1);
  requireAtMost(saturatingAdd(storedTriangles(scene), 2 * cells), limits.maxTriangles,
                "maxTriangles", where + ": the scene's triangle count with the terrain");
  desc.size = readFloat(e, "size", desc.size, where) * scale;
  desc.height = readFloat(e, "height", desc.height, where) * scale;
  desc.octaves = readCount(e, "octaves", desc.octaves, 16, where);
  desc.seed = readCount(e, "seed", desc.seed, 1u << 30, where);
  Mesh mesh = makeTerrain(desc, materialOf(e, "material", materials, where));
  Instance instance;
  instance.mesh = uint32_t(scene.meshes.size());
  if (e.contains("translate"))
    instance.transform[3] =
        glm::vec4(readVec3(e.at("translate"), where + " translate") * scale, 1.0f);
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back(instance);
}

void addSpheres(Scene& scene, const json& e, const std::map<std::string, uint32_t>& materials,
                float scale, const std::string& where, const InputLimits& limits) {
  uint64_t instances = 0;
  const auto count = readCounts(e, 2, 1024, where, instances);
  requireAtMost(scene.instances.size() + instances, limits.maxInstances, "maxInstances",
                where + ": the scene's instance count with the grid");
  const float spacing = readFloat(e, "spacing", 1.0f, where) * scale;
  const float radius = readFloat(e, "radius", 0.4f, where) * scale;
  const glm::vec3 origin = readVec3(require(e, "origin", where), where + " origin") * scale;
  const uint32_t subdivisions = readCount(e, "subdivisions", 4, UINT32_MAX, where);
  requireAtMost(subdivisions, limits.maxSphereSubdivisions, "maxSphereSubdivisions",
                where + " \"subdivisions\"");
  requireAtMost(saturatingAdd(storedTriangles(scene), icosphereTriangles(subdivisions)),
                limits.maxTriangles, "maxTriangles",
                where + ": the scene's triangle count with the sphere");
  if (!(radius > 0.0f) || !(spacing > 0.0f))
    throw Error(where + ": radius and spacing must be positive");
  Mesh sphere =
      makeIcosphere(subdivisions, radius, false, materialOf(e, "material", materials, where));
  sphere.name = fmt::format("generated icosphere ({} triangles)", sphere.triangleCount());
  const uint32_t mesh = uint32_t(scene.meshes.size());
  scene.meshes.push_back(std::move(sphere));
  for (uint32_t z = 0; z < count[1]; ++z)
    for (uint32_t x = 0; x < count[0]; ++x) {
      Instance instance;
      instance.mesh = mesh;
      instance.transform[3] =
          glm::vec4(origin + spacing * glm::vec3(float(x), 0.0f, float(z)), 1.0f);
      scene.instances.push_back(instance);
    }
}

void addImplicitGrid(Scene& scene, const json& e, const std::map<std::string, uint32_t>& materials,
                     float scale, const std::string& where, const InputLimits& limits) {
  uint64_t objects = 0;
  const auto count = readCounts(e, 3, 256, where, objects);
  requireAtMost(scene.implicits.size() + objects, limits.maxImplicitObjects, "maxImplicitObjects",
                where + ": the scene's implicit object count with the grid");
  const float spacing = readFloat(e, "spacing", 1.0f, where) * scale;
  const float size = readFloat(e, "size", 0.3f, where) * scale;
  const glm::vec3 origin = readVec3(require(e, "origin", where), where + " origin") * scale;
  if (!(size > 0.0f) || !(spacing > 0.0f))
    throw Error(where + ": size and spacing must be positive");
  const json& names = require(e, "materials", where);
  if (!names.is_array() || names.empty())
    throw Error(where + ": \"materials\" must be a non-empty array");
  std::vector<uint32_t> palette;
  for (size_t i = 0; i < names.size(); ++i) {
    json one = {{"m", names[i]}};
    palette.push_back(materialOf(one, "m", materials, where));
  }
  uint32_t n = 0;
  for (uint32_t y = 0; y < count[1]; ++y)
    for (uint32_t z = 0; z < count[2]; ++z)
      for (uint32_t x = 0; x < count[0]; ++x, ++n) {
        ImplicitObject o;
        o.name = fmt::format("grid object {}", n);
        o.material = palette[n % palette.size()];
        // Unit-size shapes scaled uniformly, so SDF kinds keep a true distance bound.
        switch (n % 4) {
          case 0:
            o.shape = implicit::Sphere{1.0f};
            break;
          case 1:
            o.shape = implicit::Box{glm::vec3(0.8f)};
            break;
          case 2:
            o.shape = implicit::Torus{0.8f, 0.25f};
            break;
          default:
            o.shape = implicit::RoundedBox{glm::vec3(0.75f), 0.2f};
            break;
        }
        o.transform = glm::mat4(size);
        o.transform[3] =
            glm::vec4(origin + spacing * glm::vec3(float(x), float(y), float(z)), 1.0f);
        scene.implicits.push_back(std::move(o));
      }
}

}  // namespace

void addGenerated(Scene& scene, const json& generated,
                  const std::map<std::string, uint32_t>& materialIndex, float scale,
                  const std::string& at, const InputLimits& limits) {
  if (!generated.is_array()) throw Error(at + ": \"generated\" must be an array");
  for (size_t i = 0; i < generated.size(); ++i) {
    const json& e = generated[i];
    const std::string where = fmt::format("{} generated[{}]", at, i);
    const std::string kind = requireString(e, "kind", where);
    if (kind == "terrain")
      addTerrain(scene, e, materialIndex, scale, where, limits);
    else if (kind == "spheres")
      addSpheres(scene, e, materialIndex, scale, where, limits);
    else if (kind == "implicitGrid")
      addImplicitGrid(scene, e, materialIndex, scale, where, limits);
    else
      throw Error(
          fmt::format("{}: unknown kind '{}' (terrain, spheres, implicitGrid)", where, kind));
  }
}

}  // namespace penumbra::scene
