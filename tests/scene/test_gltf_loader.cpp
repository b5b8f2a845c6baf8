// The glTF loader against hand-made files (tests/data/gltf/make_gltf.py).
// Expected numbers are worked out by hand in the comments, from the values
// the generator writes and the glTF 2.0 specification.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gltf_test_files.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/util/error.h"
#include "test_data.h"

using namespace penumbra;
using Catch::Approx;
using Catch::Matchers::ContainsSubstring;

namespace {

std::string gltf(const std::string& name) {
  return test::dataPath("gltf/" + name);
}

glm::vec3 world(const scene::Scene& s, const scene::Instance& inst, uint32_t vertex) {
  return glm::vec3(inst.transform * glm::vec4(s.meshes[inst.mesh].positions.at(vertex), 1.0f));
}

void requireNear(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  INFO("got (" << a.x << ", " << a.y << ", " << a.z << "), expected (" << b.x << ", " << b.y << ", "
               << b.z << ")");
  REQUIRE(glm::length(a - b) <= eps);
}

// The dielectric F0 that a material's parameters stand for (docs/materials.md,
// untinted): specular x min(0.08 x specularColor, 1) per channel.
glm::vec3 dielectricF0(const scene::Material& m) {
  return m.specular * glm::min(0.08f * m.specularColor, glm::vec3(1.0f));
}

const scene::Material& materialNamed(const scene::Scene& s, const std::string& name) {
  for (const auto& m : s.materials)
    if (m.name == name) return m;
  FAIL("no material " << name);
  throw 0;
}

bool hasWarning(const scene::GltfImport& r, const std::string& part) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

}  // namespace

TEST_CASE("glTF node transforms compose into world positions", "[gltf]") {
  const auto s = scene::loadGltf(gltf("transforms.gltf"));
  // Nodes 'child' (under 'parent'), 'matrix' and 'trs' use mesh 'tri'; 'pair'
  // uses the two-primitive mesh: 3 + 2 instances of 1 + 2 meshes.
  REQUIRE(s.meshes.size() == 3u);
  REQUIRE(s.instances.size() == 5u);

  // Scene roots are visited in order, children after their parent: the first
  // instance is 'child'. parent = T(10,0,0) Rz(90) S(2); child = T(0,0,1).
  // (1,0,0) -> child (1,0,1) -> S (2,0,2) -> Rz (0,2,2) -> T (10,2,2)
  // (0,1,0) -> (0,1,1) -> (0,2,2) -> (-2,0,2) -> (8,0,2)
  // (0,0,0) -> (0,0,1) -> (0,0,2) -> (0,0,2) -> (10,0,2)
  const auto& child = s.instances[0];
  requireNear(world(s, child, 0), {10, 0, 2});
  requireNear(world(s, child, 1), {10, 2, 2});
  requireNear(world(s, child, 2), {8, 0, 2});

  // 'matrix' holds the parent's transform as a column-major matrix, 'trs' as
  // TRS: both map (1,0,0) -> (10,2,0) and (0,1,0) -> (8,0,0).
  const auto& matrix = s.instances[1];
  const auto& trs = s.instances[2];
  for (const auto* inst : {&matrix, &trs}) {
    requireNear(world(s, *inst, 0), {10, 0, 0});
    requireNear(world(s, *inst, 1), {10, 2, 0});
    requireNear(world(s, *inst, 2), {8, 0, 0});
  }
}

TEST_CASE("glTF meshes are stored once and instanced per node and primitive", "[gltf]") {
  const auto s = scene::loadGltf(gltf("transforms.gltf"));
  // 'child', 'matrix' and 'trs' share one scene mesh (one BLAS).
  REQUIRE(s.instances[0].mesh == s.instances[1].mesh);
  REQUIRE(s.instances[1].mesh == s.instances[2].mesh);
  // 'pair' has two primitives: two meshes, each instanced at T(0,5,0).
  REQUIRE(s.instances[3].mesh != s.instances[4].mesh);
  REQUIRE(s.instances[3].mesh != s.instances[0].mesh);
  for (int i : {3, 4}) requireNear(world(s, s.instances[size_t(i)], 1), {1, 5, 0});
  // The NORMAL attribute is kept as given, in object space.
  for (const auto& n : s.meshes[s.instances[0].mesh].normals) requireNear(n, {0, 0, 1});
}

TEST_CASE("glTF sparse accessors substitute their values", "[gltf]") {
  const auto s = scene::loadGltf(gltf("sparse.gltf"));
  REQUIRE(s.meshes.size() == 1u);
  const auto& m = s.meshes[0];
  // Base (0,0,0) (1,0,0) (1,1,0) (0,1,0); vertices 1 and 3 replaced by (2,0,0), (0,3,0).
  // No NORMAL, so the quad is unwelded into 6 flat-shaded vertices in index
  // order 0 1 2 0 2 3.
  REQUIRE(m.positions.size() == 6u);
  requireNear(m.positions[0], {0, 0, 0});
  requireNear(m.positions[1], {2, 0, 0});
  requireNear(m.positions[2], {1, 1, 0});
  requireNear(m.positions[5], {0, 3, 0});
  // TEXCOORD_0 has no buffer view (zeros) and one sparse value, (0.25, 0.75) at vertex 2.
  REQUIRE(m.uv0.size() == 6u);
  REQUIRE(m.uv0[0] == glm::vec2(0.0f));
  REQUIRE(m.uv0[1] == glm::vec2(0.0f));
  REQUIRE(m.uv0[2] == glm::vec2(0.25f, 0.75f));
  REQUIRE(m.uv0[4] == glm::vec2(0.25f, 0.75f));
  REQUIRE(m.uv0[5] == glm::vec2(0.0f));
}

