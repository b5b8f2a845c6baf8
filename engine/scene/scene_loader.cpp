#include "scene/scene_loader.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "scene/gltf_loader.h"
#include "scene/implicit_json.h"
#include "scene/json_reading.h"
#include "scene/material_row.h"
#include "scene/scene_generators.h"
#include "util/embedded_files.h"
#include "util/error.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

// `scale`: the scene's unitScale (attenuationDistance is a length).
Material parseMaterial(const json& m, const std::string& name, const std::string& where,
                       float scale) {
  if (!m.is_object()) throw Error(where + ": must be an object");
  const std::string model = m.value("model", "disney");
  Material material;
  if (model == "lambert") {
    material = Material::lambert(name, glm::vec3(0.8f));
  } else if (model == "phong") {
    material.model = MaterialModel::Phong;
  } else if (model != "disney") {
    throw Error(fmt::format("{}: unknown model '{}' (disney, lambert, phong)", where, model));
  }
  material.name = name;
  if (m.contains("baseColor"))
    material.baseColor = readVec3(m.at("baseColor"), where + " baseColor");
  if (m.contains("albedo")) material.baseColor = readVec3(m.at("albedo"), where + " albedo");
  if (m.contains("emission")) material.emission = readVec3(m.at("emission"), where + " emission");
  material.metallic = readFloat(m, "metallic", material.metallic, where);
  material.roughness = readFloat(m, "roughness", material.roughness, where);
  material.anisotropic = readFloat(m, "anisotropic", material.anisotropic, where);
  material.specular = readFloat(m, "specular", material.specular, where);
  material.specularTint = readFloat(m, "specularTint", material.specularTint, where);
  material.sheen = readFloat(m, "sheen", material.sheen, where);
  material.sheenTint = readFloat(m, "sheenTint", material.sheenTint, where);
  material.clearcoat = readFloat(m, "clearcoat", material.clearcoat, where);
  material.clearcoatGloss = readFloat(m, "clearcoatGloss", material.clearcoatGloss, where);
  material.specTrans = readFloat(m, "specTrans", material.specTrans, where);
  material.ior = readFloat(m, "ior", material.ior, where);
  material.subsurface = readFloat(m, "subsurface", material.subsurface, where);
  material.thin = m.value("thin", false);
  if (m.contains("attenuationColor"))
    material.attenuationColor = readVec3(m.at("attenuationColor"), where + " attenuationColor");
  material.attenuationDistance =
      readFloat(m, "attenuationDistance", material.attenuationDistance / scale, where) * scale;
  material.ks = readFloat(m, "ks", material.ks, where);
  material.exponent = readFloat(m, "exponent", material.exponent, where);
  material.reflectivity = readFloat(m, "reflectivity", material.reflectivity, where);
  material.transparency = readFloat(m, "transparency", material.transparency, where);
  return material;
}

MaterialRowDesc parseMaterialRow(const json& row, const Scene& scene,
                                 const std::map<std::string, uint32_t>& materialIndex, float scale,
                                 const std::string& at) {
  const std::string where = at + " materialTest";
  if (!row.is_object()) throw Error(where + ": must be an object");
  MaterialRowDesc desc;
  const std::string material = require(row, "material", where).get<std::string>();
  auto it = materialIndex.find(material);
  if (it == materialIndex.end())
    throw Error(fmt::format("{}: unknown material '{}'", where, material));
  desc.base = scene.materials[it->second];
  desc.vary = row.value("vary", desc.vary);
  desc.count = row.value("count", desc.count);
  desc.radius = readFloat(row, "radius", desc.radius / scale, where) * scale;
  desc.first = readVec3(require(row, "first", where), where + " first") * scale;
  desc.last = readVec3(require(row, "last", where), where + " last") * scale;
  desc.subdivisions = row.value("subdivisions", desc.subdivisions);
  return desc;
}

