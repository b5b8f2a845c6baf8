#include "scene/scene_loader.h"

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "util/embedded_files.h"
#include "util/error.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

glm::vec3 readVec3(const json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 3)
    throw Error(fmt::format("{}: expected an array of 3 numbers", where));
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!value[i].is_number()) throw Error(fmt::format("{}: element {} is not a number", where, i));
    v[i] = value[i].get<float>();
  }
  return v;
}

const json& require(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw Error(fmt::format("{}: missing \"{}\"", where, key));
  return object.at(key);
}

}  // namespace

Scene parseScene(std::string_view text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(fmt::format("scene '{}': invalid JSON at byte {}: {}", source, e.byte, e.what()));
  }
  if (doc.value("format", "") != "penumbra-scene")
    throw Error(fmt::format("scene '{}': not a penumbra scene (\"format\" must be \"penumbra-scene\")",
                            source));
  if (doc.value("version", 0) != 1)
    throw Error(fmt::format("scene '{}': unsupported version (this build reads version 1)", source));

  Scene scene;
  scene.name = doc.value("name", source);
  const float scale = doc.value("unitScale", 1.0f);
  const std::string at = "scene '" + source + "'";

  const json& cam = require(doc, "camera", at);
  scene.camera.position = readVec3(require(cam, "position", at + " camera"), at + " camera.position") * scale;
  scene.camera.forward = glm::normalize(readVec3(require(cam, "forward", at + " camera"), at + " camera.forward"));
  scene.camera.up = glm::normalize(readVec3(require(cam, "up", at + " camera"), at + " camera.up"));
  scene.camera.verticalFovDegrees = require(cam, "verticalFovDegrees", at + " camera").get<float>();

  std::map<std::string, uint32_t> materialIndex;
  const json& materials = require(doc, "materials", at);
  if (!materials.is_object()) throw Error(at + ": \"materials\" must be an object");
  for (const auto& [name, m] : materials.items()) {
    Material material;
    material.name = name;
    const std::string where = at + " material '" + name + "'";
    if (m.contains("albedo")) material.albedo = readVec3(m.at("albedo"), where + " albedo");
    if (m.contains("emission")) material.emission = readVec3(m.at("emission"), where + " emission");
    for (int i = 0; i < 3; ++i)
      if (material.albedo[i] < 0.0f || material.albedo[i] > 1.0f || material.emission[i] < 0.0f)
        throw Error(where + ": albedo must lie in [0, 1] and emission be non-negative");
    materialIndex[name] = uint32_t(scene.materials.size());
    scene.materials.push_back(material);
  }

  const json& meshes = require(doc, "meshes", at);
  if (!meshes.is_array()) throw Error(at + ": \"meshes\" must be an array");
  for (const auto& m : meshes) {
    Mesh mesh;
    mesh.name = m.value("name", fmt::format("mesh{}", scene.meshes.size()));
    const std::string where = at + " mesh '" + mesh.name + "'";
    const std::string materialName = require(m, "material", where).get<std::string>();
    auto it = materialIndex.find(materialName);
    if (it == materialIndex.end())
      throw Error(fmt::format("{}: unknown material '{}'", where, materialName));
    mesh.material = it->second;
    const json& quads = require(m, "quads", where);
    if (!quads.is_array() || quads.empty()) throw Error(where + ": \"quads\" must be a non-empty array");
    for (const auto& quad : quads) {
      if (!quad.is_array() || quad.size() != 4)
        throw Error(where + ": each quad needs exactly 4 vertices");
      const uint32_t base = uint32_t(mesh.positions.size());
      for (int i = 0; i < 4; ++i)
        mesh.positions.push_back(readVec3(quad[i], where + " quad vertex") * scale);
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }
    scene.instances.push_back({uint32_t(scene.meshes.size()), glm::mat4(1.0f)});
    scene.meshes.push_back(std::move(mesh));
  }
  validate(scene);
  return scene;
}

Scene loadScene(const std::string& nameOrPath) {
  if (auto builtIn = embedded::find(nameOrPath + ".json")) return parseScene(*builtIn, nameOrPath);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(nameOrPath, ec)) {
    std::string names;
    for (const auto& n : builtInSceneNames()) names += (names.empty() ? "" : ", ") + n;
    throw Error(fmt::format("scene '{}': no built-in scene of that name and no such file "
                            "(built-in: {})", nameOrPath, names));
  }
  std::ifstream file(nameOrPath, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  if (!file.good() && !file.eof())
    throw Error(fmt::format("scene '{}': cannot read the file", nameOrPath));
  return parseScene(text.str(), nameOrPath);
}

std::vector<std::string> builtInSceneNames() {
  std::vector<std::string> names;
  for (auto n : embedded::names()) {
    std::string s(n);
    if (s.size() > 5 && s.ends_with(".json")) names.push_back(s.substr(0, s.size() - 5));
  }
  return names;
}

}  // namespace penumbra::scene