TEST_CASE("glTF COLOR_0: RGB or RGBA, normalized integers or floats, clamped to [0, 1]", "[gltf]") {
  const auto s = scene::loadGltf(gltf("vertex_colors.gltf"));
  REQUIRE(s.meshes.size() == 2u);
  // Normalized unsigned bytes, RGB: alpha 1; 51 / 255 = 0.2. The positions
  // are the unit triangle's, in order, so colour i is vertex i's.
  const auto& bytes = s.meshes[0];
  REQUIRE(bytes.colors.size() == bytes.positions.size());
  for (size_t v = 0; v < bytes.positions.size(); ++v) {
    const glm::vec3 p = bytes.positions[v];
    const glm::vec4 expected = p == glm::vec3(1, 0, 0)   ? glm::vec4(0, 1, 0, 1)
                               : p == glm::vec3(0, 1, 0) ? glm::vec4(0, 0, 0.2f, 1)
                                                         : glm::vec4(1, 0, 0, 1);
    CHECK(glm::length(bytes.colors[v] - expected) < 1e-6f);
  }
  // Floats, RGBA; 1.5 clamped to 1.
  const auto& floats = s.meshes[1];
  REQUIRE(floats.colors.size() == floats.positions.size());
  for (size_t v = 0; v < floats.positions.size(); ++v) {
    const float red = floats.positions[v] == glm::vec3(0, 0, 0) ? 1.0f : 0.25f;
    CHECK(floats.colors[v] == glm::vec4(red, 0.5f, 0.75f, 0.5f));
  }
  // A mesh's colours must be in range when they come from elsewhere.
  scene::Scene bad = s;
  bad.meshes[0].colors[0].g = 1.5f;
  REQUIRE_THROWS_WITH(scene::validate(bad), ContainsSubstring("vertex colour component 1.5"));
}

TEST_CASE("glTF EXT_mesh_gpu_instancing: one instance per copy, placed in the node's space",
          "[gltf]") {
  const auto r = scene::importGltf(gltf("gpu_instancing.gltf"));
  CHECK(r.warnings.empty());
  const auto& s = r.scene;
  REQUIRE(s.meshes.size() == 1u);
  REQUIRE(s.instances.size() == 3u);
  // The triangle's vertex (1, 0, 0) (vertex 1 of the file; the loader keeps
  // the vertex order) through node (10, 0, 0) x copy T R S, worked by hand:
  // as is; turned 90 degrees about +z to (0, 1, 0), moved by (2, 0, 0);
  // scaled to (2, 0, 0), moved by (0, 3, 0).
  requireNear(world(s, s.instances[0], 1), {11, 0, 0});
  requireNear(world(s, s.instances[1], 1), {12, 1, 0});
  requireNear(world(s, s.instances[2], 1), {12, 3, 0});
  REQUIRE_THROWS_WITH(scene::importGltf(gltf("invalid_instancing_counts.gltf")),
                      ContainsSubstring("EXT_mesh_gpu_instancing SCALE: 2 instances where the "
                                        "other attributes have 3"));
}

TEST_CASE("glTF normalized integer attributes and byte strides", "[gltf]") {
  const auto s = scene::loadGltf(gltf("attributes.gltf"));
  REQUIRE(s.meshes.size() == 2u);
  const auto& a = s.meshes[0];
  // Interleaved position/normal at stride 24.
  requireNear(a.positions[1], {1, 0, 0});
  requireNear(a.positions[2], {0, 1, 0});
  for (const auto& n : a.normals) requireNear(n, {0, 0, 1});
  // Unsigned bytes / 255 at stride 4: (0,255) (255,0) (128,51).
  REQUIRE(a.uv0[0].x == 0.0f);
  REQUIRE(a.uv0[0].y == 1.0f);
  REQUIRE(a.uv0[1].x == 1.0f);
  REQUIRE(a.uv0[2].x == Approx(128.0 / 255.0).epsilon(1e-6));
  REQUIRE(a.uv0[2].y == Approx(0.2).epsilon(1e-6));

  const auto& b = s.meshes[1];
  // Unsigned shorts / 65535: 32768 -> 0.500007..., 13107 -> 0.2.
  REQUIRE(b.uv0[0] == glm::vec2(0.0f, 1.0f));
  REQUIRE(b.uv0[1].x == Approx(32768.0 / 65535.0).epsilon(1e-6));
  REQUIRE(b.uv0[2].y == Approx(0.2).epsilon(1e-6));
  // Signed bytes: max(c / 127, -1), so both 127 and -128 are unit: (0,0,1) (0,0,1) (-1,0,0).
  requireNear(b.normals[0], {0, 0, 1});
  requireNear(b.normals[1], {0, 0, 1});
  requireNear(b.normals[2], {-1, 0, 0});
  // Signed shorts: max(c / 32767, -1): (1,0,0,-1) (1,0,0,-1 from -32768) ... w keeps its sign.
  requireNear(glm::vec3(b.tangents[0]), {1, 0, 0});
  REQUIRE(b.tangents[0].w == -1.0f);
  requireNear(glm::vec3(b.tangents[1]), {0, 1, 0});
  REQUIRE(b.tangents[1].w == -1.0f);
  requireNear(glm::vec3(b.tangents[2]), {0, 0, -1});
  REQUIRE(b.tangents[2].w == -1.0f);
}

