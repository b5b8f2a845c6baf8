#pragma once
// Reading typed values out of scene-file JSON with errors that say where.
// Every read checks the type and the range before converting: nlohmann's
// get<T>() throws a json::type_error that names neither file nor field, and
// converts an out-of-range double to float (infinity) or to an unsigned
// integer (undefined behaviour) without a word. `where` names the file and
// the object ("scene 'a.json' material 'white'"), `key` the field.
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "penumbra/util/error.h"

namespace penumbra::scene {

// "a number", "a string", ... for messages.
inline const char* jsonTypeName(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return "a number";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    default:
      return "not a JSON value";
  }
}

// "<where>: "<key>" is not <expected> (got <type>)".
[[noreturn]] inline void throwWrongType(const std::string& where, std::string_view key,
                                        const char* expected, const nlohmann::json& got) {
  throw Error(
      fmt::format("{}: \"{}\" is not {} (got {})", where, key, expected, jsonTypeName(got)));
}

// A number that fits a float (finite, |v| <= 3.4e38): a larger one would
// become infinity, which no renderer input means.
inline float toFloat(const nlohmann::json& value, const std::string& where, std::string_view key) {
  if (!value.is_number()) throwWrongType(where, key, "a number", value);
  const double v = value.get<double>();
  if (!std::isfinite(v) || std::abs(v) > double(std::numeric_limits<float>::max()))
    throw Error(fmt::format("{}: \"{}\" {} does not fit a float (magnitude at most 3.4e38)", where,
                            key, v));
  return float(v);
}

// A whole number in [lo, hi]; 3.0 is accepted as 3, 1e300 and 2.5 are not.
inline int64_t toInteger(const nlohmann::json& value, const std::string& where,
                         std::string_view key, int64_t lo, int64_t hi) {
  if (!value.is_number()) throwWrongType(where, key, "a whole number", value);
  bool inRange = false;
  int64_t v = 0;
  if (value.is_number_unsigned()) {
    const uint64_t u = value.get<uint64_t>();
    inRange = u <= uint64_t(hi) && int64_t(u) >= lo;
    v = inRange ? int64_t(u) : 0;
  } else if (value.is_number_integer()) {
    v = value.get<int64_t>();
    inRange = v >= lo && v <= hi;
  } else {
    // Compared as double before converting: the conversion of a double
    // outside int64's range is undefined.
    const double d = value.get<double>();
    inRange = std::floor(d) == d && d >= double(lo) && d <= double(hi);
    v = inRange ? int64_t(d) : 0;
  }
  if (!inRange)
    throw Error(fmt::format("{}: \"{}\" {} is not a whole number in {}..{}", where, key,
                            value.dump(), lo, hi));
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
  if (!m.is_object() || !m.contains(key)) return fallback;
  return toFloat(m.at(key), where, key);
}

inline float requireFloat(const nlohmann::json& m, const char* key, const std::string& where) {
  return toFloat(require(m, key, where), where, key);
}

inline int64_t readInteger(const nlohmann::json& m, const char* key, int64_t fallback, int64_t lo,
                           int64_t hi, const std::string& where) {
  if (!m.is_object() || !m.contains(key)) return fallback;
  return toInteger(m.at(key), where, key, lo, hi);
}

inline std::string readString(const nlohmann::json& m, const char* key, const std::string& fallback,
                              const std::string& where) {
  if (!m.is_object() || !m.contains(key)) return fallback;
  const nlohmann::json& value = m.at(key);
  if (!value.is_string()) throwWrongType(where, key, "a string", value);
  return value.get<std::string>();
}

inline std::string requireString(const nlohmann::json& m, const char* key,
                                 const std::string& where) {
  const nlohmann::json& value = require(m, key, where);
  if (!value.is_string()) throwWrongType(where, key, "a string", value);
  return value.get<std::string>();
}

inline bool readBool(const nlohmann::json& m, const char* key, bool fallback,
                     const std::string& where) {
  if (!m.is_object() || !m.contains(key)) return fallback;
  const nlohmann::json& value = m.at(key);
  if (!value.is_boolean()) throwWrongType(where, key, "true or false", value);
  return value.get<bool>();
}

// Positions and translations are read as double (world placements stay
// double until the renderer moves them to the camera); everything else float.
// Here `where` names the field itself ("scene 'a.json' camera.position").
inline glm::dvec3 readDVec3(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 3)
    throw Error(fmt::format("{}: expected an array of 3 numbers, got {}", where,
                            value.is_array() ? fmt::format("{} elements", value.size())
                                             : std::string(jsonTypeName(value))));
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!value[size_t(i)].is_number())
      throw Error(fmt::format("{}: element {} is not a number (got {})", where, i,
                              jsonTypeName(value[size_t(i)])));
    v[i] = value[size_t(i)].get<double>();
    if (!std::isfinite(v[i])) throw Error(fmt::format("{}: element {} is not finite", where, i));
  }
  return v;
}

inline glm::vec3 readVec3(const nlohmann::json& value, const std::string& where) {
  const glm::dvec3 v = readDVec3(value, where);
  for (int i = 0; i < 3; ++i)
    if (std::abs(v[i]) > double(std::numeric_limits<float>::max()))
      throw Error(fmt::format("{}: element {} ({}) does not fit a float (magnitude at most 3.4e38)",
                              where, i, v[i]));
  return glm::vec3(v);
}

// A direction: non-zero (normalising zero gives NaN), returned unit length.
// Normalised in float, as the loaders always have, so images stay the same.
inline glm::vec3 readDirection(const nlohmann::json& value, const std::string& where) {
  const glm::vec3 v = readVec3(value, where);
  const float length = glm::length(v);
  if (!(length > 0.0f) || !std::isfinite(length))
    throw Error(fmt::format("{}: must be a non-zero direction of finite length", where));
  return glm::normalize(v);
}

}  // namespace penumbra::scene
