// EXT_meshopt_compression: files whose buffer views meshoptimizer's encoders
// compressed here (vertex streams, with and without the octahedral filter;
// triangle and index-sequence index streams), loaded and compared with the
// values that went in.
#include <fmt/format.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cstring>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gltf_test_files.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/input_limits.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;

namespace {

// A 3 x 3 grid of vertices, bent so that no two share a position, with unit
// normals leaning out of the grid; 8 triangles.
struct Grid {
  std::vector<glm::vec3> positions, normals;
  std::vector<uint32_t> triangles;
  Grid() {
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) {
        positions.push_back({0.5f * x, 0.5f * y, 0.1f * float(x * y) + 0.01f * float(x)});
        normals.push_back(
            glm::normalize(glm::vec3(0.3f * float(x - 1), 0.2f * float(y - 1), 1.0f)));
      }
    for (uint32_t y = 0; y < 2; ++y)
      for (uint32_t x = 0; x < 2; ++x) {
        const uint32_t a = y * 3 + x;
        for (uint32_t v : {a, a + 1, a + 4, a, a + 4, a + 3}) triangles.push_back(v);
      }
  }
};

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
  std::string s(values.size() * sizeof(T), '\0');
  std::memcpy(s.data(), values.data(), s.size());
  return s;
}

std::string encodeVertices(const void* data, size_t count, size_t stride) {
  std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
  out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(),
                                        data, count, stride));
  REQUIRE(!out.empty());
  return out;
}

// The compressed streams of the grid and the glTF that reads them: buffer 0
// holds the compressed bytes, buffer 1 is the fallback, with no data of its
// own (in a .glb, buffer 0 is the BIN chunk; in a .gltf, `compressedUri`).
struct CompressedGrid {
  std::string bin, json;
};

CompressedGrid compressedGrid(const Grid& g, const std::string& compressedUri) {
  const size_t n = g.positions.size();
  // Positions as they are (12 bytes); normals as octahedral bytes (4, the
  // fourth unused): KHR_mesh_quantization's normalized BYTE VEC3 after the filter.
  std::vector<float> normals4;
  for (const auto& v : g.normals) normals4.insert(normals4.end(), {v.x, v.y, v.z, 1.0f});
  std::vector<int8_t> octahedral(n * 4);
  meshopt_encodeFilterOct(octahedral.data(), n, 4, 8, normals4.data());
  const std::string positions = encodeVertices(g.positions.data(), n, 12);
  const std::string normals = encodeVertices(octahedral.data(), n, 4);
  std::vector<uint16_t> triangles16(g.triangles.begin(), g.triangles.end());
  std::string triangles(meshopt_encodeIndexBufferBound(g.triangles.size(), n), '\0');
  triangles.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(triangles.data()),
                                             triangles.size(), triangles16.data(),
                                             triangles16.size()));
  // The same triangles, each turned over, as an index sequence of 32-bit indices.
  std::vector<uint32_t> reversed;
  for (size_t t = 0; t < g.triangles.size(); t += 3)
    reversed.insert(reversed.end(), {g.triangles[t + 2], g.triangles[t + 1], g.triangles[t]});
  std::string sequence(meshopt_encodeIndexSequenceBound(reversed.size(), n), '\0');
  sequence.resize(meshopt_encodeIndexSequence(reinterpret_cast<unsigned char*>(sequence.data()),
                                              sequence.size(), reversed.data(), reversed.size()));
  REQUIRE(!triangles.empty());
  REQUIRE(!sequence.empty());

  CompressedGrid out;
  std::string views;
  size_t fallbackOffset = 0;
  auto add = [&](const std::string& stream, size_t stride, size_t count, const char* mode,
                 const char* filter, bool vertexView) {
    while (out.bin.size() % 4) out.bin += '\0';
    const size_t length = count * stride;
    views += fmt::format(
        R"({}{{"buffer":1,"byteOffset":{},"byteLength":{}{},"extensions":{{"EXT_meshopt_compression":{{
          "buffer":0,"byteOffset":{},"byteLength":{},"byteStride":{},"count":{},"mode":"{}"{}}}}}}})",
        views.empty() ? "" : ",", fallbackOffset, length,
        vertexView ? fmt::format(R"(,"byteStride":{})", stride) : "", out.bin.size(), stream.size(),
        stride, count, mode, filter ? fmt::format(R"(,"filter":"{}")", filter) : "");
    out.bin += stream;
    fallbackOffset += (length + 3) / 4 * 4;
  };
  add(positions, 12, n, "ATTRIBUTES", nullptr, true);
  add(normals, 4, n, "ATTRIBUTES", "OCTAHEDRAL", true);
  add(triangles, 2, g.triangles.size(), "TRIANGLES", nullptr, false);
  add(sequence, 4, reversed.size(), "INDICES", nullptr, false);
  while (out.bin.size() % 4) out.bin += '\0';
  out.json = fmt::format(
      R"({{"asset":{{"version":"2.0"}},
      "extensionsUsed":["EXT_meshopt_compression","KHR_mesh_quantization"],
      "extensionsRequired":["EXT_meshopt_compression","KHR_mesh_quantization"],
      "buffers":[{{{}"byteLength":{}}},{{"byteLength":{},"extensions":{{"EXT_meshopt_compression":{{"fallback":true}}}}}}],
      "bufferViews":[{}],
      "accessors":[{{"bufferView":0,"componentType":5126,"count":{},"type":"VEC3","min":[0,0,0],"max":[1,1,0.3]}},
        {{"bufferView":1,"componentType":5120,"normalized":true,"count":{},"type":"VEC3"}},
        {{"bufferView":2,"componentType":5123,"count":{},"type":"SCALAR"}},
        {{"bufferView":3,"componentType":5125,"count":{},"type":"SCALAR"}}],
      "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"NORMAL":1}},"indices":2}},
                               {{"attributes":{{"POSITION":0,"NORMAL":1}},"indices":3}}]}}],
      "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}})",
      compressedUri.empty() ? "" : fmt::format(R"("uri":"{}",)", compressedUri), out.bin.size(),
      fallbackOffset, views, n, n, g.triangles.size(), reversed.size());
  return out;
}