TEST_CASE("glTF KHR_mesh_quantization: integer positions scaled by their node and byte normals",
          "[gltf]") {
  // Required by the file, so refusing it would fail the load.
  const auto r = scene::importGltf(gltf("mesh_quantization.gltf"));
  REQUIRE_FALSE(hasWarning(r, "KHR_mesh_quantization"));
  const auto& s = r.scene;
  REQUIRE(s.meshes.size() == 1u);
  REQUIRE(s.instances.size() == 1u);
  const auto& m = s.meshes[0];
  // Shorts 0 or 1000 as they are (not normalized), then the node: x 0.001, + (0, 0, 5).
  requireNear(m.positions[3], {1000, 1000, 0});
  requireNear(world(s, s.instances[0], 0), {0, 0, 5});
  requireNear(world(s, s.instances[0], 1), {1, 0, 5});
  requireNear(world(s, s.instances[0], 3), {1, 1, 5});
  REQUIRE(m.indices.size() == 6u);
  // Normalized signed bytes: 127 / 127 = 1, max(-128 / 127, -1) = -1.
  for (const auto& n : m.normals) requireNear(n, {0, 0, 1});
  for (const auto& t : m.tangents) {
    requireNear(glm::vec3(t), {1, 0, 0});
    REQUIRE(t.w == -1.0f);
  }
  // Unsigned bytes, not normalized: the integers 0 and 1.
  REQUIRE(m.uv0.size() == 4u);
  REQUIRE(m.uv0[0] == glm::vec2(0, 0));
  REQUIRE(m.uv0[1] == glm::vec2(1, 0));
  REQUIRE(m.uv0[2] == glm::vec2(0, 1));
  REQUIRE(m.uv0[3] == glm::vec2(1, 1));
}

TEST_CASE("glTF primitives without normals are flat-shaded", "[gltf]") {
  const auto s = scene::loadGltf(gltf("generated.gltf"));
  const auto& fold = s.meshes[0];
  // Two triangles sharing an edge become 6 vertices.
  REQUIRE(fold.positions.size() == 6u);
  REQUIRE(fold.normals.size() == 6u);
  // Triangle (0,0,0) (1,0,0) (0,1,0): +z.
  for (int i = 0; i < 3; ++i) requireNear(fold.normals[size_t(i)], {0, 0, 1});
  // Triangle (1,0,0) (1,1,1) (0,1,0): (0,1,1) x (-1,1,0) = (-1,-1,1), over sqrt 3.
  const float k = 1.0f / std::sqrt(3.0f);
  for (int i = 3; i < 6; ++i) requireNear(fold.normals[size_t(i)], {-k, -k, k});
  // UVs follow their vertices: vertex 3 of the file (uv (0,0)) is the second
  // triangle's second corner.
  REQUIRE(fold.uv0[4] == glm::vec2(0.0f, 0.0f));
}

TEST_CASE("glTF tangents are generated from UVs", "[gltf]") {
  const auto s = scene::loadGltf(gltf("generated.gltf"));
  REQUIRE(s.meshes.size() == 4u);
  // Quad in the xy plane, normal +z, u along +x and v down (along -y): the
  // tangent is +x and cross(n, t) = +y points to decreasing v: w = +1.
  for (const auto& t : s.meshes[1].tangents) {
    requireNear(glm::vec3(t), {1, 0, 0});
    REQUIRE(t.w == 1.0f);
  }
  // u mirrored (along -x): tangent -x, cross(n, t) = -y but the image's up is
  // still +y: left-handed, w = -1.
  for (const auto& t : s.meshes[2].tangents) {
    requireNear(glm::vec3(t), {-1, 0, 0});
    REQUIRE(t.w == -1.0f);
  }
  // Normals tilted to n = (0.6, 0, 0.8): Gram-Schmidt of +x gives
  // (1,0,0) - 0.6 n = (0.64, 0, -0.48) -> (0.8, 0, -0.6), orthogonal to n;
  // cross(n, t) = (0, 1, 0): w = +1.
  const auto& tilted = s.meshes[3];
  for (size_t i = 0; i < tilted.tangents.size(); ++i) {
    requireNear(glm::vec3(tilted.tangents[i]), {0.8f, 0, -0.6f});
    REQUIRE(std::abs(glm::dot(glm::vec3(tilted.tangents[i]), tilted.normals[i])) < 1e-6f);
    REQUIRE(tilted.tangents[i].w == 1.0f);
  }
  // The flat-shaded fold has UVs too: its generated tangents are unit and
  // orthogonal to the face normals.
  for (size_t i = 0; i < s.meshes[0].tangents.size(); ++i) {
    const glm::vec3 t(s.meshes[0].tangents[i]);
    REQUIRE(glm::length(t) == Approx(1.0f));
    REQUIRE(std::abs(glm::dot(t, s.meshes[0].normals[i])) < 1e-6f);
  }
}

TEST_CASE("glTF strips and fans become triangle lists; points and lines are skipped", "[gltf]") {
  const auto r = scene::importGltf(gltf("modes.gltf"));
  // Strip corners v0 (0,0,0), v1 (1,0,0), v2 (0,1,0), v3 (1,1,0); flat
  // normals unweld the corners in triangle order.
  REQUIRE(r.scene.meshes.size() == 2u);
  REQUIRE(hasWarning(r, "primitive 0: mode 0 is not made of triangles"));
  REQUIRE(hasWarning(r, "primitive 1: mode 1 is not made of triangles"));
  // Strip: (v0 v1 v2), then (v1 v3 v2): every other triangle reversed, so
  // both keep the first one's counter-clockwise winding (+z).
  const auto& strip = r.scene.meshes[0];
  REQUIRE(strip.triangleCount() == 2u);
  requireNear(strip.positions[3], {1, 0, 0});
  requireNear(strip.positions[4], {1, 1, 0});
  requireNear(strip.positions[5], {0, 1, 0});
  // Fan corners v0 (0,0,0), v1 (1,0,0), v2 (1,1,0), v3 (0,1,0):
  // triangles (v1 v2 v0), (v2 v3 v0).
  const auto& fan = r.scene.meshes[1];
  REQUIRE(fan.triangleCount() == 2u);
  requireNear(fan.positions[0], {1, 0, 0});
  requireNear(fan.positions[2], {0, 0, 0});
  requireNear(fan.positions[3], {1, 1, 0});
  requireNear(fan.positions[4], {0, 1, 0});
  for (const auto* m : {&strip, &fan})
    for (const auto& n : m->normals) requireNear(n, {0, 0, 1});
}

