#include "penumbra/batch/render_job.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "penumbra/render/image_size.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/json_reading.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"

namespace penumbra::render {
namespace {

using nlohmann::json;

json toJson(glm::vec3 v) {
  return json::array({v.x, v.y, v.z});
}

template <class Enum>
struct Named {
  Enum value;
  const char* name;
};
constexpr Named<scene::MaterialModel> kModels[] = {{scene::MaterialModel::Disney, "disney"},
                                                   {scene::MaterialModel::Lambert, "lambert"},
                                                   {scene::MaterialModel::Phong, "phong"},
                                                   {scene::MaterialModel::Unlit, "unlit"}};

// The Material menu's scalar parameters (the Disney ones, then Phong's).
struct FloatField {
  const char* name;
  float scene::Material::*field;
  // Made editable after records were first written: a record without it
  // keeps the scene's value, which is what the viewer showed when it was
  // written (MaterialOverride::sceneValues).
  bool optional = false;
};
constexpr FloatField kFloatFields[] = {
    {"metallic", &scene::Material::metallic},
    {"roughness", &scene::Material::roughness},
    {"anisotropic", &scene::Material::anisotropic},
    {"specular", &scene::Material::specular},
    {"specularTint", &scene::Material::specularTint},
    {"sheen", &scene::Material::sheen},
    {"sheenTint", &scene::Material::sheenTint},
    {"clearcoat", &scene::Material::clearcoat},
    {"clearcoatGloss", &scene::Material::clearcoatGloss},
    {"specTrans", &scene::Material::specTrans},
    {"ior", &scene::Material::ior},
    {"subsurface", &scene::Material::subsurface},
    {"ks", &scene::Material::ks},
    {"exponent", &scene::Material::exponent},
    {"reflectivity", &scene::Material::reflectivity},
    {"transparency", &scene::Material::transparency},
    {"anisotropyStrength", &scene::Material::anisotropyStrength, true},
    {"anisotropyRotation", &scene::Material::anisotropyRotation, true},
    {"sheenRoughness", &scene::Material::sheenRoughness, true},
    {"diffuseTransmission", &scene::Material::diffuseTransmission, true},
    {"iridescence", &scene::Material::iridescence, true},
    {"iridescenceIor", &scene::Material::iridescenceIor, true},
    {"iridescenceThickness", &scene::Material::iridescenceThicknessMaximum, true},
    {"dispersion", &scene::Material::dispersion, true}};

// The Material menu's colours besides baseColor (always written), all made
// editable after records were first written.
struct ColorField {
  const char* name;
  glm::vec3 scene::Material::*field;
};
constexpr ColorField kColorFields[] = {
    {"specularColor", &scene::Material::specularColor},
    {"sheenColor", &scene::Material::sheenColor},
    {"diffuseTransmissionColor", &scene::Material::diffuseTransmissionColor}};

bool fromScene(const MaterialOverride& o, const char* name) {
  return std::find(o.sceneValues.begin(), o.sceneValues.end(), name) != o.sceneValues.end();
}

bool sameEditableParameters(const scene::Material& a, const scene::Material& b) {
  if (a.model != b.model || a.baseColor != b.baseColor || a.thin != b.thin) return false;
  for (const auto& f : kFloatFields)
    if (a.*f.field != b.*f.field) return false;
  for (const auto& f : kColorFields)
    if (a.*f.field != b.*f.field) return false;
  return true;
}

void applyOverride(const MaterialOverride& o, scene::Material& to) {
  to.model = o.material.model;
  to.baseColor = o.material.baseColor;
  to.thin = o.material.thin;
  for (const auto& f : kFloatFields)
    if (!fromScene(o, f.name)) to.*f.field = o.material.*f.field;
  for (const auto& f : kColorFields)
    if (!fromScene(o, f.name)) to.*f.field = o.material.*f.field;
}

template <class Enum, size_t N>
const char* nameOf(const Named<Enum> (&table)[N], Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

template <class Enum, size_t N>
std::optional<Enum> parseName(const Named<Enum> (&table)[N], std::string_view name) {
  for (const auto& entry : table)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

// Every read checks type and range before converting: nlohmann's get<T>()
// turns 1e300 into an unsigned integer by undefined behaviour (a render with
// seed 0) and 1e39 into a float infinity. Messages are "<file>: "<field>" ...".
class Reader {
 public:
  Reader(const json& document, const std::string& source) : doc_(document), source_(source) {}

  void read(const char* key, std::string& out) const {
    if (!doc_.contains(key)) return;
    const json& value = doc_.at(key);
    if (!value.is_string())
      fail(key, fmt::format("must be a string (got {})", scene::jsonTypeName(value)));
    out = value.get<std::string>();
  }
  void read(const char* key, bool& out) const {
    if (!doc_.contains(key)) return;
    const json& value = doc_.at(key);
    if (!value.is_boolean())
      fail(key, fmt::format("must be true or false (got {})", scene::jsonTypeName(value)));
    out = value.get<bool>();
  }
  // A whole number in lo..hi (3.0 is 3; 2.5 and 1e300 are refused).
  void read(const char* key, uint32_t& out, uint32_t lo = 0,
            uint32_t hi = std::numeric_limits<uint32_t>::max()) const {
    if (doc_.contains(key)) out = whole(doc_.at(key), key, lo, hi);
  }
  // A finite float in lo..hi.
  void read(const char* key, float& out, float lo = -std::numeric_limits<float>::max(),
            float hi = std::numeric_limits<float>::max()) const {
    if (!doc_.contains(key)) return;
    out = finite(doc_.at(key), key);
    if (!(out >= lo && out <= hi)) fail(key, fmt::format("{} is outside {}..{}", out, lo, hi));
  }
  uint32_t whole(const json& value, const std::string& key, uint32_t lo, uint32_t hi) const {
    return uint32_t(scene::toInteger(value, source_, key, lo, hi));
  }
  glm::vec3 vec3(const json& value, const std::string& key) const {
    if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
        !value[2].is_number())
      fail(key, "must be an array of 3 numbers");
    return {finite(value[0], key), finite(value[1], key), finite(value[2], key)};
  }
  // A table setting's value (render_settings.h), checked as its type says.
  double setting(const Setting& setting, const json& value) const {
    const std::string key(setting.key);
    switch (setting.type) {
      case SettingType::Flag:
        if (!value.is_boolean())
          fail(key, fmt::format("must be true or false (got {})", scene::jsonTypeName(value)));
        return value.get<bool>() ? 1.0 : 0.0;
      case SettingType::Count:
        return double(
            scene::toInteger(value, source_, key, int64_t(setting.min), int64_t(setting.max)));
      case SettingType::Number: {
        const double v = finite(value, key);
        if (!(v >= setting.min && v <= setting.max))
          fail(key, fmt::format("{} is outside {}..{}", float(v), setting.min, setting.max));
        return v;
      }
      case SettingType::Choice: {
        if (!value.is_string())
          fail(key, fmt::format("must be a string (got {})", scene::jsonTypeName(value)));
        const auto index = setting.parse(value.get<std::string>());
        if (!index) fail(key, fmt::format("'{}' is not a known value", value.get<std::string>()));
        return *index;
      }
    }
    fail(key, "has an unknown type");
  }
  // A number that fits a float: the renderer cannot use NaN or infinity.
  float finite(const json& value, const std::string& key) const {
    if (!value.is_number()) fail(key, "must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > std::numeric_limits<float>::max())
      fail(key, "must be a finite number");
    return float(number);
  }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw Error(fmt::format("{}: \"{}\" {}", source_, key, what));
  }

 private:
  const json& doc_;
  const std::string& source_;
};

// Floats are written as the float the setting holds; nlohmann writes
// enough digits for them to read back exactly.
json settingToJson(const Setting& setting, const RenderSettings& settings) {
  const double v = setting.get(settings);
  switch (setting.type) {
    case SettingType::Flag:
      return v != 0.0;
    case SettingType::Count:
      return uint32_t(v);
    case SettingType::Number:
      return float(v);
    case SettingType::Choice:
      return setting.format(v);
  }
  return nullptr;
}

json overrideToJson(const MaterialOverride& o) {
  const scene::Material& m = o.material;
  json j = {{"index", o.index},
            {"name", m.name},
            {"model", materialModelName(m.model)},
            {"baseColor", toJson(m.baseColor)},
            {"thin", m.thin}};
  for (const auto& f : kFloatFields)
    if (!fromScene(o, f.name)) j[f.name] = m.*f.field;
  for (const auto& f : kColorFields)
    if (!fromScene(o, f.name)) j[f.name] = toJson(m.*f.field);
  return j;
}

// Every field is required but those made editable later (FloatField::
// optional): a partial override would leave the rest to whatever the scene
// holds, which the viewer's image did not show.
MaterialOverride overrideFromJson(const json& j, const std::string& key, const Reader& r) {
  if (!j.is_object()) r.fail(key, "must be an object");
  auto field = [&](const char* name) -> const json& {
    if (!j.contains(name)) r.fail(key + "." + name, "is missing");
    return j.at(name);
  };
  MaterialOverride o;
  const json& index = field("index");
  if (!index.is_number_unsigned() || index.get<uint64_t>() > std::numeric_limits<uint32_t>::max())
    r.fail(key + ".index", "must be a whole number >= 0");
  o.index = index.get<uint32_t>();
  scene::Material& m = o.material;
  if (!field("name").is_string()) r.fail(key + ".name", "must be a string");
  m.name = j.at("name").get<std::string>();
  const json& model = field("model");
  std::optional<scene::MaterialModel> parsed;
  if (model.is_string()) parsed = parseMaterialModel(model.get<std::string>());
  if (!parsed) r.fail(key + ".model", "must be one of disney, lambert, phong, unlit");
  m.model = *parsed;
  auto readColor = [&](const char* name, glm::vec3& to) {
    const json& color = field(name);
    if (!color.is_array() || color.size() != 3)
      r.fail(key + "." + name, "must be an array of 3 numbers");
    for (int c = 0; c < 3; ++c) to[c] = r.finite(color[size_t(c)], key + "." + name);
  };
  readColor("baseColor", m.baseColor);
  for (const auto& f : kFloatFields) {
    if (f.optional && !j.contains(f.name))
      o.sceneValues.push_back(f.name);
    else
      m.*f.field = r.finite(field(f.name), key + "." + f.name);
  }
  for (const auto& f : kColorFields) {
    if (!j.contains(f.name))
      o.sceneValues.push_back(f.name);
    else
      readColor(f.name, m.*f.field);
  }
  if (!field("thin").is_boolean()) r.fail(key + ".thin", "must be true or false");
  m.thin = j.at("thin").get<bool>();
  return o;
}

}  // namespace

const char* materialModelName(scene::MaterialModel model) {
  return nameOf(kModels, model);
}
std::optional<scene::MaterialModel> parseMaterialModel(std::string_view name) {
  return parseName(kModels, name);
}

const std::vector<std::string>& editableMaterialParameters() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& f : kFloatFields) list.push_back(f.name);
    for (const auto& f : kColorFields) list.push_back(f.name);
    return list;
  }();
  return names;
}

