#pragma once
// Reading typed values out of scene-file JSON with errors that say where.
#include <fmt/format.h>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "util/error.h"

namespace penumbra::scene {

inline glm::vec3 readVec3(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 3)
    throw Error(fmt::format("{}: expected an array of 3 numbers", where));
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!value[i].is_number()) throw Error(fmt::format("{}: element {} is not a number", where, i));
    v[i] = value[i].get<float>();
  }
  return v;
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