TEST_CASE("glTF .glb, external and embedded buffers load the same triangle", "[gltf]") {
  for (const char* name : {"triangle.glb", "external.gltf", "embedded.gltf"}) {
    INFO(name);
    const auto s = scene::loadGltf(gltf(name));
    REQUIRE(s.meshes.size() == 1u);
    REQUIRE(s.instances.size() == 1u);
    const auto& m = s.meshes[0];
    REQUIRE(m.triangleCount() == 1u);
    // Flat normal of (0,0,0) (1,0,0) (0,1,0) is +z.
    requireNear(world(s, s.instances[0], 1), {1, 0, 0});
    requireNear(world(s, s.instances[0], 2), {0, 1, 0});
    requireNear(m.normals[0], {0, 0, 1});
  }
}

TEST_CASE("glTF materials map onto the Lambert-diffuse Disney parameters", "[gltf]") {
  const auto r = scene::importGltf(gltf("materials.gltf"));
  const auto& s = r.scene;
  for (const auto& m : s.materials) REQUIRE(m.model == scene::MaterialModel::Lambert);

  const auto& base = materialNamed(s, "base");
  REQUIRE(base.baseColor == glm::vec3(0.5f, 0.25f, 1.0f));
  REQUIRE(base.metallic == Approx(0.3f));
  REQUIRE(base.roughness == Approx(0.7f));
  // ior 1.5: F0 = (0.5 / 2.5)^2 = 0.04.
  for (int c = 0; c < 3; ++c) REQUIRE(dielectricF0(base)[c] == Approx(0.04f));
  // A grey F0 up to 0.08 is `specular` alone: no coloured-F0 code for it.
  REQUIRE(base.specularColor == glm::vec3(1.0f));
  REQUIRE(base.specTrans == 0.0f);

  // emissiveFactor (1, 0.5, 0.25) x emissiveStrength 4.
  REQUIRE(materialNamed(s, "emissive").emission == glm::vec3(4.0f, 2.0f, 1.0f));

  // transmission 0.9, ior 1.33: F0 = (0.33 / 2.33)^2 = 0.0200593; no volume: thin-walled.
  const auto& glass = materialNamed(s, "glass");
  REQUIRE(glass.specTrans == Approx(0.9f));
  REQUIRE(glass.ior == Approx(1.33f));
  REQUIRE(dielectricF0(glass).x == Approx(0.0200593).epsilon(1e-4));
  REQUIRE(glass.thin);

  // A volume with thickness > 0 refracts (not thin) and absorbs as its
  // attenuation says (simulated: no warning).
  const auto& volume = materialNamed(s, "volume");
  REQUIRE(volume.specTrans == 1.0f);
  REQUIRE_FALSE(volume.thin);
  REQUIRE(volume.attenuationDistance == 2.0f);
  REQUIRE(volume.attenuationColor == glm::vec3(1.0f, 0.5f, 0.5f));
  // KHR_materials_dispersion's 20 / Abbe number, as stored.
  REQUIRE(volume.dispersion == 0.4f);
  REQUIRE_FALSE(hasWarning(r, "'volume': dispersion"));
  // Dispersion on thin glass is kept (a viewer may make it solid) but warned
  // about, in one line: thin glass does not bend light.
  const auto thin = scene::importGltf(gltf("dispersion_thin.gltf"));
  REQUIRE(thin.scene.materials.at(0).dispersion == 0.5f);
  REQUIRE(thin.warnings.size() == 1u);
  REQUIRE(hasWarning(thin, "'thin glass': dispersion needs transmission through a volume"));
  REQUIRE_FALSE(hasWarning(r, "volume attenuation"));
  REQUIRE(std::isinf(glass.attenuationDistance));  // no volume: a clear medium

  // clearcoat 0.8 and roughness 0.2: the Lambert model's coat is the
  // extension's, with clearcoatGloss = 1 - roughness.
  const auto& coat = materialNamed(s, "coat");
  REQUIRE(coat.model == scene::MaterialModel::Lambert);
  REQUIRE(coat.clearcoat == Approx(0.8f));
  REQUIRE(coat.clearcoatGloss == Approx(0.8f));

  // KHR_materials_specular: F0 = min(F0(ior) x specularColorFactor, 1) x specularFactor,
  // per channel; ior 2: F0(ior) = 1/9, colour (10, 1, 0.2), factor 0.5.
  const glm::vec3 specularF0 = dielectricF0(materialNamed(s, "specular"));
  CHECK(specularF0.x == Approx(0.5f));  // 10/9 clamped to 1
  CHECK(specularF0.y == Approx(0.5f / 9.0f));
  CHECK(specularF0.z == Approx(0.1f / 9.0f));
  // ... and F90 = specularFactor; 1 without the extension.
  CHECK(materialNamed(s, "specular").specularF90 == 0.5f);
  CHECK(materialNamed(s, "coat").specularF90 == 1.0f);

  // Sheen strength is the colour's largest channel, untinted.
  const auto& sheen = materialNamed(s, "sheen");
  // sheenColorFactor (0.2, 0.6, 0.4): its largest channel is the strength,
  // the colour over it the hue, so that sheen x sheenColor is the factor.
  REQUIRE(sheen.sheen == Approx(0.6f));
  REQUIRE(sheen.sheenTint == 0.0f);
  for (int c = 0; c < 3; ++c)
    REQUIRE(sheen.sheen * sheen.sheenColor[c] == Approx(glm::vec3(0.2f, 0.6f, 0.4f)[c]));
  // sheenRoughnessFactor 0.5, for the Lambert model's Charlie sheen.
  REQUIRE(sheen.sheenRoughness == 0.5f);
  REQUIRE(sheen.model == scene::MaterialModel::Lambert);

  // Unset factors take glTF's defaults: white, metallic 1, roughness 1.
  const auto& defaults = materialNamed(s, "defaults");
  REQUIRE(defaults.baseColor == glm::vec3(1.0f));
  REQUIRE(defaults.metallic == 1.0f);
  REQUIRE(defaults.roughness == 1.0f);
  REQUIRE(defaults.emission == glm::vec3(0.0f));

  // 10 primitives: 'mask' (alpha 0.2 < cutoff 0.5) is cut away; the one
  // without a material gets glTF's default material.
  REQUIRE(s.meshes.size() == 9u);
  const auto& last = s.materials[s.meshes.back().material];
  REQUIRE(last.baseColor == glm::vec3(1.0f));
  REQUIRE(last.metallic == 1.0f);
  for (const auto& mesh : s.meshes) REQUIRE(s.materials[mesh.material].name != "mask");
}

