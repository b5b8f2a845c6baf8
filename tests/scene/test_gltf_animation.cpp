// glTF animations, morph weights and skins at a chosen time, against files
// the tests write. Every expected position is worked out by hand in the
// comments from the keyframes, the joints and the glTF 2.0 specification
// (3.7.3 skins, 3.11 animations, appendix C interpolation).
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "gltf_test_files.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/util/error.h"
#include "test_data.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;

namespace {

// The world positions of every vertex of every instance.
std::vector<glm::dvec3> worldVertices(const scene::Scene& s) {
  std::vector<glm::dvec3> out;
  for (const auto& instance : s.instances)
    for (const glm::vec3& p : s.meshes[instance.mesh].positions)
      out.push_back(glm::dvec3(instance.transform * glm::dvec4(glm::dvec3(p), 1.0)));
  return out;
}

void requireVertex(const std::vector<glm::dvec3>& vertices, glm::dvec3 expected,
                   double eps = 1e-5) {
  const bool found = std::any_of(vertices.begin(), vertices.end(), [&](const glm::dvec3& v) {
    return glm::length(v - expected) <= eps;
  });
  std::string got;
  for (const auto& v : vertices) got += fmt::format(" ({:.6f}, {:.6f}, {:.6f})", v.x, v.y, v.z);
  INFO("expected (" << expected.x << ", " << expected.y << ", " << expected.z << "); got" << got);
  REQUIRE(found);
}

bool hasWarning(const scene::GltfImport& r, const std::string& part) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

scene::AnimationChoice at(const std::string& animation, double seconds) {
  return {animation, seconds};
}

const float kSin45 = float(std::sqrt(0.5));

// One triangle (0,0,0) (1,0,0) (0,1,0) at node 0, and two animations of
// node 0. "Move": translation LINEAR (0,0,0) at 0 s to (2,0,0) at 2 s;
// rotation LINEAR from none at 0 s to 90 degrees about +z at 1 s; scale
// STEP 1 from 0 s, 2 from 1 s. "Cubic": translation CUBICSPLINE from x = 0
// (out-tangent 3) at 0 s to x = 1 (in-tangent 2) at 1 s; the outer tangents
// (100, -100) lie outside the keyframes and must not matter.
std::string trsFile(const test::TempFolder& folder) {
  test::GltfWriter w;
  const int position =
      w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3, R"(,"min":[0,0,0],"max":[1,1,0])");
  const int times2 = w.floats({0, 2}, "SCALAR", 1);
  const int times1 = w.floats({0, 1}, "SCALAR", 1);
  const int translations = w.floats({0, 0, 0, 2, 0, 0}, "VEC3", 3);
  const int rotations = w.floats({0, 0, 0, 1, 0, 0, kSin45, kSin45}, "VEC4", 4);
  const int scales = w.floats({1, 1, 1, 2, 2, 2}, "VEC3", 3);
  const int cubic = w.floats({100, 0, 0, 0, 0, 0, 3, 0, 0,    // in, value, out at 0 s
                              2, 0, 0, 1, 0, 0, -100, 0, 0},  // in, value, out at 1 s
                             "VEC3", 3);
  return w.write(folder, "trs",
                 fmt::format(R"(
    "meshes":[{{"primitives":[{{"attributes":{{"POSITION":{}}}}}]}}],
    "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],
    "animations":[
      {{"name":"Move","samplers":[{{"input":{},"output":{}}},
          {{"input":{},"output":{},"interpolation":"LINEAR"}},
          {{"input":{},"output":{},"interpolation":"STEP"}}],
        "channels":[{{"sampler":0,"target":{{"node":0,"path":"translation"}}}},
                    {{"sampler":1,"target":{{"node":0,"path":"rotation"}}}},
                    {{"sampler":2,"target":{{"node":0,"path":"scale"}}}}]}},
      {{"name":"Cubic","samplers":[{{"input":{},"output":{},"interpolation":"CUBICSPLINE"}}],
        "channels":[{{"sampler":0,"target":{{"node":0,"path":"translation"}}}}]}}])",
                             position, times2, translations, times1, rotations, times1, scales,
                             times1, cubic));
}

}  // namespace

