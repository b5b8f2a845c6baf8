// KHR_draco_mesh_compression: meshes that Draco's encoder compressed here
// (positions, normals, texture coordinates; lossless, without quantization),
// loaded and compared with the values that went in.
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gltf_test_files.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/input_limits.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;

namespace {

// Two triangles of a bent quad, each corner with its own normal and uv.
struct Soup {
  std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0.25f}, {1, 1, 0.5f},
                                      {0, 0, 0}, {1, 1, 0.5f},  {0, 1, 0.125f}};
  std::vector<glm::vec3> normals = {{0, 0, 1}, {0.6f, 0, 0.8f}, {0, 0.6f, 0.8f},
                                    {0, 0, 1}, {0, 0.6f, 0.8f}, {-0.6f, 0, 0.8f}};
  std::vector<glm::vec2> uvs = {{0, 0}, {0.75f, 0}, {0.75f, 0.5f}, {0, 0}, {0.75f, 0.5f}, {0, 1}};
};

// The soup as Draco's encoder writes it, with the unique ids of its
// position, normal and uv attributes (0, 1, 2).
std::string dracoSoup(const Soup& s) {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2);
  const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int nrm = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  for (int f = 0; f < 2; ++f) {
    const int c = 3 * f;
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &s.positions[c],
                                      &s.positions[c + 1], &s.positions[c + 2]);
    builder.SetAttributeValuesForFace(nrm, draco::FaceIndex(f), &s.normals[c], &s.normals[c + 1],
                                      &s.normals[c + 2]);
    builder.SetAttributeValuesForFace(uv, draco::FaceIndex(f), &s.uvs[c], &s.uvs[c + 1],
                                      &s.uvs[c + 2]);
  }
  const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  REQUIRE(mesh);
  REQUIRE(mesh->attribute(pos)->unique_id() == 0u);
  REQUIRE(mesh->attribute(nrm)->unique_id() == 1u);
  REQUIRE(mesh->attribute(uv)->unique_id() == 2u);
  draco::Encoder encoder;
  draco::EncoderBuffer out;
  REQUIRE(encoder.EncodeMeshToBuffer(*mesh, &out).ok());
  return std::string(out.data(), out.size());
}

// A .glb whose one primitive is `draco` (4 points after Draco merges the
// shared corners) and whose accessors have no buffer view, as exporters write them.
std::string dracoGlb(const std::string& draco, size_t points = 4, size_t indices = 6) {
  const std::string json = fmt::format(
      R"({{"asset":{{"version":"2.0"}},
      "extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"],
      "buffers":[{{"byteLength":{}}}],"bufferViews":[{{"buffer":0,"byteLength":{}}}],
      "accessors":[{{"componentType":5126,"count":{},"type":"VEC3","min":[0,0,0],"max":[1,1,0.5]}},
                   {{"componentType":5126,"count":{},"type":"VEC3"}},
                   {{"componentType":5126,"count":{},"type":"VEC2"}},
                   {{"componentType":5123,"count":{},"type":"SCALAR"}}],
      "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2}},"indices":3,
        "extensions":{{"KHR_draco_mesh_compression":{{"bufferView":0,
          "attributes":{{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2}}}}}}}}]}}],
      "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}})",
      draco.size(), draco.size(), points, points, points, indices);
  return test::glb(json, draco);
}

// Triangles as corners (position, normal, uv), each rotated to start at its
// smallest corner and the list sorted: the loader may reorder triangles.
using Corner = std::array<float, 8>;
std::vector<std::array<Corner, 3>> corners(const std::vector<glm::vec3>& p,
                                           const std::vector<glm::vec3>& n,
                                           const std::vector<glm::vec2>& uv,
                                           const std::vector<uint32_t>& indices) {
  std::vector<std::array<Corner, 3>> out;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::array<Corner, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = indices[t + k];
      tri[k] = {p.at(v).x, p.at(v).y, p.at(v).z,  n.at(v).x,
                n.at(v).y, n.at(v).z, uv.at(v).x, uv.at(v).y};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("glTF KHR_draco_mesh_compression: positions, normals, uvs and triangles as encoded",
          "[gltf]") {
  const Soup soup;
  test::TempFolder folder("gltf-draco");
  const auto r = scene::importGltf(folder.write("quad.glb", dracoGlb(dracoSoup(soup))));
  REQUIRE(r.scene.meshes.size() == 1u);
  const auto& mesh = r.scene.meshes[0];
  CHECK(mesh.positions.size() == 4u);
  REQUIRE(mesh.normals.size() == mesh.positions.size());
  REQUIRE(mesh.uv0.size() == mesh.positions.size());
  CHECK(corners(mesh.positions, mesh.normals, mesh.uv0, mesh.indices) ==
        corners(soup.positions, soup.normals, soup.uvs, {0, 1, 2, 3, 4, 5}));
  CHECK(r.warnings.empty());
}

TEST_CASE("glTF KHR_draco_mesh_compression: bad data and mismatched accessors are refused",
          "[gltf]") {
  const Soup soup;
  test::TempFolder folder("gltf-draco-bad");
  const std::string draco = dracoSoup(soup);
  std::string broken = draco;
  std::fill(broken.begin() + 8, broken.end(), '\x7f');
  CHECK_THAT(test::gltfRefusal(folder.write("broken.glb", dracoGlb(broken))),
             ContainsSubstring("mesh 0 primitive 0: KHR_draco_mesh_compression data does not "
                               "decode (Draco: "));
  CHECK_THAT(test::gltfRefusal(folder.write("count.glb", dracoGlb(draco, 5))),
             ContainsSubstring("mesh 0 primitive 0: NORMAL accessor has 5 elements, the Draco "
                               "mesh 4 points"));
  scene::InputLimits limits;
  limits.maxDecodedBytes = 60;  // normals 48 bytes, positions 48 more
  CHECK_THAT(test::gltfRefusal(folder.write("quad.glb", dracoGlb(draco)), limits),
             ContainsSubstring("KHR_draco_mesh_compression decodes to 48 bytes") &&
                 ContainsSubstring("InputLimits::maxDecodedBytes"));
}