TEST_CASE("glTF emissive primitives are emitters", "[gltf]") {
  const auto s = scene::loadGltf(gltf("emissive_quad.gltf"));
  size_t emissive = 0;
  for (const auto& m : s.meshes)
    if (s.materials[m.material].isEmissive()) {
      ++emissive;
      REQUIRE(s.materials[m.material].emission == glm::vec3(10.0f));
    }
  REQUIRE(emissive == 1u);
}

TEST_CASE("glTF cameras: the first in node order is the view, others by name", "[gltf]") {
  const auto r = scene::importGltf(gltf("cameras.gltf"));
  auto s = r.scene;
  // Node 1 'front' (camera 'second') precedes node 2 'side' although the
  // scene lists node 2 first; node 3's orthographic camera comes last.
  REQUIRE(s.cameras.size() == 3u);
  REQUIRE(r.warnings.empty());
  REQUIRE_FALSE(s.camera.orthographic());
  requireNear(s.camera.position, {0, 0, 5});
  requireNear(s.camera.forward, {0, 0, -1});
  requireNear(s.camera.up, {0, 1, 0});
  // yfov 0.8 rad in degrees.
  REQUIRE(s.camera.verticalFovDegrees == Approx(0.8 * 180.0 / 3.14159265358979));

  // By node name: 'side' at (5,0,0) turned 90 degrees about +y: -z -> -x.
  scene::selectCamera(s, "side");
  requireNear(s.camera.position, {5, 0, 0});
  requireNear(s.camera.forward, {-1, 0, 0});
  REQUIRE(s.camera.verticalFovDegrees == Approx(0.5 * 180.0 / 3.14159265358979));
  // By camera name.
  scene::selectCamera(s, "second");
  requireNear(s.camera.position, {0, 0, 5});
  REQUIRE_THROWS_WITH(
      scene::selectCamera(s, "nope"),
      ContainsSubstring("no camera named 'nope'") &&
          ContainsSubstring("0 'second' (node 'front'), 1 'first' (node 'side'), 2 'ortho'"));

  // 'ortho': xmag 1.5 and ymag 1 are half its width and height; 2 m above the
  // origin, turned -90 degrees about +x: it looks down (-z -> -y), its up is -z.
  scene::selectCamera(s, "ortho");
  REQUIRE(s.camera.orthographic());
  REQUIRE(s.camera.orthographicHeight == Approx(2.0));
  REQUIRE(s.camera.aspectRatio == Approx(1.5));
  requireNear(s.camera.position, {0, 2, 0});
  requireNear(s.camera.forward, {0, -1, 0});
  requireNear(s.camera.up, {0, 0, -1});
  // By index in node order, which unnamed cameras need.
  scene::selectCamera(s, "1");
  requireNear(s.camera.position, {5, 0, 0});
  scene::selectCamera(s, "0");
  requireNear(s.camera.position, {0, 0, 5});
  REQUIRE_THROWS_WITH(scene::selectCamera(s, "3"), ContainsSubstring("no camera named '3'"));
  s.cameras[1].name.clear();
  s.cameras[1].nodeName.clear();
  REQUIRE_THROWS_WITH(scene::selectCamera(s, "x"), ContainsSubstring("1 (unnamed)"));
}

TEST_CASE("glTF without cameras frames the scene", "[gltf]") {
  const auto s = scene::loadGltf(gltf("embedded.gltf"));
  REQUIRE(s.cameras.empty());
  // Bounds (0,0,0)..(1,1,0): the framing camera (test_camera_placement.cpp)
  // looks at their centre from the front (+z), right and above.
  const glm::dvec3 toCentre = glm::dvec3(0.5, 0.5, 0.0) - s.camera.position;
  requireNear(glm::vec3(glm::normalize(toCentre)), s.camera.forward);
  REQUIRE(s.camera.position.x > 0.5);
  REQUIRE(s.camera.position.y > 0.5);
  REQUIRE(s.camera.position.z > 0.0);
}

TEST_CASE("glTF extensions: required unsupported fails, optional warns", "[gltf]") {
  REQUIRE_THROWS_WITH(scene::importGltf(gltf("extension_required.gltf")),
                      ContainsSubstring("extension_required.gltf") &&
                          ContainsSubstring("requires extension KHR_texture_basisu"));
  // Refused before anything is read, in the same line, where the texture
  // would otherwise fail on what it lacks (a PNG or JPEG source).
  REQUIRE_THROWS_WITH(scene::importGltf(gltf("extension_required_compressed.gltf")),
                      ContainsSubstring("requires extension KHR_texture_basisu, which is "
                                        "not supported (supported: "));
  const auto r = scene::importGltf(gltf("extension_optional.gltf"));
  REQUIRE(r.warnings.size() == 1u);
  REQUIRE_THAT(r.warnings[0], ContainsSubstring("KHR_materials_pbrSpecularGlossiness") &&
                                  ContainsSubstring("extension_optional.gltf"));
  REQUIRE(r.warnings[0].find('\n') == std::string::npos);
  // Supported extensions in extensionsUsed are silent.
  REQUIRE_FALSE(hasWarning(scene::importGltf(gltf("materials.gltf")), "KHR_materials_sheen"));
}