TEST_CASE("glTF animations: STEP, LINEAR with slerp, CUBICSPLINE, held outside the keyframes",
          "[gltf]") {
  test::TempFolder folder("gltf-animation-trs");
  const std::string file = trsFile(folder);
  // Without a choice, the node's own (identity) transform.
  auto rest = worldVertices(scene::importGltf(file).scene);
  requireVertex(rest, {1, 0, 0});
  // "Move" at 0.5 s: translation (0.5,0,0), 45 degrees about z, scale 1 (STEP
  // holds 0 s's value): (1,0,0) goes to (0.5 + cos 45, sin 45, 0).
  auto half = worldVertices(scene::importGltf(file, {}, {}, at("Move", 0.5)).scene);
  requireVertex(half, {0.5 + std::sqrt(0.5), std::sqrt(0.5), 0});
  requireVertex(half, {0.5 - std::sqrt(0.5), std::sqrt(0.5), 0});  // (0,1,0)
  // At 1 s: translation (1,0,0), 90 degrees, scale 2: (1,0,0) -> (2,0,0) ->
  // (0,2,0) -> (1,2,0).
  requireVertex(worldVertices(scene::importGltf(file, {}, {}, at("Move", 1.0)).scene), {1, 2, 0});
  // Past the end every channel holds its last value: translation (2,0,0),
  // 90 degrees, scale 2: (1,0,0) -> (2,2,0); the time is said to be outside.
  const auto late = scene::importGltf(file, {}, {}, at("0", 3.0));
  requireVertex(worldVertices(late.scene), {2, 2, 0});
  CHECK(hasWarning(late,
                   "3 s is outside the keyframes of animation 0 'Move' (0 to 2 s); the last "
                   "pose is drawn"));
  // Before the start, the first values: the rest pose.
  requireVertex(worldVertices(scene::importGltf(file, {}, {}, at("Move", -1.0)).scene), {1, 0, 0});
  // A time alone picks the first animation.
  requireVertex(worldVertices(scene::importGltf(file, {}, {}, {"", 1.0}).scene), {1, 2, 0});
  // "Cubic" at 0.5 s, the Hermite basis at u = 0.5 with span 1:
  // h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = -0.125, so
  // x = 0.5 * 0 + 0.125 * 3 + 0.5 * 1 - 0.125 * 2 = 0.625.
  requireVertex(worldVertices(scene::importGltf(file, {}, {}, at("Cubic", 0.5)).scene),
                {0.625, 0, 0});
  // "all": both at once, the later ("Cubic") winning on the translation they
  // share: translation (0.625,0,0) with "Move"'s 45 degrees and scale 1, so
  // (1,0,0) goes to (0.625 + cos 45, sin 45, 0).
  requireVertex(worldVertices(scene::importGltf(file, {}, {}, at("all", 0.5)).scene),
                {0.625 + std::sqrt(0.5), std::sqrt(0.5), 0});
  // At a keyframe, its value (the middle of the three).
  requireVertex(worldVertices(scene::importGltf(file, {}, {}, at("1", 1.0)).scene), {1, 0, 0});
}

TEST_CASE("glTF animation choices that do not exist are one clear error", "[gltf]") {
  test::TempFolder folder("gltf-animation-bad");
  const std::string file = trsFile(folder);
  CHECK_THAT(test::gltfRefusalWith(file, at("Walk", 0.0)),
             ContainsSubstring("no animation 'Walk' (animations by index and name: 0 'Move', 1 "
                               "'Cubic')"));
  CHECK_THAT(test::gltfRefusalWith(file, at("2", 0.0)), ContainsSubstring("no animation '2'"));
  for (const char* choice : {"", "all"})
    CHECK_THAT(test::gltfRefusalWith(test::dataPath("gltf/cameras.gltf"), {choice, 1.0}),
               ContainsSubstring("the file has no animations to draw at a time"));
}

