#include "penumbra/scene/gltf_lights.h"

#include <fmt/format.h>

#include <cmath>

#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {

std::optional<PointLight> nodeLight(const tinygltf::Model& model, const tinygltf::Node& node,
                                    const glm::dmat4& world, const std::string& where) {
  const auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end()) return std::nullopt;
  const tinygltf::Value& index = ext->second.Get("light");
  if (!index.IsNumber())
    throw Error(fmt::format("{}: KHR_lights_punctual has no light index", where));
  const int i = index.GetNumberAsInt();
  if (i < 0 || size_t(i) >= model.lights.size())
    throw Error(
        fmt::format("{}: light {} does not exist ({} lights)", where, i, model.lights.size()));
  const tinygltf::Light& src = model.lights[size_t(i)];
  const std::string what =
      fmt::format("{} light {}{}", where, i, src.name.empty() ? "" : " '" + src.name + "'");

  glm::vec3 color(1.0f);
  if (!src.color.empty()) {
    if (src.color.size() != 3) throw Error(fmt::format("{}: color must have 3 values", what));
    color = glm::vec3(float(src.color[0]), float(src.color[1]), float(src.color[2]));
  }
  if (!(src.intensity >= 0.0) || !std::isfinite(src.intensity) || color.r < 0 || color.g < 0 ||
      color.b < 0)
    throw Error(fmt::format("{}: intensity and color must be finite and >= 0", what));
  if (!(src.range >= 0.0) || !std::isfinite(src.range))
    throw Error(fmt::format("{}: range must be > 0 (or absent)", what));

  PointLight light;
  light.intensity = color * float(src.intensity);
  light.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
  const glm::dvec3 facing = glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
  if (!(glm::length(facing) > 0.0))
    throw Error(fmt::format("{}: the node's transform collapses its -z axis", what));
  light.direction = glm::vec3(glm::normalize(facing));
  light.range = float(src.range);
  if (src.type == "directional") {
    light.type = LightType::Directional;
  } else if (src.type == "spot") {
    const double inner = src.spot.innerConeAngle, outer = src.spot.outerConeAngle;
    const double quarterTurn = std::acos(-1.0) / 2.0;
    if (!(inner >= 0.0 && inner < outer && outer <= quarterTurn + 1e-9))
      throw Error(fmt::format(
          "{}: spot cone angles must satisfy 0 <= inner < outer <= pi/2 (inner {}, outer {})", what,
          inner, outer));
    light.type = LightType::Spot;
    light.innerConeDegrees = float(inner * 180.0 / std::acos(-1.0));
    light.outerConeDegrees = float(outer * 180.0 / std::acos(-1.0));
  } else if (src.type == "point") {
    light.type = LightType::Point;
  } else {
    throw Error(
        fmt::format("{}: unknown light type '{}' (point, spot, directional)", what, src.type));
  }
  return light;
}

}  // namespace penumbra::scene::gltf