TEST_CASE("bad glTF input gives one clear error naming the file and the part", "[gltf]") {
  struct Case {
    const char* file;
    const char* part;
  };
  const Case cases[] = {
      {"invalid_truncated.gltf", "parse error at line"},
      {"invalid_accessor_range.gltf", "accessor 0"},
      {"invalid_short_buffer.gltf", "buffer view 1"},
      {"invalid_missing_buffer.gltf", "missing.bin"},
      {"invalid_missing_image.gltf", "missing.png"},
      {"invalid_index.gltf", "index 7"},
      {"invalid_cycle.gltf", "cyclic"},
      {"invalid_nan.gltf", "not a finite number"},
      {"invalid_accessor_index.gltf", "accessor 9"},
      {"invalid_orthographic_height.gltf", "ymag 1e-40"},
      {"invalid_specular_color.gltf", "specularColorFactor must be finite and non-negative"},
      {"no_such_file.gltf", "no such file"},
  };
  for (const auto& c : cases) {
    INFO(c.file);
    try {
      scene::importGltf(gltf(c.file));
      FAIL("no error");
    } catch (const Error& e) {
      const std::string message = e.what();
      INFO(message);
      REQUIRE(message.find(c.file) != std::string::npos);
      REQUIRE(message.find(c.part) != std::string::npos);
      REQUIRE(message.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("glTF: zero-area triangles are dropped at load with a warning", "[gltf]") {
  // degenerate.gltf (make_gltf.py): (0,1,2) and (1,4,2) have area 1/2; (0,0,1)
  // repeats a corner and (0,1,3) has collinear corners (0,0,0) (1,0,0) (2,0,0).
  const auto r = scene::importGltf(gltf("degenerate.gltf"));
  REQUIRE(r.scene.meshes.size() == 1u);
  const auto& mesh = r.scene.meshes[0];
  REQUIRE(mesh.indices.size() == 6u);
  const std::vector<glm::vec3> expected = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                           {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (size_t i = 0; i < 6; ++i) CHECK(mesh.positions[mesh.indices[i]] == expected[i]);
  CHECK(hasWarning(r, "2 degenerate (zero-area) triangles dropped"));
  // The same primitive three times: one line for the file, with the sum.
  const auto many = scene::importGltf(gltf("degenerate_primitives.gltf"));
  size_t lines = 0;
  for (const auto& w : many.warnings) lines += w.find("degenerate") != std::string::npos;
  CHECK(lines == 1u);
  CHECK(hasWarning(many,
                   "6 degenerate (zero-area) triangles dropped from 3 primitives (the first: "
                   "glTF '"));
  CHECK(hasWarning(many, "'some degenerate' primitive 0)"));
}

TEST_CASE(
    "glTF: node transforms compose in double, so a root far from the origin keeps its centimetres",
    "[gltf][precision]") {
  // A float cannot hold 1000000.03 (its spacing there is 0.0625).
  const auto s = scene::loadGltf(gltf("far_translation.gltf"));
  REQUIRE(s.instances.size() == 1u);
  CHECK(s.instances[0].transform[3] == glm::dvec4(1000000.03, -200000.01, 0.07, 1.0));
}

TEST_CASE("glTF URIs stay inside the file's folder unless the user allows others", "[gltf]") {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / fmt::format("penumbra-uri-{}", ::getpid());
  fs::remove_all(root);
  fs::create_directories(root / "scene" / "data");
  fs::copy_file(gltf("external.bin"), root / "external.bin");
  fs::copy_file(gltf("external.bin"), root / "scene" / "data" / "external.bin");
  fs::create_symlink(root / "external.bin", root / "scene" / "link.bin");
  std::ifstream in(gltf("external.gltf"));
  std::stringstream read;
  read << in.rdbuf();
  const std::string text = read.str();
  // The same file with its buffer's URI replaced.
  auto withUri = [&](const std::string& name, const std::string& uri) {
    std::string t = text;
    const std::string from = "\"uri\": \"external.bin\"";
    REQUIRE(t.find(from) != std::string::npos);
    t.replace(t.find(from), from.size(), "\"uri\": \"" + uri + "\"");
    const fs::path path = root / "scene" / name;
    std::ofstream(path) << t;
    return path.string();
  };
  const std::string below = withUri("below.gltf", "data/external.bin");
  const std::string parent = withUri("parent.gltf", "../external.bin");
  const std::string absolute = withUri("absolute.gltf", (root / "external.bin").string());
  const std::string linked = withUri("linked.gltf", "link.bin");
  const std::string folder = withUri("folder.gltf", "data");

  // A subfolder is the file's own.
  REQUIRE(scene::loadGltf(below).meshes.at(0).triangleCount() == 1u);
  // "..", an absolute path and a link that leads out are refused, naming the
  // URI and the way to allow it; allowed, they load the same triangle.
  for (const std::string& path : {parent, absolute, linked}) {
    INFO(path);
    REQUIRE_THROWS_WITH(scene::loadGltf(path),
                        ContainsSubstring("outside the glTF file's folder") &&
                            ContainsSubstring("--allow-external-files"));
    scene::FileAccess allow;
    allow.allowOutsideFolder = true;
    REQUIRE(scene::loadGltf(path, allow).meshes.at(0).triangleCount() == 1u);
  }
  // A URI naming a folder is no file to read.
  REQUIRE_THROWS_WITH(scene::loadGltf(folder), ContainsSubstring("'" + (root / "scene").string() +
                                                                 "/data' is not a readable file"));
  fs::remove_all(root);
}

// Bounded inputs (scene/input_limits.h, docs/security.md): a file past a
// limit is one error line naming the file, the part and the limit, found
// before the allocation or the recursion it would have caused
// (test::gltfRefusal checks that).

TEST_CASE("glTF JSON nested past the depth limit is refused before tinygltf parses it", "[gltf]") {
  test::TempFolder folder("gltf-depth");
  // 20,000 levels in "extras": tinygltf converted them recursively and
  // overflowed the stack. In a .gltf and in a .glb's JSON chunk.
  const std::string deep = R"({"asset":{"version":"2.0"},"extras":)" + std::string(20000, '[') +
                           std::string(20000, ']') + "}";
  for (const std::string& path :
       {folder.write("deep.gltf", deep), folder.write("deep.glb", test::glb(deep))}) {
    INFO(path);
    CHECK_THAT(test::gltfRefusal(path),
               ContainsSubstring("JSON nests arrays and objects deeper than the "
                                 "limit 256") &&
                   ContainsSubstring("InputLimits::maxJsonDepth"));
  }
  // transforms.gltf nests 6 levels: a limit of 6 loads it, 5 does not.
  scene::InputLimits limits;
  limits.maxJsonDepth = 6;
  REQUIRE(scene::importGltf(gltf("transforms.gltf"), {}, limits).scene.instances.size() == 5u);
  limits.maxJsonDepth = 5;
  CHECK_THAT(test::gltfRefusal(gltf("transforms.gltf"), limits), ContainsSubstring("the limit 5"));
}

TEST_CASE("glTF accessors without a buffer view are bounded before they are zero-filled",
          "[gltf]") {
  test::TempFolder folder("gltf-zeros");
  // 2^24 and 2^28 zero positions from a file of about 230 bytes.
  for (uint64_t count : {uint64_t(1) << 24, uint64_t(1) << 28}) {
    const std::string path = folder.write(
        "zeros.gltf",
        fmt::format(R"({{"asset":{{"version":"2.0"}},"accessors":[{{"componentType":5126,
          "count":{},"type":"VEC3"}}],"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
          "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}})",
                    count));
    INFO(count);
    CHECK_THAT(test::gltfRefusal(path),
               ContainsSubstring("mesh 0 primitive 0 POSITION (accessor 0) element count "
                                 "without a buffer view " +
                                 std::to_string(count) + " exceeds the limit 1048576") &&
                   ContainsSubstring("InputLimits::maxZeroFilledElements"));
  }
  // sparse.gltf's TEXCOORD_0 is 4 zeros with one sparse value: loads at a
  // limit of 4, not at 3.
  scene::InputLimits limits;
  limits.maxZeroFilledElements = 4;
  REQUIRE(scene::importGltf(gltf("sparse.gltf"), {}, limits).scene.meshes.size() == 1u);
  limits.maxZeroFilledElements = 3;
  CHECK_THAT(test::gltfRefusal(gltf("sparse.gltf"), limits),
             ContainsSubstring("TEXCOORD_0 (accessor 1) element count without a buffer view 4 "
                               "exceeds the limit 3"));
}

TEST_CASE("glTF accessor counts, decoded bytes, triangles, instances and node visits are bounded",
          "[gltf]") {
  // Each limit set to exactly what a small file needs (it loads), then one less.
  struct Case {
    const char* file;
    uint64_t scene::InputLimits::*limit;
    uint64_t needed;
    const char* message;
  };
  const Case cases[] = {
      // sparse.gltf: its largest accessor is the 6 indices; it decodes 4 x 3
      // + 4 x 2 floats and 6 indices (104 bytes) into 2 triangles.
      {"sparse.gltf", &scene::InputLimits::maxAccessorElements, 6,
       "indices (accessor 2) element count 6 exceeds the limit 5 "
       "(InputLimits::maxAccessorElements"},
      {"sparse.gltf", &scene::InputLimits::maxDecodedBytes, 104,
       "the file's decoded accessor bytes 104 exceeds the limit 103 (InputLimits::maxDecodedBytes"},
      {"sparse.gltf", &scene::InputLimits::maxTriangles, 2,
       "the file's triangle count 2 exceeds the limit 1 (InputLimits::maxTriangles"},
      // transforms.gltf: 5 nodes, 5 instances.
      {"transforms.gltf", &scene::InputLimits::maxInstances, 5,
       "instance count 5 exceeds the limit 4 (InputLimits::maxInstances"},
      {"transforms.gltf", &scene::InputLimits::maxNodeVisits, 5,
       "node visits 5 exceeds the limit 4 (InputLimits::maxNodeVisits"},
  };
  for (const auto& c : cases) {
    INFO(c.file << ": " << c.message);
    scene::InputLimits limits;
    limits.*c.limit = c.needed;
    CHECK_NOTHROW(scene::importGltf(gltf(c.file), {}, limits));
    limits.*c.limit = c.needed - 1;
    CHECK_THAT(test::gltfRefusal(gltf(c.file), limits), ContainsSubstring(c.message));
  }
}

TEST_CASE("glTF KHR_materials_variants: each variant gives its primitives their materials",
          "[gltf]") {
  test::TempFolder folder("gltf-variants");
  folder.write("tri.bin", test::trianglePositions());
  // Two primitives and three materials; the first primitive is 'beige' by
  // default, 'red' under variant 0 and 'blue' under variant 1; the second
  // is 'beige' except under variant 1 ('red').
  auto file = [&](const std::string& secondMapping) {
    return folder.write("variants.gltf", R"({"asset":{"version":"2.0"},
      "extensionsUsed":["KHR_materials_variants"],
      "extensions":{"KHR_materials_variants":{"variants":[{"name":"sunset"},{"name":"ocean"}]}},
      "buffers":[{"uri":"tri.bin","byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
      "materials":[{"name":"beige"},{"name":"red"},{"name":"blue"}],
      "meshes":[{"primitives":[
        {"attributes":{"POSITION":0},"material":0,"extensions":{"KHR_materials_variants":{"mappings":[
          {"material":1,"variants":[0]},{"material":2,"variants":[1]}]}}},
        {"attributes":{"POSITION":0},"material":0,"extensions":{"KHR_materials_variants":{"mappings":[
          )" + secondMapping + R"(]}}}]}],
      "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
  };
  const auto loaded = scene::importGltf(file(R"({"material":1,"variants":[1]})"));
  CHECK(loaded.warnings.empty());
  const scene::Scene& s = loaded.scene;
  REQUIRE(s.meshes.size() == 2u);
  REQUIRE(s.materialVariants.size() == 2u);
  CHECK(s.materialVariants[0].name == "sunset");
  CHECK(s.materialVariants[1].name == "ocean");
  auto materials = [](const scene::Scene& v) {
    return std::vector<std::string>{v.materials[v.meshes[0].material].name,
                                    v.materials[v.meshes[1].material].name};
  };
  CHECK(materials(s) == std::vector<std::string>{"beige", "beige"});
  for (const auto& [name, expected] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"sunset", {"red", "beige"}}, {"ocean", {"blue", "red"}}, {"1", {"blue", "red"}}}) {
    INFO("variant " << name);
    scene::Scene v = s;
    scene::selectMaterialVariant(v, name);
    CHECK(materials(v) == expected);
    scene::validate(v);
  }
  scene::Scene v = s;
  CHECK_THROWS_WITH(scene::selectMaterialVariant(v, "dusk"),
                    ContainsSubstring("no material variant 'dusk' (variants by index and name: 0 "
                                      "'sunset', 1 'ocean')"));
  CHECK_THROWS_WITH(scene::selectMaterialVariant(v, "2"),
                    ContainsSubstring("no material variant '2'"));
  // A mapping to a variant or material the file does not have.
  CHECK_THAT(test::gltfRefusal(file(R"({"material":1,"variants":[2]})")),
             ContainsSubstring("mesh 0 primitive 1: KHR_materials_variants variant is not one of "
                               "the 2 there are"));
  CHECK_THAT(test::gltfRefusal(file(R"({"material":3,"variants":[0]})")),
             ContainsSubstring("KHR_materials_variants material is not one of the 3 there are"));
}

TEST_CASE("glTF morph targets: the mesh's default weights, or the node's, shape what is drawn",
          "[gltf]") {
  test::TempFolder folder("gltf-morph");
  // Base triangle (0,0,0) (1,0,0) (0,1,0) with normals +z; target 0 lifts
  // vertex 0 by 1 in z; target 1 moves vertex 1 by 1 in x and tilts every
  // normal by +x. Weights 0.5 and 0.25: vertex 0 at (0, 0, 0.5), vertex 1 at
  // (1.25, 0, 0), normals (0.25, 0, 1) normalised.
  const std::vector<float> floats = {
      0, 0, 0, 1, 0, 0, 0, 1, 0,  // POSITION
      0, 0, 1, 0, 0, 1, 0, 0, 1,  // NORMAL
      0, 0, 1, 0, 0, 0, 0, 0, 0,  // target 0 POSITION
      0, 0, 0, 1, 0, 0, 0, 0, 0,  // target 1 POSITION
      1, 0, 0, 1, 0, 0, 1, 0, 0,  // target 1 NORMAL
  };
  std::string bin(floats.size() * 4, '\0');
  std::memcpy(bin.data(), floats.data(), bin.size());
  folder.write("morph.bin", bin);
  auto file = [&](const std::string& weights, const std::string& nodeWeights) {
    std::string views, accessors;
    for (int i = 0; i < 5; ++i) {
      views +=
          fmt::format(R"({}{{"buffer":0,"byteOffset":{},"byteLength":36}})", i ? "," : "", 36 * i);
      accessors +=
          fmt::format(R"({}{{"bufferView":{},"componentType":5126,"count":3,"type":"VEC3"{}}})",
                      i ? "," : "", i, i == 0 ? R"(,"min":[0,0,0],"max":[1,1,0])" : "");
    }
    return folder.write("morph.gltf", fmt::format(R"({{"asset":{{"version":"2.0"}},
      "buffers":[{{"uri":"morph.bin","byteLength":180}}],"bufferViews":[{}],"accessors":[{}],
      "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"NORMAL":1}},
        "targets":[{{"POSITION":2}},{{"POSITION":3,"NORMAL":4}}]}}]{}}}],
      "nodes":[{{"mesh":0{}}}],"scenes":[{{"nodes":[0]}}]}})",
                                                  views, accessors, weights, nodeWeights));
  };
  const auto r = scene::importGltf(file(R"(,"weights":[0.5,0.25])", ""));
  CHECK(r.warnings.empty());
  const scene::Mesh& mesh = r.scene.meshes.at(0);
  auto find = [&](glm::vec3 p) {
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      if (glm::length(mesh.positions[v] - p) <= 1e-6f) return v;
    FAIL("no vertex at (" << p.x << ", " << p.y << ", " << p.z << ")");
    return size_t(0);
  };
  find({0.0f, 0.0f, 0.5f});
  find({1.25f, 0.0f, 0.0f});
  find({0.0f, 1.0f, 0.0f});
  for (const glm::vec3& n : mesh.normals)
    requireNear(n, glm::normalize(glm::vec3(0.25f, 0.0f, 1.0f)));
  // Without weights the base shape, and a line saying the targets weigh 0.
  const auto base = scene::importGltf(file("", ""));
  CHECK(hasWarning(base, "2 morph targets but 0 default weights"));
  requireNear(base.scene.meshes.at(0).normals.at(0), glm::vec3(0.0f, 0.0f, 1.0f));
  // A node's own weights (1, 0) win over the mesh's: vertex 0 at (0, 0, 1)
  // (test_gltf_animation.cpp has the animated ones).
  const auto own = scene::importGltf(file(R"(,"weights":[0.5,0.25])", R"(,"weights":[1,0])"));
  bool lifted = false;
  for (const glm::vec3& p : own.scene.meshes.at(0).positions)
    lifted = lifted || glm::length(p - glm::vec3(0.0f, 0.0f, 1.0f)) <= 1e-6f;
  CHECK(lifted);
}