void setEditableParameter(scene::Material& material, std::string_view name,
                          const std::vector<float>& values) {
  float* scalar = nullptr;
  glm::vec3* color = name == "baseColor" ? &material.baseColor : nullptr;
  for (const auto& f : kFloatFields)
    if (name == f.name) scalar = &(material.*f.field);
  for (const auto& f : kColorFields)
    if (name == f.name) color = &(material.*f.field);
  if (!scalar && !color) {
    std::string known = "baseColor";
    for (const auto& f : kFloatFields) known += std::string(", ") + f.name;
    for (const auto& f : kColorFields) known += std::string(", ") + f.name;
    throw Error(fmt::format("unknown material parameter '{}' ({})", name, known));
  }
  const size_t expected = color ? 3 : 1;
  if (values.size() != expected)
    throw Error(fmt::format("material parameter '{}' takes {} number(s), got {}", name, expected,
                            values.size()));
  if (color) {
    // The scene's ranges (scene::validate): a coloured F0 may pass 1, the
    // other colours may not.
    const bool unbounded = name == "specularColor";
    for (float v : values)
      if (!(v >= 0.0f && (unbounded ? std::isfinite(v) : v <= 1.0f)))
        throw Error(fmt::format("material parameter '{}' takes values {}, got {}", name,
                                unbounded ? ">= 0" : "in [0, 1]", v));
    *color = {values[0], values[1], values[2]};
  } else {
    *scalar = values[0];
  }
}