TEST_CASE("glTF animation samplers are checked before they are used", "[gltf]") {
  test::TempFolder folder("gltf-animation-samplers");
  auto file = [&](const std::vector<float>& times, const std::vector<float>& values,
                  const std::string& interpolation) {
    test::GltfWriter w;
    const int position =
        w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3, R"(,"min":[0,0,0],"max":[1,1,0])");
    const int input = w.floats(times, "SCALAR", 1);
    const int output = w.floats(values, "VEC3", 3);
    return w.write(folder, "bad",
                   fmt::format(R"(
      "meshes":[{{"primitives":[{{"attributes":{{"POSITION":{}}}}}]}}],
      "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],
      "animations":[{{"samplers":[{{"input":{},"output":{},"interpolation":"{}"}}],
        "channels":[{{"sampler":0,"target":{{"node":0,"path":"translation"}}}}]}}])",
                               position, input, output, interpolation));
  };
  CHECK_THAT(
      test::gltfRefusalWith(file({0, 1, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "LINEAR"), {"", 0.5}),
      ContainsSubstring("animation 0 channel 0 sampler 0 input: times are not increasing "
                        "(keyframe 2: 1 after 1)"));
  CHECK_THAT(test::gltfRefusalWith(file({0, 1}, {0, 0, 0, 1, 0, 0}, "CUBICSPLINE"), {"", 0.5}),
             ContainsSubstring("output: 2 values for 2 keyframes (CUBICSPLINE keeps 3 per "
                               "keyframe)"));
  CHECK_THAT(test::gltfRefusalWith(file({0, 1}, {0, 0, 0, 1, 0, 0}, "SMOOTH"), {"", 0.5}),
             ContainsSubstring("unknown interpolation 'SMOOTH'"));
  // A node given by a matrix may not be animated (glTF 2.0, 3.11).
  std::string text = test::readText(file({0, 1}, {0, 0, 0, 1, 0, 0}, "LINEAR"));
  const std::string node = R"("nodes":[{"mesh":0}])";
  REQUIRE(text.find(node) != std::string::npos);
  text.replace(text.find(node), node.size(),
               R"("nodes":[{"mesh":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]}])");
  CHECK_THAT(test::gltfRefusalWith(folder.write("matrix.gltf", text), {"", 0.5}),
             ContainsSubstring("node 0: is animated but has a matrix"));
}

TEST_CASE("glTF morph weights: a node's own, or an animation's at the chosen time", "[gltf]") {
  test::TempFolder folder("gltf-animation-morph");
  // Base triangle (0,0,0) (1,0,0) (0,1,0); target 0 lifts vertex 0 by 1 in
  // z, target 1 moves vertex 1 by 1 in x. Weights animated LINEAR from (0, 0)
  // at 0 s to (1, 0.5) at 1 s: at 0.5 s (0.5, 0.25), so vertex 0 at
  // (0, 0, 0.5) and vertex 1 at (1.25, 0, 0).
  auto file = [&](const std::string& nodeWeights,
                  const std::vector<float>& keyedWeights = {0, 0, 1, 0.5f}) {
    test::GltfWriter w;
    const int position =
        w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3, R"(,"min":[0,0,0],"max":[1,1,0])");
    const int t0 = w.floats({0, 0, 1, 0, 0, 0, 0, 0, 0}, "VEC3", 3);
    const int t1 = w.floats({0, 0, 0, 1, 0, 0, 0, 0, 0}, "VEC3", 3);
    const int times = w.floats({0, 1}, "SCALAR", 1);
    const int weights = w.floats(keyedWeights, "SCALAR", 1);
    return w.write(folder, "morph",
                   fmt::format(R"(
      "meshes":[{{"primitives":[{{"attributes":{{"POSITION":{}}},
        "targets":[{{"POSITION":{}}},{{"POSITION":{}}}]}}],"weights":[0,0]}}],
      "nodes":[{{"mesh":0{}}},{{"mesh":0}}],"scenes":[{{"nodes":[0,1]}}],
      "animations":[{{"samplers":[{{"input":{},"output":{}}}],
        "channels":[{{"sampler":0,"target":{{"node":0,"path":"weights"}}}}]}}])",
                               position, t0, t1, nodeWeights, times, weights));
  };
  const auto animated = scene::importGltf(file(""), {}, {}, {"", 0.5});
  CHECK(animated.warnings.empty());
  REQUIRE(animated.scene.instances.size() == 2);
  // Node 0 is animated, node 1 (not targeted) keeps the mesh's weights (0, 0):
  // two shapes of one mesh.
  CHECK(animated.scene.meshes.size() == 2);
  const auto v = worldVertices(animated.scene);
  requireVertex(v, {0, 0, 0.5});
  requireVertex(v, {1.25, 0, 0});
  requireVertex(v, {0, 0, 0});
  requireVertex(v, {1, 0, 0});
  // A node's own weights (1, 0) over the mesh's, without an animation:
  // vertex 0 at (0, 0, 1); node 1 shares nothing with it.
  const auto own = scene::importGltf(file(R"(,"weights":[1,0])"));
  requireVertex(worldVertices(own.scene), {0, 0, 1});
  CHECK(own.scene.meshes.size() == 2);
  // Nodes with equal weights share the converted mesh.
  CHECK(scene::importGltf(file("")).scene.meshes.size() == 1);
  // One weight per target per keyframe: three per keyframe is refused.
  CHECK_THAT(test::gltfRefusalWith(file("", {0, 0, 0, 1, 0.5f, 0}), {"", 0.5}),
             ContainsSubstring("output: 6 values for 2 keyframes of 2 morph weights"));
}

