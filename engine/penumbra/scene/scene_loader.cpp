#include "penumbra/scene/scene_loader.h"

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

#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/implicit_json.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/json_reading.h"
#include "penumbra/scene/material_row.h"
#include "penumbra/scene/scene_generators.h"
#include "penumbra/util/embedded_files.h"
#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

// `scale`: the scene's unitScale (attenuationDistance is a length).
Material parseMaterial(const json& m, const std::string& name, const std::string& where,
                       float scale) {
  if (!m.is_object())
    throw Error(fmt::format("{}: must be an object (got {})", where, jsonTypeName(m)));
  const std::string model = readString(m, "model", "disney", where);
  Material material;
  if (model == "lambert") {
    material = Material::lambert(name, glm::vec3(0.8f));
  } else if (model == "phong") {
    material.model = MaterialModel::Phong;
  } else if (model == "unlit") {
    material.model = MaterialModel::Unlit;
  } else if (model != "disney") {
    throw Error(
        fmt::format("{}: unknown model '{}' (disney, lambert, phong, unlit)", where, model));
  }
  material.name = name;
  if (m.contains("baseColor"))
    material.baseColor = readVec3(m.at("baseColor"), where + " baseColor");
  if (m.contains("albedo")) material.baseColor = readVec3(m.at("albedo"), where + " albedo");
  if (m.contains("emission")) material.emission = readVec3(m.at("emission"), where + " emission");
  material.metallic = readFloat(m, "metallic", material.metallic, where);
  material.roughness = readFloat(m, "roughness", material.roughness, where);
  material.anisotropic = readFloat(m, "anisotropic", material.anisotropic, where);
  material.anisotropyStrength =
      readFloat(m, "anisotropyStrength", material.anisotropyStrength, where);
  material.anisotropyRotation =
      readFloat(m, "anisotropyRotation", material.anisotropyRotation, where);
  material.specular = readFloat(m, "specular", material.specular, where);
  material.specularTint = readFloat(m, "specularTint", material.specularTint, where);
  material.specularF90 = readFloat(m, "specularF90", material.specularF90, where);
  if (m.contains("specularColor"))
    material.specularColor = readVec3(m.at("specularColor"), where + " specularColor");
  material.sheen = readFloat(m, "sheen", material.sheen, where);
  material.sheenTint = readFloat(m, "sheenTint", material.sheenTint, where);
  material.sheenRoughness = readFloat(m, "sheenRoughness", material.sheenRoughness, where);
  if (m.contains("sheenColor"))
    material.sheenColor = readVec3(m.at("sheenColor"), where + " sheenColor");
  material.clearcoat = readFloat(m, "clearcoat", material.clearcoat, where);
  material.clearcoatGloss = readFloat(m, "clearcoatGloss", material.clearcoatGloss, where);
  material.specTrans = readFloat(m, "specTrans", material.specTrans, where);
  material.diffuseTransmission =
      readFloat(m, "diffuseTransmission", material.diffuseTransmission, where);
  if (m.contains("diffuseTransmissionColor"))
    material.diffuseTransmissionColor =
        readVec3(m.at("diffuseTransmissionColor"), where + " diffuseTransmissionColor");
  material.ior = readFloat(m, "ior", material.ior, where);
  material.iridescence = readFloat(m, "iridescence", material.iridescence, where);
  material.iridescenceIor = readFloat(m, "iridescenceIor", material.iridescenceIor, where);
  // Without a thickness texture only the maximum is used: one number.
  material.iridescenceThicknessMaximum =
      readFloat(m, "iridescenceThickness", material.iridescenceThicknessMaximum, where);
  material.dispersion = readFloat(m, "dispersion", material.dispersion, where);
  material.subsurface = readFloat(m, "subsurface", material.subsurface, where);
  material.thin = readBool(m, "thin", false, where);
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
                                 const std::string& at, const InputLimits& limits) {
  const std::string where = at + " materialTest";
  if (!row.is_object()) throw Error(where + ": must be an object");
  MaterialRowDesc desc;
  const std::string material = requireString(row, "material", where);
  auto it = materialIndex.find(material);
  if (it == materialIndex.end())
    throw Error(fmt::format("{}: unknown material '{}'", where, material));
  desc.base = scene.materials[it->second];
  desc.vary = readString(row, "vary", desc.vary, where);
  desc.count = uint32_t(readInteger(row, "count", desc.count, 1, 64, where));
  desc.radius = readFloat(row, "radius", desc.radius / scale, where) * scale;
  desc.first = readVec3(require(row, "first", where), where + " first") * scale;
  desc.last = readVec3(require(row, "last", where), where + " last") * scale;
  desc.subdivisions =
      uint32_t(readInteger(row, "subdivisions", desc.subdivisions, 0, UINT32_MAX, where));
  // Each sphere is its own mesh of 20 * 4^subdivisions triangles.
  requireAtMost(desc.subdivisions, limits.maxSphereSubdivisions, "maxSphereSubdivisions",
                where + " \"subdivisions\"");
  requireAtMost(saturatingAdd(storedTriangles(scene),
                              saturatingMul(desc.count, icosphereTriangles(desc.subdivisions))),
                limits.maxTriangles, "maxTriangles",
                where + ": the scene's triangle count with the row");
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
      if (!std::isfinite(glm::value_ptr(t)[i]))
        throw Error(where + ": \"transform\" holds a non-finite number");
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
  // An orthographic view grows with the scene it looks at.
  r.orthographicHeight *=
      float(glm::length(glm::dvec3(t * glm::dvec4(glm::normalize(glm::dvec3(c.up)), 0.0))));
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
    for (uint32_t* ref : m.textureSlots())
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
// The moment of a "gltf" entry's animations: the caller's choice where
// given, else the entry's "animation" and "time".
AnimationChoice entryAnimation(const json& g, const std::string& where,
                               const AnimationChoice& given) {
  if (!given.empty()) return given;
  AnimationChoice choice;
  if (g.contains("animation")) {
    const json& a = g.at("animation");
    if (a.is_string())
      choice.animation = a.get<std::string>();
    else if (a.is_number_unsigned())
      choice.animation = std::to_string(a.get<uint64_t>());
    else
      throw Error(where + ": \"animation\" must be a name or an index >= 0");
  }
  if (g.contains("time")) {
    if (!g.at("time").is_number()) throw Error(where + ": \"time\" must be a number (seconds)");
    choice.seconds = g.at("time").get<double>();
  }
  return choice;
}

std::optional<Camera> loadGltfParts(Scene& scene, const json& list, const std::string& at,
                                    const std::string& baseDirectory, const FileAccess& access,
                                    const InputLimits& limits, const AnimationChoice& animation) {
  if (!list.is_array()) throw Error(at + ": \"gltf\" must be an array");
  std::optional<Camera> view;
  for (size_t i = 0; i < list.size(); ++i) {
    const json& g = list[i];
    const std::string where = fmt::format("{} gltf[{}]", at, i);
    std::filesystem::path path(requireString(g, "file", where));
    if (path.is_relative() && !baseDirectory.empty())
      path = std::filesystem::path(baseDirectory) / path;
    const glm::dmat4 t = readTransform(g, where);
    Scene part = loadGltf(path.string(), access, limits, entryAnimation(g, where, animation));
    if (g.contains("camera")) selectCamera(part, requireString(g, "camera", where));
    // Each file is bounded on its own; together they must fit too.
    requireAtMost(storedTriangles(scene) + storedTriangles(part), limits.maxTriangles,
                  "maxTriangles", where + ": the scene's triangle count with the file");
    requireAtMost(scene.instances.size() + part.instances.size(), limits.maxInstances,
                  "maxInstances", where + ": the scene's instance count with the file");
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
    const std::filesystem::path file = requireString(e, "file", where);
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
  env.rotationDegrees = readFloat(e, "rotation", 0.0f, where);
  env.intensity = readFloat(e, "intensity", 1.0f, where);
  env.visibleBackground = readBool(e, "background", true, where);
  try {
    validateEnvironment(env);
  } catch (const Error& error) {
    throw Error(where + ": " + error.what());
  }
  return env;
}

// The scene file's camera (positions and lengths in file units times `scale`).
Camera parseCamera(const json& cam, const std::string& at, float scale) {
  Camera camera;
  const std::string where = at + " camera";
  if (!cam.is_object())
    throw Error(fmt::format("{}: must be an object (got {})", where, jsonTypeName(cam)));
  camera.position = readDVec3(require(cam, "position", where), where + ".position") * double(scale);
  camera.forward = readDirection(require(cam, "forward", where), where + ".forward");
  camera.up = readDirection(require(cam, "up", where), where + ".up");
  // A perspective camera's field of view or an orthographic one's height.
  if (cam.contains("verticalFovDegrees") == cam.contains("orthographicHeight"))
    throw Error(where +
                ": give \"verticalFovDegrees\" (perspective) or \"orthographicHeight\", "
                "exactly one");
  if (cam.contains("orthographicHeight")) {
    camera.orthographicHeight = requireFloat(cam, "orthographicHeight", where) * scale;
    if (!(camera.orthographicHeight > 0.0f) || !std::isfinite(camera.orthographicHeight))
      throw Error(fmt::format("{}: \"orthographicHeight\" {} must be finite and > 0", where,
                              camera.orthographicHeight / scale));
  } else {
    camera.verticalFovDegrees = requireFloat(cam, "verticalFovDegrees", where);
    if (!(camera.verticalFovDegrees > 0.0f && camera.verticalFovDegrees < 180.0f))
      throw Error(fmt::format("{}: \"verticalFovDegrees\" {} must lie in (0, 180)", where,
                              camera.verticalFovDegrees));
  }
  camera.aspectRatio = readFloat(cam, "aspectRatio", 0.0f, where);
  camera.apertureRadius = readFloat(cam, "apertureRadius", 0.0f, where) * scale;
  camera.focusDistance = readFloat(cam, "focusDistance", 1.0f / scale, where) * scale;
  // An f-number instead of a radius: the radius is focal length / (2 N),
  // with the focal length of a 35 mm frame (24 mm tall) at this field of view.
  if (cam.contains("fNumber")) {
    if (cam.contains("apertureRadius"))
      throw Error(at + " camera: give \"apertureRadius\" or \"fNumber\", not both");
    if (camera.orthographic())
      throw Error(at +
                  " camera: an orthographic camera has no focal length for \"fNumber\"; "
                  "give \"apertureRadius\"");
    const float fNumber = requireFloat(cam, "fNumber", where);
    if (!(fNumber > 0.0f) || !std::isfinite(fNumber))
      throw Error(fmt::format("{} camera: fNumber {} must be finite and > 0", at, fNumber));
    camera.apertureRadius = apertureRadiusForFNumber(fNumber, camera.verticalFovDegrees);
  }
  camera.apertureBlades = uint32_t(readInteger(cam, "apertureBlades", 0, 0, 32, where));
  try {
    validateCamera(camera);
  } catch (const Error& e) {
    throw Error(at + " " + e.what());
  }
  return camera;
}

// One entry of "lights": a point, spot or directional light.
PointLight parseLight(const json& l, const std::string& where, float scale) {
  if (!l.is_object())
    throw Error(fmt::format("{}: must be an object (got {})", where, jsonTypeName(l)));
  const std::string type = requireString(l, "type", where);
  PointLight light;
  if (type == "point") {
    light.type = LightType::Point;
  } else if (type == "spot") {
    light.type = LightType::Spot;
  } else if (type == "directional") {
    light.type = LightType::Directional;
  } else {
    throw Error(fmt::format("{}: unknown light type '{}' (point, spot, directional)", where, type));
  }
  // A directional light's "intensity" is its irradiance.
  light.intensity = readVec3(require(l, "intensity", where), where + " intensity");
  if (light.intensity.r < 0 || light.intensity.g < 0 || light.intensity.b < 0)
    throw Error(where + " intensity: must be >= 0");
  if (light.type != LightType::Directional)
    light.position = readDVec3(require(l, "position", where), where + " position") * double(scale);
  if (light.type != LightType::Point) {
    const glm::vec3 direction = readVec3(require(l, "direction", where), where + " direction");
    if (!(glm::length(direction) > 0.0f)) throw Error(where + " direction: must not be zero");
    light.direction = glm::normalize(direction);
  }
  if (light.type == LightType::Spot) {
    light.outerConeDegrees = requireFloat(l, "outerConeDegrees", where);
    light.innerConeDegrees = readFloat(l, "innerConeDegrees", light.outerConeDegrees, where);
    if (!(light.outerConeDegrees > 0.0f && light.outerConeDegrees < 180.0f))
      throw Error(where + " outerConeDegrees: must be in (0, 180)");
    if (!(light.innerConeDegrees >= 0.0f && light.innerConeDegrees <= light.outerConeDegrees))
      throw Error(fmt::format("{}: innerConeDegrees {} must be in 0..outerConeDegrees ({})", where,
                              light.innerConeDegrees, light.outerConeDegrees));
  }
  if (light.type == LightType::Directional && l.contains("angularRadiusDegrees")) {
    light.angularRadiusDegrees = requireFloat(l, "angularRadiusDegrees", where);
    if (!(light.angularRadiusDegrees >= 0.0f && light.angularRadiusDegrees < 90.0f))
      throw Error(where + " angularRadiusDegrees: must be in [0, 90)");
  }
  if (light.type != LightType::Directional && l.contains("range")) {
    light.range = requireFloat(l, "range", where) * scale;
    if (!(light.range > 0.0f) || !std::isfinite(light.range))
      throw Error(where + " range: must be finite and > 0");
  }
  return light;
}

// One entry of "meshes": quads of four vertices each (two triangles), its
// material by name. `triangles` counts the scene's, bounded by the limits.
Mesh parseQuadMesh(const json& m, const std::string& numbered, const std::string& at,
                   size_t meshNumber, const std::map<std::string, uint32_t>& materialIndex,
                   float scale, const InputLimits& limits, uint64_t& triangles) {
  if (!m.is_object())
    throw Error(fmt::format("{}: must be an object (got {})", numbered, jsonTypeName(m)));
  Mesh mesh;
  mesh.name = readString(m, "name", fmt::format("mesh{}", meshNumber), numbered);
  const std::string where = at + " mesh '" + mesh.name + "'";
  const std::string materialName = requireString(m, "material", where);
  auto it = materialIndex.find(materialName);
  if (it == materialIndex.end())
    throw Error(fmt::format("{}: unknown material '{}'", where, materialName));
  mesh.material = it->second;
  const json& quads = require(m, "quads", where);
  if (!quads.is_array() || quads.empty())
    throw Error(where + ": \"quads\" must be a non-empty array");
  triangles += 2 * uint64_t(quads.size());
  requireAtMost(triangles, limits.maxTriangles, "maxTriangles",
                where + ": the scene's triangle count");
  for (size_t q = 0; q < quads.size(); ++q) {
    const json& quad = quads[q];
    if (!quad.is_array() || quad.size() != 4)
      throw Error(fmt::format("{}: quad {} needs exactly 4 vertices", where, q));
    const uint32_t base = uint32_t(mesh.positions.size());
    for (size_t i = 0; i < 4; ++i)
      mesh.positions.push_back(readVec3(quad[i], fmt::format("{} quad {} vertex {}", where, q, i)) *
                               scale);
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  }
  return mesh;
}

}  // namespace

Scene parseScene(std::string_view text, const std::string& source, const std::string& baseDirectory,
                 const FileAccess& access, const InputLimits& limits,
                 const AnimationChoice& animation) {
  const std::string at = "scene '" + source + "'";
  // Bounded before parsing: the tree takes many times the text, and
  // copying or destroying it recurses per level.
  requireAtMost(text.size(), limits.maxJsonBytes, "maxJsonBytes", at + " JSON text size in bytes");
  requireJsonDepth(text, limits, at);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(fmt::format("scene '{}': invalid JSON at byte {}: {}", source, e.byte, e.what()));
  } catch (const json::exception& e) {
    // A number too large for a double (1e400) is an out_of_range error.
    throw Error(fmt::format("scene '{}': invalid JSON: {}", source, e.what()));
  }
  if (!doc.is_object() || !doc.contains("format") || doc.at("format") != "penumbra-scene")
    throw Error(fmt::format(
        "scene '{}': not a penumbra scene (\"format\" must be \"penumbra-scene\")", source));
  if (!doc.contains("version") || doc.at("version") != 1)
    throw Error(
        fmt::format("scene '{}': unsupported version (this build reads version 1)", source));

  Scene scene;
  scene.name = readString(doc, "name", source, at);
  const float scale = readFloat(doc, "unitScale", 1.0f, at);
  if (!(scale > 0.0f)) throw Error(fmt::format("{}: \"unitScale\" {} must be > 0", at, scale));

  const bool hasGltf = doc.contains("gltf");
  if (!hasGltf && !animation.empty())
    throw Error(at + ": has no glTF files, so no animations to draw at a time");
  if (!hasGltf || doc.contains("camera")) {
    scene.camera = parseCamera(require(doc, "camera", at), at, scale);
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
    for (size_t i = 0; i < lights.size(); ++i) {
      scene.pointLights.push_back(parseLight(lights[i], fmt::format("{} light[{}]", at, i), scale));
    }
  }
  if (doc.contains("ambient")) scene.ambient = readVec3(doc.at("ambient"), at + " ambient");
  if (doc.contains("environment"))
    scene.environment = parseEnvironment(doc.at("environment"), at + " environment", baseDirectory);

  // By reference: a copy of the array would recurse through all of it.
  static const json kEmptyArray = json::array();
  const json& meshes = doc.contains("meshes") ? doc.at("meshes") : kEmptyArray;
  if (!meshes.is_array()) throw Error(at + ": \"meshes\" must be an array");
  uint64_t triangles = storedTriangles(scene);
  for (size_t n = 0; n < meshes.size(); ++n) {
    Mesh mesh = parseQuadMesh(meshes[n], fmt::format("{} meshes[{}]", at, n), at,
                              scene.meshes.size(), materialIndex, scale, limits, triangles);
    scene.instances.push_back({uint32_t(scene.meshes.size()), glm::dmat4(1.0)});
    scene.meshes.push_back(std::move(mesh));
  }
  if (doc.contains("implicits")) {
    const json& implicits = doc.at("implicits");
    if (implicits.is_array())
      requireAtMost(implicits.size(), limits.maxImplicitObjects, "maxImplicitObjects",
                    at + " implicit object count");
    scene.implicits = parseImplicits(implicits, materialIndex, scale, at);
  }
  if (doc.contains("generated"))
    addGenerated(scene, doc.at("generated"), materialIndex, scale, at, limits);
  if (doc.contains("materialTest"))
    addMaterialRow(
        scene, parseMaterialRow(doc.at("materialTest"), scene, materialIndex, scale, at, limits));
  if (hasGltf) {
    auto view = loadGltfParts(scene, doc.at("gltf"), at, baseDirectory, access, limits, animation);
    if (!doc.contains("camera") && view) scene.camera = *view;
  }
  validate(scene);
  return scene;
}