std::vector<MaterialOverride> materialOverrides(const std::vector<scene::Material>& loaded,
                                                const std::vector<scene::Material>& edited) {
  std::vector<MaterialOverride> overrides;
  for (size_t i = 0; i < edited.size() && i < loaded.size(); ++i)
    if (!sameEditableParameters(loaded[i], edited[i]))
      overrides.push_back({uint32_t(i), edited[i]});
  return overrides;
}

void applyMaterialOverrides(scene::Scene& scene, const std::vector<MaterialOverride>& overrides,
                            const std::string& source) {
  for (size_t i = 0; i < overrides.size(); ++i) {
    const MaterialOverride& o = overrides[i];
    if (o.index >= scene.materials.size())
      throw Error(
          fmt::format("{}: \"materials[{}].index\" {} is out of range: scene '{}' has {} materials",
                      source, i, o.index, scene.name, scene.materials.size()));
    scene::Material& target = scene.materials[o.index];
    if (target.name != o.material.name)
      throw Error(fmt::format(
          "{}: \"materials[{}].name\" '{}' does not match material {} of scene '{}' ('{}')", source,
          i, o.material.name, o.index, scene.name, target.name));
    applyOverride(o, target);
  }
}

scene::Environment chooseEnvironment(const scene::Environment& sceneEnvironment,
                                     const scene::Scene& scene, const EnvironmentChoice& choice) {
  scene::Environment env = sceneEnvironment;
  if (choice.map == "none") {
    env = scene::Environment{};
  } else if (choice.map == "default") {
    env = scene::defaultEnvironment();
  } else if (!choice.map.empty()) {
    env = scene::loadEnvironmentMap(choice.map);
  }
  if (choice.map != "none" && !env.present() && !scene.hasOwnLighting()) {
    env = scene::defaultEnvironment();
    log::info(
        "scene '{}' has no light{}: lit by the default studio environment (--env none: unlit)",
        scene.name,
        scene.hasEmitters() ? " (its glTF emissive materials are not counted as lights)" : "");
  }
  if (!env.present() && (choice.rotationDegrees || choice.intensity || choice.visibleBackground))
    throw Error(
        "environment: rotation, intensity and background need an environment (--env FILE gives "
        "one)");
  if (choice.rotationDegrees) env.rotationDegrees = *choice.rotationDegrees;
  if (choice.intensity) env.intensity = *choice.intensity;
  if (choice.visibleBackground) env.visibleBackground = *choice.visibleBackground;
  scene::validateEnvironment(env);
  return env;
}