glm::dmat4 readTransform(const json& g, const std::string& where) {
  if (g.contains("transform")) {
    const json& m = g.at("transform");
    if (!m.is_array() || m.size() != 16)
      throw Error(where + ": \"transform\" must be an array of 16 numbers (column-major)");
    glm::dmat4 t;
    for (int i = 0; i < 16; ++i) {
      if (!m[size_t(i)].is_number()) throw Error(where + ": \"transform\" holds a non-number");
      glm::value_ptr(t)[i] = m[size_t(i)].get<double>();
    }
    return t;
  }
  glm::dmat4 t(1.0);
  if (g.contains("translation"))
    t = glm::translate(t, readDVec3(g.at("translation"), where + " translation"));
  if (g.contains("rotation")) {
    const json& r = g.at("rotation");
    if (!r.is_array() || r.size() != 4 || !r[0].is_number() || !r[1].is_number() ||
        !r[2].is_number() || !r[3].is_number())
      throw Error(where + ": \"rotation\" must be a quaternion [x, y, z, w]");
    const glm::dquat q(r[3].get<double>(), r[0].get<double>(), r[1].get<double>(),
                       r[2].get<double>());
    if (!(glm::length(q) > 0.0)) throw Error(where + ": \"rotation\" is a zero quaternion");
    t = t * glm::mat4_cast(glm::normalize(q));
  }
  if (g.contains("scale")) t = glm::scale(t, readDVec3(g.at("scale"), where + " scale"));
  return t;
}

Camera transformCamera(const Camera& c, const glm::dmat4& t) {
  Camera r = c;
  r.position = glm::dvec3(t * glm::dvec4(c.position, 1.0));
  r.forward = glm::normalize(glm::vec3(t * glm::dvec4(glm::dvec3(c.forward), 0.0)));
  r.up = glm::normalize(glm::vec3(t * glm::dvec4(glm::dvec3(c.up), 0.0)));
  return r;
}

// Appends `part` to `scene`, its instances and cameras moved by `t`.
void merge(Scene& scene, const Scene& part, const glm::dmat4& t) {
  const uint32_t materialBase = uint32_t(scene.materials.size());
  const uint32_t meshBase = uint32_t(scene.meshes.size());
  const uint32_t textureBase = uint32_t(scene.textures.size());
  const uint32_t textureRefBase = uint32_t(scene.textureRefs.size());
  scene.textures.insert(scene.textures.end(), part.textures.begin(), part.textures.end());
  for (TextureRef ref : part.textureRefs) {
    ref.texture += textureBase;
    scene.textureRefs.push_back(ref);
  }
  for (Material m : part.materials) {
    for (uint32_t* ref : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
                          &m.emissiveTexture, &m.occlusionTexture})
      if (*ref != Material::kNoTexture) *ref += textureRefBase;
    scene.materials.push_back(std::move(m));
  }
  for (Mesh mesh : part.meshes) {
    mesh.material += materialBase;
    scene.meshes.push_back(std::move(mesh));
  }
  for (const auto& inst : part.instances)
    scene.instances.push_back({inst.mesh + meshBase, t * inst.transform});
  for (NamedCamera c : part.cameras) {
    c.camera = transformCamera(c.camera, t);
    scene.cameras.push_back(std::move(c));
  }
}

// The "gltf" list; returns the view the first file suggests.
std::optional<Camera> loadGltfParts(Scene& scene, const json& list, const std::string& at,
                                    const std::string& baseDirectory, const FileAccess& access) {
  if (!list.is_array()) throw Error(at + ": \"gltf\" must be an array");
  std::optional<Camera> view;
  for (size_t i = 0; i < list.size(); ++i) {
    const json& g = list[i];
    const std::string where = fmt::format("{} gltf[{}]", at, i);
    const json& file = require(g, "file", where);
    if (!file.is_string()) throw Error(where + ": \"file\" must be a string");
    std::filesystem::path path(file.get<std::string>());
    if (path.is_relative() && !baseDirectory.empty())
      path = std::filesystem::path(baseDirectory) / path;
    const glm::dmat4 t = readTransform(g, where);
    Scene part = loadGltf(path.string(), access);
    if (g.contains("camera")) {
      if (!g.at("camera").is_string()) throw Error(where + ": \"camera\" must be a string");
      selectCamera(part, g.at("camera").get<std::string>());
    }
    if (!view) view = transformCamera(part.camera, t);
    merge(scene, part, t);
  }
  return view;
}

// "environment": { "file": "sky.exr" (relative to the scene file) or
// "color": [r, g, b], "rotation": degrees, "intensity": x, "background": bool }
Environment parseEnvironment(const json& e, const std::string& where,
                             const std::string& baseDirectory) {
  if (!e.is_object()) throw Error(where + ": must be an object");
  Environment env;
  if (e.contains("file") == e.contains("color"))
    throw Error(where + ": give exactly one of \"file\" (an .exr or .hdr map) and \"color\"");
  if (e.contains("file")) {
    const std::filesystem::path file = e.at("file").get<std::string>();
    env = loadEnvironmentMap((file.is_absolute() || baseDirectory.empty()
                                  ? file
                                  : std::filesystem::path(baseDirectory) / file)
                                 .string());
  } else {
    const glm::vec3 color = readVec3(e.at("color"), where + " color");
    if (!(color.r >= 0 && color.g >= 0 && color.b >= 0))
      throw Error(where + " color: must be >= 0");
    env = constantEnvironment(color);
  }
  env.rotationDegrees = e.value("rotation", 0.0f);
  env.intensity = e.value("intensity", 1.0f);
  env.visibleBackground = e.value("background", true);
  try {
    validateEnvironment(env);
  } catch (const Error& error) {
    throw Error(where + ": " + error.what());
  }
  return env;
}

}  // namespace

