#include "penumbra/scene/implicit_json.h"

#include <fmt/format.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <set>

#include "penumbra/scene/json_reading.h"
#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

const std::set<std::string> kCommonKeys = {"name", "kind", "material", "transform"};
const std::set<std::string> kSphereTracingKeys = {"maxSteps", "tolerance"};
// The kinds scene::isSignedDistanceKind names, as the file spells them.
const std::set<std::string> kMarchedKinds = {"torus", "roundedBox", "blend", "mandelbulb"};

// A shape parameter: any number, converted to float as it is. A value past
// float's range becomes infinity, which validateImplicit refuses naming the
// object, the parameter and the value, as it does every out-of-range size.
float shapeParameter(const json& object, const char* key, const std::string& where) {
  const json& value = require(object, key, where);
  if (!value.is_number()) throwWrongType(where, key, "a number", value);
  return value.get<float>();
}

uint32_t readCount(const json& object, const char* key, uint32_t fallback,
                   const std::string& where) {
  return uint32_t(readInteger(object, key, fallback, 1, 1000000, where));
}

glm::vec2 readVec2(const json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
    throw Error(fmt::format("{}: expected an array of 2 numbers", where));
  return {value[0].get<float>(), value[1].get<float>()};
}

// Typos ("radious") would otherwise silently fall back to defaults.
void rejectUnknownKeys(const json& object, const std::set<std::string>& allowed,
                       const std::string& where) {
  for (const auto& [key, value] : object.items())
    if (!allowed.count(key)) {
      std::string list;
      for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
      throw Error(fmt::format("{}: unknown key \"{}\" (allowed: {})", where, key, list));
    }
}

// The keys a shape kind reads, beside the common ones.
std::set<std::string> shapeKeys(const std::string& kind) {
  if (kind == "sphere") return {"radius"};
  if (kind == "plane") return {"halfExtents"};
  if (kind == "box") return {"halfExtents"};
  if (kind == "torus") return {"majorRadius", "minorRadius"};
  if (kind == "roundedBox") return {"halfExtents", "cornerRadius"};
  if (kind == "blend") return {"blendRadius", "primitives"};
  if (kind == "mandelbulb") return {"power", "iterations"};
  return {};
}

const char* kKinds = "sphere, plane, box, torus, roundedBox, blend, mandelbulb";
const char* kBlendKinds = "sphere, box, torus, roundedBox";

std::variant<implicit::Sphere, implicit::Box, implicit::Torus, implicit::RoundedBox>
parseBlendableShape(const json& o, const std::string& kind, const std::string& where) {
  if (kind == "sphere") return implicit::Sphere{shapeParameter(o, "radius", where)};
  if (kind == "box")
    return implicit::Box{readVec3(require(o, "halfExtents", where), where + " halfExtents")};
  if (kind == "torus")
    return implicit::Torus{shapeParameter(o, "majorRadius", where),
                           shapeParameter(o, "minorRadius", where)};
  if (kind == "roundedBox")
    return implicit::RoundedBox{readVec3(require(o, "halfExtents", where), where + " halfExtents"),
                                shapeParameter(o, "cornerRadius", where)};
  throw Error(fmt::format("{}: kind '{}' cannot be blended ({})", where, kind, kBlendKinds));
}

implicit::Blend parseBlend(const json& o, const std::string& where) {
  implicit::Blend blend;
  blend.blendRadius = shapeParameter(o, "blendRadius", where);
  const json& primitives = require(o, "primitives", where);
  if (!primitives.is_array()) throw Error(where + ": \"primitives\" must be an array");
  for (const auto& p : primitives) {
    const std::string at = fmt::format("{} primitive {}", where, blend.primitives.size());
    if (!p.is_object()) throw Error(at + ": must be an object");
    const std::string kind = requireString(p, "kind", at);
    auto allowed = shapeKeys(kind);
    allowed.insert({"kind", "offset"});
    rejectUnknownKeys(p, allowed, at);
    implicit::BlendPrimitive primitive{parseBlendableShape(p, kind, at), glm::vec3(0.0f)};
    if (p.contains("offset")) primitive.offset = readVec3(p.at("offset"), at + " offset");
    blend.primitives.push_back(primitive);
  }
  return blend;
}

