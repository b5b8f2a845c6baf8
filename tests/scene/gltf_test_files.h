#pragma once
// Small glTF files written by the tests themselves, for inputs that are
// easier to read as code than as checked-in files: hostile headers, counts
// and nesting (docs/security.md).
#include <fmt/format.h>
#include <unistd.h>

#include <catch2/catch_test_macros.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "penumbra/scene/gltf_loader.h"
#include "penumbra/util/error.h"

namespace penumbra::test {

// importGltf's error for `path`, checked to be one line naming the file.
inline std::string gltfRefusal(const std::string& path, const scene::InputLimits& limits = {},
                               const scene::AnimationChoice& animation = {}) {
  try {
    scene::importGltf(path, {}, limits, animation);
  } catch (const Error& e) {
    const std::string message = e.what();
    CHECK(message.find(std::filesystem::path(path).filename().string()) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    return message;
  }
  FAIL("no error for " << path);
  return "";
}

// The whole text of the file at `path`.
inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string gltfRefusalWith(const std::string& path,
                                   const scene::AnimationChoice& animation) {
  return gltfRefusal(path, {}, animation);
}

// A folder of its own under the system's temporary folder, removed with it.
class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              fmt::format("penumbra-{}-{}", name, ::getpid())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  // Writes `bytes` to `name` in the folder; returns its path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return file.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// `value` as `n` bytes, least significant first (glTF, GLB, TGA) or first
// most significant (PSD).
inline std::string littleEndian(uint64_t value, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += char((value >> (8 * i)) & 0xff);
  return s;
}
inline std::string bigEndian(uint64_t value, int n) {
  std::string s;
  for (int i = n - 1; i >= 0; --i) s += char((value >> (8 * i)) & 0xff);
  return s;
}

// The 36 bytes of one triangle's positions (0,0,0) (1,0,0) (0,1,0) as floats.
inline std::string trianglePositions() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string s(sizeof(p), '\0');
  std::memcpy(s.data(), p, sizeof(p));
  return s;
}

// A .gltf of that triangle, its positions in buffer `buffer` (a file name
// or data), using material 0 when `material` is given: `material` is the
// material object, `images` and `textures` their arrays' contents.
inline std::string triangleGltf(const std::string& bufferUri, const std::string& material = "",
                                const std::string& images = "", const std::string& textures = "") {
  std::string doc = R"({"asset":{"version":"2.0"},
    "buffers":[{"uri":")" +
                    bufferUri + R"(","byteLength":36}],
    "bufferViews":[{"buffer":0,"byteLength":36}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0})";
  doc += material.empty() ? "}]}]," : R"(,"material":0}]}],"materials":[)" + material + "],";
  if (!images.empty()) doc += R"("images":[)" + images + "],";
  if (!textures.empty()) doc += R"("textures":[)" + textures + "],";
  return doc + R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
}

// A .glb of `json` and, if not empty, a BIN chunk of `bin` (both padded to
// 4 bytes as the format asks: JSON with spaces, BIN with zeros).
inline std::string glb(std::string json, std::string bin = "") {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string chunks = littleEndian(json.size(), 4) + "JSON" + json;
  if (!bin.empty()) chunks += littleEndian(bin.size(), 4) + std::string("BIN\0", 4) + bin;
  return "glTF" + littleEndian(2, 4) + littleEndian(12 + chunks.size(), 4) + chunks;
}

// Image headers that claim `width` x `height` pixels and hold none: what
// stb_image reads to size its allocation.
inline std::string psdHeader(uint32_t width, uint32_t height) {
  // Signature, version 1, 6 reserved bytes, 3 channels, height, width,
  // 8 bits a channel, RGB colour mode.
  return "8BPS" + bigEndian(1, 2) + std::string(6, '\0') + bigEndian(3, 2) + bigEndian(height, 4) +
         bigEndian(width, 4) + bigEndian(8, 2) + bigEndian(3, 2);
}
inline std::string tgaHeader(uint32_t width, uint32_t height) {
  // No id, no colour map, run-length-encoded true colour, origin (0, 0),
  // 32 bits a pixel; then a few bytes of "pixels" (stb_image reads on past
  // the end as zeros).
  return std::string("\0\0\x0a", 3) + std::string(9, '\0') + littleEndian(width, 2) +
         littleEndian(height, 2) + std::string("\x20\0", 2) + std::string(172, '\xff');
}

// A glTF file's binary buffer and its views and accessors, one view per
// accessor, written beside the JSON as "<name>.bin".
class GltfWriter {
 public:
  // Float accessor of `type` (SCALAR, VEC3, VEC4, MAT4) holding `values`.
  int floats(const std::vector<float>& values, const std::string& type, int components,
             const std::string& extra = "") {
    std::string bytes(values.size() * 4, '\0');
    std::memcpy(bytes.data(), values.data(), bytes.size());
    return add(bytes, 5126, type, int(values.size()) / components, extra);
  }
  // Unsigned byte VEC4 accessor (JOINTS_0).
  int bytes4(const std::vector<uint8_t>& values, const std::string& extra = "") {
    return add(std::string(values.begin(), values.end()), 5121, "VEC4", int(values.size() / 4),
               extra);
  }
  std::string write(const test::TempFolder& folder, const std::string& name,
                    const std::string& rest) const {
    folder.write(name + ".bin", bin_);
    return folder.write(name + ".gltf",
                        fmt::format(R"({{"asset":{{"version":"2.0"}},
          "buffers":[{{"uri":"{}.bin","byteLength":{}}}],
          "bufferViews":[{}],"accessors":[{}],{}}})",
                                    name, bin_.size(), join(views_), join(accessors_), rest));
  }

 private:
  int add(const std::string& bytes, int componentType, const std::string& type, int count,
          const std::string& extra) {
    while (bin_.size() % 4) bin_ += '\0';
    views_.push_back(fmt::format(R"({{"buffer":0,"byteOffset":{},"byteLength":{}}})", bin_.size(),
                                 bytes.size()));
    bin_ += bytes;
    accessors_.push_back(
        fmt::format(R"({{"bufferView":{},"componentType":{},"count":{},"type":"{}"{}}})",
                    views_.size() - 1, componentType, count, type, extra));
    return int(accessors_.size()) - 1;
  }
  static std::string join(const std::vector<std::string>& parts) {
    std::string s;
    for (const auto& p : parts) s += (s.empty() ? "" : ",") + p;
    return s;
  }
  std::string bin_;
  std::vector<std::string> views_, accessors_;
};

}  // namespace penumbra::test