Scene parseScene(std::string_view text, const std::string& source,
                 const std::string& baseDirectory, const FileAccess& access) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(fmt::format("scene '{}': invalid JSON at byte {}: {}", source, e.byte, e.what()));
  }
  if (doc.value("format", "") != "penumbra-scene")
    throw Error(fmt::format(
        "scene '{}': not a penumbra scene (\"format\" must be \"penumbra-scene\")", source));
  if (doc.value("version", 0) != 1)
    throw Error(
        fmt::format("scene '{}': unsupported version (this build reads version 1)", source));

  Scene scene;
  scene.name = doc.value("name", source);
  const float scale = doc.value("unitScale", 1.0f);
  const std::string at = "scene '" + source + "'";

  const bool hasGltf = doc.contains("gltf");
  if (!hasGltf || doc.contains("camera")) {
    const json& cam = require(doc, "camera", at);
    scene.camera.position =
        readDVec3(require(cam, "position", at + " camera"), at + " camera.position") *
        double(scale);
    scene.camera.forward =
        glm::normalize(readVec3(require(cam, "forward", at + " camera"), at + " camera.forward"));
    scene.camera.up =
        glm::normalize(readVec3(require(cam, "up", at + " camera"), at + " camera.up"));
    scene.camera.verticalFovDegrees =
        require(cam, "verticalFovDegrees", at + " camera").get<float>();
    scene.camera.aspectRatio = cam.value("aspectRatio", 0.0f);
    scene.camera.apertureRadius = cam.value("apertureRadius", 0.0f) * scale;
    scene.camera.focusDistance = cam.value("focusDistance", 1.0f / scale) * scale;
    // An f-number instead of a radius: the radius is focal length / (2 N),
    // with the focal length of a 35 mm frame (24 mm tall) at this field of view.
    if (cam.contains("fNumber")) {
      if (cam.contains("apertureRadius"))
        throw Error(at + " camera: give \"apertureRadius\" or \"fNumber\", not both");
      const float fNumber = cam.at("fNumber").get<float>();
      if (!(fNumber > 0.0f) || !std::isfinite(fNumber))
        throw Error(fmt::format("{} camera: fNumber {} must be finite and > 0", at, fNumber));
      scene.camera.apertureRadius =
          apertureRadiusForFNumber(fNumber, scene.camera.verticalFovDegrees);
    }
    const int blades = cam.value("apertureBlades", 0);
    if (blades < 0)
      throw Error(fmt::format("{} camera: apertureBlades {} is negative", at, blades));
    scene.camera.apertureBlades = uint32_t(blades);
    try {
      validateCamera(scene.camera);
    } catch (const Error& e) {
      throw Error(at + " " + e.what());
    }
  }

  std::map<std::string, uint32_t> materialIndex;
  static const json kEmptyObject = json::object();
  const json& materials =
      hasGltf && !doc.contains("materials") ? kEmptyObject : require(doc, "materials", at);
  if (!materials.is_object()) throw Error(at + ": \"materials\" must be an object");
  for (const auto& [name, m] : materials.items()) {
    scene.materials.push_back(parseMaterial(m, name, at + " material '" + name + "'", scale));
    materialIndex[name] = uint32_t(scene.materials.size() - 1);
  }

  if (doc.contains("lights")) {
    const json& lights = doc.at("lights");
    if (!lights.is_array()) throw Error(at + ": \"lights\" must be an array");
    for (const auto& l : lights) {
      const std::string where = at + " light";
      const std::string type = require(l, "type", where).get<std::string>();
      PointLight light;
      if (type == "point") {
        light.type = LightType::Point;
      } else if (type == "spot") {
        light.type = LightType::Spot;
      } else if (type == "directional") {
        light.type = LightType::Directional;
      } else {
        throw Error(
            fmt::format("{}: unknown light type '{}' (point, spot, directional)", where, type));
      }
      // A directional light's "intensity" is its irradiance.
      light.intensity = readVec3(require(l, "intensity", where), where + " intensity");
      if (light.intensity.r < 0 || light.intensity.g < 0 || light.intensity.b < 0)
        throw Error(where + " intensity: must be >= 0");
      if (light.type != LightType::Directional)
        light.position =
            readDVec3(require(l, "position", where), where + " position") * double(scale);
      if (light.type != LightType::Point) {
        const glm::vec3 direction = readVec3(require(l, "direction", where), where + " direction");
        if (!(glm::length(direction) > 0.0f)) throw Error(where + " direction: must not be zero");
        light.direction = glm::normalize(direction);
      }
      if (light.type == LightType::Spot) {
        light.outerConeDegrees = require(l, "outerConeDegrees", where).get<float>();
        light.innerConeDegrees = l.value("innerConeDegrees", light.outerConeDegrees);
        if (!(light.outerConeDegrees > 0.0f && light.outerConeDegrees < 180.0f))
          throw Error(where + " outerConeDegrees: must be in (0, 180)");
        if (!(light.innerConeDegrees >= 0.0f && light.innerConeDegrees <= light.outerConeDegrees))
          throw Error(fmt::format("{}: innerConeDegrees {} must be in 0..outerConeDegrees ({})",
                                  where, light.innerConeDegrees, light.outerConeDegrees));
      }
      if (light.type == LightType::Directional && l.contains("angularRadiusDegrees")) {
        light.angularRadiusDegrees = l.at("angularRadiusDegrees").get<float>();
        if (!(light.angularRadiusDegrees >= 0.0f && light.angularRadiusDegrees < 90.0f))
          throw Error(where + " angularRadiusDegrees: must be in [0, 90)");
      }
      if (light.type != LightType::Directional && l.contains("range")) {
        light.range = l.at("range").get<float>() * scale;
        if (!(light.range > 0.0f)) throw Error(where + " range: must be > 0");
      }
      scene.pointLights.push_back(light);
    }
  }
  if (doc.contains("ambient")) scene.ambient = readVec3(doc.at("ambient"), at + " ambient");
  if (doc.contains("environment"))
    scene.environment = parseEnvironment(doc.at("environment"), at + " environment", baseDirectory);

  const json meshes = doc.value("meshes", json::array());
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
    if (!quads.is_array() || quads.empty())
      throw Error(where + ": \"quads\" must be a non-empty array");
    for (const auto& quad : quads) {
      if (!quad.is_array() || quad.size() != 4)
        throw Error(where + ": each quad needs exactly 4 vertices");
      const uint32_t base = uint32_t(mesh.positions.size());
      for (int i = 0; i < 4; ++i)
        mesh.positions.push_back(readVec3(quad[i], where + " quad vertex") * scale);
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }
    scene.instances.push_back({uint32_t(scene.meshes.size()), glm::dmat4(1.0)});
    scene.meshes.push_back(std::move(mesh));
  }
  if (doc.contains("implicits"))
    scene.implicits = parseImplicits(doc.at("implicits"), materialIndex, scale, at);
  if (doc.contains("generated")) addGenerated(scene, doc.at("generated"), materialIndex, scale, at);
  if (doc.contains("materialTest"))
    addMaterialRow(scene,
                   parseMaterialRow(doc.at("materialTest"), scene, materialIndex, scale, at));
  if (hasGltf) {
    auto view = loadGltfParts(scene, doc.at("gltf"), at, baseDirectory, access);
    if (!doc.contains("camera") && view) scene.camera = *view;
  }
  validate(scene);
  return scene;
}

Scene loadScene(const std::string& nameOrPath, const FileAccess& access) {
  if (auto builtIn = embedded::find(nameOrPath + ".json")) return parseScene(*builtIn, nameOrPath);
  if (isGltfPath(nameOrPath)) return loadGltf(nameOrPath, access);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(nameOrPath, ec)) {
    std::string names;
    for (const auto& n : builtInSceneNames()) names += (names.empty() ? "" : ", ") + n;
    throw Error(
        fmt::format("scene '{}': no built-in scene of that name and no such file "
                    "(built-in: {})",
                    nameOrPath, names));
  }
  std::ifstream file(nameOrPath, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  if (!file.good() && !file.eof())
    throw Error(fmt::format("scene '{}': cannot read the file", nameOrPath));
  return parseScene(text.str(), nameOrPath,
                    std::filesystem::path(nameOrPath).parent_path().string(), access);
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