namespace {

// A skinned triangle: A (0,0,0) on joint 0, B (1,1,0) half on each joint,
// C (0,2,0) on joint 1; normals +z at A, +x at B and C. The skinned node 0 is
// at (100,0,0), which must not move the mesh (3.7.3.1). Joint 0 is node 1
// at (0,0,5); joint 1 is node 2, its child, at (0,1,0) in it. Inverse bind
// matrices undo the joints' rest placements: translate(0,0,-5) and
// translate(0,-1,-5). Animation "Bend" turns joint 1 by 90 degrees about +z
// at 1 s (LINEAR from none at 0 s).
std::string skinFile(const test::TempFolder& folder, const std::vector<uint8_t>& joints,
                     const std::string& nodePlace = R"("translation":[100,0,0])",
                     const std::string& jointsExtra = "") {
  test::GltfWriter w;
  const int position =
      w.floats({0, 0, 0, 1, 1, 0, 0, 2, 0}, "VEC3", 3, R"(,"min":[0,0,0],"max":[1,2,0])");
  const int normal = w.floats({0, 0, 1, 1, 0, 0, 1, 0, 0}, "VEC3", 3);
  const int jointIndices = w.bytes4(joints, jointsExtra);
  const int weights = w.floats({1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0}, "VEC4", 4);
  const int inverseBind = w.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  -5, 1,  //
                                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, -5, 1},
                                   "MAT4", 16);
  const int times = w.floats({0, 1}, "SCALAR", 1);
  const int rotations = w.floats({0, 0, 0, 1, 0, 0, kSin45, kSin45}, "VEC4", 4);
  return w.write(folder, "skin",
                 fmt::format(R"(
    "meshes":[{{"primitives":[{{"attributes":{{"POSITION":{},"NORMAL":{},"JOINTS_0":{},
      "WEIGHTS_0":{}}}}}]}}],
    "skins":[{{"joints":[1,2],"inverseBindMatrices":{}}}],
    "nodes":[{{"mesh":0,"skin":0,{}}},
             {{"translation":[0,0,5],"children":[2]}},{{"translation":[0,1,0]}}],
    "scenes":[{{"nodes":[0,1]}}],
    "animations":[{{"name":"Bend","samplers":[{{"input":{},"output":{}}}],
      "channels":[{{"sampler":0,"target":{{"node":2,"path":"rotation"}}}}]}}])",
                             position, normal, jointIndices, weights, inverseBind, nodePlace, times,
                             rotations));
}

}  // namespace