Scene loadScene(const std::string& nameOrPath, const FileAccess& access, const InputLimits& limits,
                const AnimationChoice& animation) {
  if (auto builtIn = embedded::find(nameOrPath + ".json"))
    return parseScene(*builtIn, nameOrPath, "", access, limits, animation);
  std::error_code ec;
  if (std::filesystem::is_directory(nameOrPath, ec))
    throw Error(fmt::format(
        "scene '{}': is a folder; give a scene file (.json), a glTF file (.gltf, .glb) or a "
        "built-in scene name",
        nameOrPath));
  if (isGltfPath(nameOrPath)) return loadGltf(nameOrPath, access, limits, animation);
  if (!std::filesystem::is_regular_file(nameOrPath, ec)) {
    std::string names;
    for (const auto& n : builtInSceneNames()) names += (names.empty() ? "" : ", ") + n;
    throw Error(
        fmt::format("scene '{}': no built-in scene of that name and no such file "
                    "(built-in: {})",
                    nameOrPath, names));
  }
  // Refused before reading: maxJsonBytes bounds the text as well as the tree.
  const uintmax_t size = std::filesystem::file_size(nameOrPath, ec);
  if (!ec)
    requireAtMost(size, limits.maxJsonBytes, "maxJsonBytes",
                  fmt::format("scene '{}' JSON text size in bytes", nameOrPath));
  std::ifstream file(nameOrPath, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  if (!file.good() && !file.eof())
    throw Error(fmt::format("scene '{}': cannot read the file", nameOrPath));
  return parseScene(text.str(), nameOrPath,
                    std::filesystem::path(nameOrPath).parent_path().string(), access, limits,
                    animation);
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
