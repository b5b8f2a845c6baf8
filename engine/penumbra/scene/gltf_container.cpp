#include "penumbra/scene/gltf_container.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {
namespace {

uint32_t readU32(const unsigned char* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);  // little-endian, as the targets
  return v;
}

void appendU32(std::vector<unsigned char>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back((unsigned char)((v >> (8 * i)) & 0xff));
}

}  // namespace

bool usesExtension(const nlohmann::json& doc, const char* extension) {
  const auto used = doc.find("extensionsUsed");
  if (used == doc.end() || !used->is_array()) return false;
  for (const auto& name : *used)
    if (name.is_string() && name.get<std::string>() == extension) return true;
  return false;
}

void editJson(std::vector<unsigned char>& data, bool binary,
              const std::function<bool(nlohmann::json&)>& edit, const std::string& at) {
  size_t jsonStart = 0, jsonLength = data.size();
  if (binary) {
    // "glTF", version, length, then the JSON chunk's length and type.
    if (data.size() < 20) return;
    jsonStart = 20;
    jsonLength = readU32(data.data() + 12);
    if (jsonLength > data.size() - 20) return;  // tinygltf reports it
  }
  nlohmann::json doc =
      nlohmann::json::parse(data.begin() + std::ptrdiff_t(jsonStart),
                            data.begin() + std::ptrdiff_t(jsonStart + jsonLength), nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !edit(doc)) return;
  std::string json = doc.dump();
  if (!binary) {
    data.assign(json.begin(), json.end());
    return;
  }
  while (json.size() % 4 != 0) json += ' ';
  const size_t rest = jsonStart + jsonLength;  // the chunks after the JSON
  std::vector<unsigned char> out(data.begin(), data.begin() + 12);
  appendU32(out, uint32_t(json.size()));
  appendU32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  out.insert(out.end(), data.begin() + std::ptrdiff_t(rest), data.end());
  if (out.size() > UINT32_MAX) throw Error(fmt::format("{}: larger than 4 GiB once edited", at));
  const uint32_t total = uint32_t(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  data = std::move(out);
}

}  // namespace penumbra::scene::gltf