// A triangle as its three corners (position, normal), rotated so the
// smallest position comes first: the loader may reorder triangles and
// rotate nothing else.
using Corner = std::array<float, 6>;
using Triangle = std::array<Corner, 3>;
std::vector<Triangle> trianglesOf(const std::vector<glm::vec3>& positions,
                                  const std::vector<glm::vec3>& normals,
                                  const std::vector<uint32_t>& indices) {
  std::vector<Triangle> out;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = positions.at(indices[t + k]), n = normals.at(indices[t + k]);
      tri[k] = {p.x, p.y, p.z, n.x, n.y, n.z};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Both primitives against the grid: positions exact (the vertex codec is
// lossless), normals within the 8-bit octahedral encoding's error (about
// 1/127 per component; 0.02 in length), the second primitive's triangles
// turned over.
void requireGrid(const scene::Scene& s, const Grid& g) {
  REQUIRE(s.meshes.size() == 2u);
  std::vector<uint32_t> reversed;
  for (size_t t = 0; t < g.triangles.size(); t += 3)
    reversed.insert(reversed.end(), {g.triangles[t + 2], g.triangles[t + 1], g.triangles[t]});
  for (size_t m = 0; m < 2; ++m) {
    INFO("primitive " << m);
    const auto& mesh = s.meshes[m];
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    // Match the loaded normals to the grid's by position, then compare.
    std::vector<glm::vec3> normals;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const auto at = std::find(g.positions.begin(), g.positions.end(), mesh.positions[v]);
      REQUIRE(at != g.positions.end());
      const glm::vec3 expected = g.normals[size_t(at - g.positions.begin())];
      CHECK(glm::length(mesh.normals[v] - expected) <= 0.02f);
      normals.push_back(expected);
    }
    CHECK(trianglesOf(mesh.positions, normals, mesh.indices) ==
          trianglesOf(g.positions, g.normals, m == 0 ? g.triangles : reversed));
  }
}

}  // namespace

TEST_CASE("glTF EXT_meshopt_compression: vertex and index streams decode to what was encoded",
          "[gltf]") {
  const Grid g;
  test::TempFolder folder("gltf-meshopt");
  // A .glb whose fallback buffer has no data, and a .gltf with the
  // compressed bytes in a file of their own.
  const CompressedGrid packed = compressedGrid(g, "");
  const auto glb = scene::importGltf(folder.write("grid.glb", test::glb(packed.json, packed.bin)));
  requireGrid(glb.scene, g);
  CHECK(glb.warnings.empty());
  const CompressedGrid separate = compressedGrid(g, "grid.bin");
  folder.write("grid.bin", separate.bin);
  requireGrid(scene::importGltf(folder.write("grid.gltf", separate.json)).scene, g);
}

TEST_CASE("glTF EXT_meshopt_compression: broken streams and limits are refused naming the view",
          "[gltf]") {
  const Grid g;
  test::TempFolder folder("gltf-meshopt-bad");
  const CompressedGrid packed = compressedGrid(g, "");
  // The compressed bytes cut short: the first view's stream no longer decodes.
  std::string cut = packed.bin;
  std::fill(cut.begin(), cut.begin() + 8, '\0');
  CHECK_THAT(test::gltfRefusal(folder.write("cut.glb", test::glb(packed.json, cut))),
             ContainsSubstring("buffer view 0: EXT_meshopt_compression data does not decode as "
                               "ATTRIBUTES of 9 x 12 bytes"));
  // 108 + 36 + 48 + 96 bytes decoded: a limit of 200 stops at the fourth view.
  scene::InputLimits limits;
  limits.maxDecodedBytes = 200;
  CHECK_THAT(
      test::gltfRefusal(folder.write("grid.glb", test::glb(packed.json, packed.bin)), limits),
      ContainsSubstring("buffer view 3: EXT_meshopt_compression decodes to 24 x 4 bytes") &&
          ContainsSubstring("InputLimits::maxDecodedBytes"));
}