void applyEnvironmentChoice(scene::Scene& scene, const EnvironmentChoice& choice) {
  scene.environment = chooseEnvironment(scene.environment, scene, choice);
}

std::string renderJobToJson(const RenderJob& job) {
  json doc;
  doc["format"] = "penumbra-render";
  doc["version"] = 1;
  doc["scene"] = job.scene;
  doc["vary"] = job.vary;
  doc["set"] = job.set;
  if (!job.variant.empty()) doc["variant"] = job.variant;
  if (!job.animation.animation.empty()) doc["animation"] = job.animation.animation;
  if (job.animation.seconds) doc["time"] = *job.animation.seconds;
  if (job.camera) {
    doc["camera"] = {{"position", toJson(job.camera->position)},
                     {"forward", toJson(job.camera->forward)},
                     {"up", toJson(job.camera->up)},
                     {"verticalFovDegrees", job.camera->verticalFovDegrees},
                     {"orthographicHeight", job.camera->orthographicHeight},
                     {"aspectRatio", job.camera->aspectRatio},
                     {"apertureRadius", job.camera->apertureRadius},
                     {"focusDistance", job.camera->focusDistance},
                     {"apertureBlades", job.camera->apertureBlades}};
  }
  doc["width"] = job.width;
  doc["height"] = job.height;
  doc["spp"] = job.spp;
  for (const Setting& setting : renderSettingsTable())
    if (setting.recorded) doc[std::string(setting.key)] = settingToJson(setting, job.settings);
  if (!job.environment.empty()) {
    const EnvironmentChoice& e = job.environment;
    json env = json::object();
    if (!e.map.empty()) env["map"] = e.map;
    if (e.rotationDegrees) env["rotation"] = *e.rotationDegrees;
    if (e.intensity) env["intensity"] = *e.intensity;
    if (e.visibleBackground) env["background"] = *e.visibleBackground;
    doc["environment"] = env;
  }
  if (!job.materials.empty()) {
    json materials = json::array();
    for (const auto& o : job.materials) materials.push_back(overrideToJson(o));
    doc["materials"] = materials;
  }
  // nlohmann writes floats with max_digits10 digits: they read back exactly.
  return doc.dump(2) + "\n";
}