ImplicitShape parseShape(const json& o, const std::string& kind, const std::string& where) {
  if (kind == "plane") {
    implicit::Plane plane;
    if (o.contains("halfExtents"))
      plane.halfExtents = readVec2(o.at("halfExtents"), where + " halfExtents");
    return plane;
  }
  if (kind == "blend") return parseBlend(o, where);
  if (kind == "mandelbulb") {
    implicit::Mandelbulb bulb;
    bulb.power = readFloat(o, "power", bulb.power, where);
    bulb.iterations = readCount(o, "iterations", bulb.iterations, where);
    return bulb;
  }
  return std::visit([](auto shape) -> ImplicitShape { return shape; },
                    parseBlendableShape(o, kind, where));
}

// Object to world = unitScale * translate * rotate * scale.
// Double, as every world placement (scene.h).
glm::dmat4 parseTransform(const json& t, float unitScale, const std::string& where) {
  if (!t.is_object()) throw Error(where + ": must be an object");
  rejectUnknownKeys(t, {"translate", "rotate", "scale"}, where);
  glm::dmat4 m(1.0);
  if (t.contains("translate"))
    m = glm::translate(m, readDVec3(t.at("translate"), where + " translate"));
  if (t.contains("rotate")) {
    const json& r = t.at("rotate");
    const std::string at = where + " rotate";
    if (!r.is_object()) throw Error(at + ": must be an object {\"axis\": [x,y,z], \"degrees\": a}");
    rejectUnknownKeys(r, {"axis", "degrees"}, at);
    const glm::vec3 axis = readVec3(require(r, "axis", at), at + " axis");
    if (!(glm::length(axis) > 0.0f)) throw Error(at + ": the axis must be non-zero");
    m = glm::rotate(m, glm::radians(double(requireFloat(r, "degrees", at))),
                    glm::dvec3(glm::normalize(axis)));
  }
  if (t.contains("scale")) {
    const json& s = t.at("scale");
    const glm::vec3 scale =
        s.is_number() ? glm::vec3(toFloat(s, where, "scale")) : readVec3(s, where + " scale");
    m = glm::scale(m, glm::dvec3(scale));
  }
  return glm::scale(glm::dmat4(1.0), glm::dvec3(unitScale)) * m;
}

ImplicitObject parseObject(const json& o, size_t index,
                           const std::map<std::string, uint32_t>& materialIndex, float unitScale,
                           const std::string& where) {
  const std::string numbered = fmt::format("{} implicit {}", where, index);
  if (!o.is_object()) throw Error(numbered + ": must be an object");
  const std::string kind = requireString(o, "kind", numbered);
  ImplicitObject object;
  object.name =
      o.contains("name") ? requireString(o, "name", numbered) : kind + std::to_string(index);
  const std::string at = fmt::format("{} implicit '{}'", where, object.name);
  auto allowed = shapeKeys(kind);
  if (allowed.empty()) throw Error(fmt::format("{}: unknown kind '{}' ({})", at, kind, kKinds));
  allowed.insert(kCommonKeys.begin(), kCommonKeys.end());
  if (kMarchedKinds.count(kind))
    allowed.insert(kSphereTracingKeys.begin(), kSphereTracingKeys.end());
  rejectUnknownKeys(o, allowed, at);
  object.shape = parseShape(o, kind, at);

  const std::string materialName = requireString(o, "material", at);
  auto it = materialIndex.find(materialName);
  if (it == materialIndex.end())
    throw Error(fmt::format("{}: unknown material '{}'", at, materialName));
  object.material = it->second;
  object.transform = o.contains("transform")
                         ? parseTransform(o.at("transform"), unitScale, at + " transform")
                         : glm::scale(glm::dmat4(1.0), glm::dvec3(unitScale));
  object.sphereTracing.maxSteps = readCount(o, "maxSteps", object.sphereTracing.maxSteps, at);
  object.sphereTracing.tolerance = readFloat(o, "tolerance", object.sphereTracing.tolerance, at);
  return object;
}

}  // namespace

std::vector<ImplicitObject> parseImplicits(const json& implicits,
                                           const std::map<std::string, uint32_t>& materialIndex,
                                           float unitScale, const std::string& where) {
  if (!implicits.is_array()) throw Error(where + ": \"implicits\" must be an array");
  std::vector<ImplicitObject> objects;
  for (const auto& o : implicits)
    objects.push_back(parseObject(o, objects.size(), materialIndex, unitScale, where));
  return objects;
}

}  // namespace penumbra::scene
