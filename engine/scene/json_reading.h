#pragma once
// Reading typed values out of scene-file JSON with errors that say where.
#include <fmt/format.h>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "util/error.h"

namespace penumbra::scene {

// Positions and translations are read as double (world placements stay
// double until the renderer moves them to the camera); everything else float.
inline glm::dvec3 readDVec3(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 3)
    throw Error(fmt::format("{}: expected an array of 3 numbers", where));
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!value[i].is_number()) throw Error(fmt::format("{}: element {} is not a number", where, i));
    v[i] = value[i].get<double>();
  }
  return v;
}

inline glm::vec3 readVec3(const nlohmann::json& value, const std::string& where) {
  return glm::vec3(readDVec3(value, where));
}

inline const nlohmann::json& require(const nlohmann::json& object, const char* key,
                                     const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw Error(fmt::format("{}: missing \"{}\"", where, key));
  return object.at(key);
}

inline float readFloat(const nlohmann::json& m, const char* key, float fallback,
                       const std::string& where) {
  if (!m.contains(key)) return fallback;
  if (!m.at(key).is_number()) throw Error(fmt::format("{}: \"{}\" is not a number", where, key));
  return m.at(key).get<float>();
}

}  // namespace penumbra::scene