TEST_CASE("glTF skins: vertices follow their joints, the skinned node's transform does not",
          "[gltf]") {
  test::TempFolder folder("gltf-skin");
  const std::string file = skinFile(folder, {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0});
  // At rest the joints stand where the inverse bind matrices expect them:
  // the triangle as stored, not at x = 100.
  const auto rest = scene::importGltf(file);
  CHECK(rest.warnings.empty());
  const auto r = worldVertices(rest.scene);
  for (glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 2, 0)})
    requireVertex(r, p);
  // At 1 s joint 1 is turned 90 degrees. C: (0,2,0) -> inverse bind (0,1,-5)
  // -> turned (-1,0,-5) -> joint 1's place (-1,1,0). B: half of itself (joint
  // 0 is at rest) and half of (1,1,0) -> (1,0,-5) -> (0,1,-5) -> (0,2,0):
  // (0.5,1.5,0). A stays.
  const auto bent = scene::importGltf(file, {}, {}, {"Bend", 1.0});
  const auto b = worldVertices(bent.scene);
  requireVertex(b, {0, 0, 0});
  requireVertex(b, {0.5, 1.5, 0});
  requireVertex(b, {-1, 1, 0});
  // Normals turn with the joints: C's +x becomes +y; B's blended matrix
  // 0.5 (I + R90) is a 45-degree turn times 0.707, so +x becomes
  // (cos 45, sin 45, 0) once normalised; A's +z stays.
  const scene::Mesh& mesh = bent.scene.meshes.at(bent.scene.instances.at(0).mesh);
  const glm::dmat3 toWorld(bent.scene.instances.at(0).transform);
  auto normalAt = [&](glm::dvec3 world) {
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::dvec3 p(bent.scene.instances.at(0).transform *
                         glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
      if (glm::length(p - world) < 1e-5)
        return glm::normalize(toWorld * glm::dvec3(mesh.normals[i]));
    }
    FAIL("no vertex there");
    return glm::dvec3(0.0);
  };
  CHECK(glm::length(normalAt({-1, 1, 0}) - glm::dvec3(0, 1, 0)) < 1e-5);
  CHECK(glm::length(normalAt({0.5, 1.5, 0}) - glm::dvec3(std::sqrt(0.5), std::sqrt(0.5), 0)) <
        1e-5);
  CHECK(glm::length(normalAt({0, 0, 0}) - glm::dvec3(0, 0, 1)) < 1e-5);
  // A skinned node whose own transform collapses (scale 0) is still drawn
  // by its joints.
  const auto flat = scene::importGltf(
      skinFile(folder, {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0}, R"("scale":[0,0,0])"));
  for (glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 2, 0)})
    requireVertex(worldVertices(flat.scene), p);
  // Joint indices must be plain unsigned integers.
  CHECK_THAT(test::gltfRefusal(skinFile(folder, {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0},
                                        R"("translation":[100,0,0])", R"(,"normalized":true)")),
             ContainsSubstring("JOINTS_0 (accessor 2): joint indices must be unsigned bytes or "
                               "shorts, not normalised"));
  // A joint index past the skin's two joints.
  CHECK_THAT(test::gltfRefusal(skinFile(folder, {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 0})),
             ContainsSubstring("mesh 0 primitive 0 JOINTS_0: vertex 2 names joint 2, not one of "
                               "the skin's 2"));
}

TEST_CASE("glTF skins without joints are refused in one line that says why", "[gltf]") {
  test::TempFolder folder("gltf-skin-draft");
  // Drafts before glTF 2.0 named joints ("jointNames"); tinygltf fails such a
  // file without a reason, so the loader says it first.
  const std::string file = folder.write("draft.gltf", R"({"asset":{"version":"2.0"},
    "skins":[{"jointNames":["hip"]}],"nodes":[{}],"scenes":[{"nodes":[0]}]})");
  CHECK_THAT(test::gltfRefusal(file),
             ContainsSubstring("skin 0 has no \"joints\" array (it has \"jointNames\", from a "
                               "draft before glTF 2.0)"));
}