RenderJob renderJobFromJson(const std::string& text, const std::string& source,
                            const scene::InputLimits& limits) {
  // Bounded before parsing, as scene files are (scene/input_limits.h).
  scene::requireAtMost(text.size(), limits.maxJsonBytes, "maxJsonBytes",
                       source + ": JSON text size in bytes");
  scene::requireJsonDepth(text, limits, source);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    // Syntax errors, and numbers too large for a double (1e400).
    throw Error(fmt::format("{}: not valid JSON ({})", source, e.what()));
  }
  if (!doc.is_object() || !doc.contains("format") || doc["format"] != "penumbra-render")
    throw Error(fmt::format(
        "{}: not a penumbra render settings file (\"format\": \"penumbra-render\")", source));
  if (!doc.contains("version") || doc["version"] != 1)
    throw Error(fmt::format("{}: unsupported version (this build reads version 1)", source));
  Reader r(doc, source);
  RenderJob job;
  r.read("scene", job.scene);
  r.read("vary", job.vary);
  r.read("set", job.set);
  r.read("variant", job.variant);
  r.read("animation", job.animation.animation);
  if (doc.contains("time")) {
    if (!doc["time"].is_number() || !std::isfinite(doc["time"].get<double>()))
      r.fail("time", "must be a finite number (seconds)");
    job.animation.seconds = doc["time"].get<double>();
  }
  if (doc.contains("camera")) {
    const json& c = doc["camera"];
    if (!c.is_object()) r.fail("camera", "must be an object");
    scene::Camera camera;
    for (const char* key : {"position", "forward", "up"})
      if (!c.contains(key)) r.fail(std::string("camera.") + key, "is missing");
    camera.position = r.vec3(c["position"], "camera.position");
    camera.forward = r.vec3(c["forward"], "camera.forward");
    camera.up = r.vec3(c["up"], "camera.up");
    // Zero would normalise to NaN; parallel ones leave no image plane.
    if (!(glm::length(camera.forward) > 0.0f) || !std::isfinite(glm::length(camera.forward)))
      r.fail("camera.forward", "must be a non-zero direction of finite length");
    if (!(glm::length(glm::cross(camera.forward, camera.up)) > 0.0f))
      r.fail("camera.up", "must be non-zero and not parallel to camera.forward");
    if (c.contains("verticalFovDegrees")) {
      camera.verticalFovDegrees = r.finite(c["verticalFovDegrees"], "camera.verticalFovDegrees");
      if (!(camera.verticalFovDegrees > 0.0f && camera.verticalFovDegrees < 180.0f))
        r.fail("camera.verticalFovDegrees", "must lie in (0, 180)");
    }
    for (auto [key, field] : {std::pair{"apertureRadius", &scene::Camera::apertureRadius},
                              std::pair{"focusDistance", &scene::Camera::focusDistance},
                              std::pair{"orthographicHeight", &scene::Camera::orthographicHeight},
                              std::pair{"aspectRatio", &scene::Camera::aspectRatio}}) {
      if (!c.contains(key)) continue;
      camera.*field = r.finite(c[key], std::string("camera.") + key);
    }
    if (c.contains("apertureBlades"))
      camera.apertureBlades = r.whole(c["apertureBlades"], "camera.apertureBlades", 0, 32);
    try {
      scene::validateCamera(camera);
    } catch (const Error& e) {
      throw Error(fmt::format("{}: {}", source, e.what()));
    }
    job.camera = camera;
  }
  r.read("width", job.width);
  r.read("height", job.height);
  r.read("spp", job.spp, 1, kMaxSamplesPerPixel);
  for (const Setting& setting : renderSettingsTable())
    if (setting.recorded && doc.contains(setting.key))
      setting.set(job.settings, r.setting(setting, doc.at(std::string(setting.key))));
  if (doc.contains("environment")) {
    const json& e = doc["environment"];
    if (!e.is_object()) r.fail("environment", "must be an object");
    EnvironmentChoice& choice = job.environment;
    if (e.contains("map")) {
      if (!e["map"].is_string()) r.fail("environment.map", "must be a string");
      choice.map = e["map"].get<std::string>();
    }
    for (auto [key, field] : {std::pair{"rotation", &EnvironmentChoice::rotationDegrees},
                              std::pair{"intensity", &EnvironmentChoice::intensity}}) {
      if (!e.contains(key)) continue;
      choice.*field = r.finite(e[key], std::string("environment.") + key);
    }
    if (choice.intensity && !(*choice.intensity >= 0.0f))
      r.fail("environment.intensity", "must be >= 0");
    if (e.contains("background")) {
      if (!e["background"].is_boolean()) r.fail("environment.background", "must be true or false");
      choice.visibleBackground = e["background"].get<bool>();
    }
  }
  if (doc.contains("materials")) {
    const json& materials = doc["materials"];
    if (!materials.is_array()) r.fail("materials", "must be an array");
    for (size_t i = 0; i < materials.size(); ++i)
      job.materials.push_back(overrideFromJson(materials[i], fmt::format("materials[{}]", i), r));
  }
  if (!isValidImageSize(job.width, job.height))
    r.fail("width/height", fmt::format("must be 1..{}", kMaxImageSide));
  if (job.spp < 1) r.fail("spp", "must be at least 1");
  return job;
}

void saveRenderJob(const std::string& path, const RenderJob& job) {
  std::ofstream out(path, std::ios::binary);
  out << renderJobToJson(job);
  if (!out) throw Error(fmt::format("cannot write render settings '{}'", path));
}

RenderJob loadRenderJob(const std::string& path, const scene::InputLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read render settings '{}'", path));
  // Refused before reading: maxJsonBytes bounds the text as well as the tree.
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec)
    scene::requireAtMost(size, limits.maxJsonBytes, "maxJsonBytes",
                         path + ": JSON text size in bytes");
  std::stringstream text;
  text << in.rdbuf();
  return renderJobFromJson(text.str(), path, limits);
}

}  // namespace penumbra::render
