// The NEE emitter table (engine/penumbra/render/emitter_table.h) on the CPU, against
// values worked out by hand: areas, luminances, choice probabilities and
// their running sums, placement in render space, winding under mirroring.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/render/emitter_table.h"

using namespace penumbra;
using namespace penumbra::render;
using Catch::Approx;

namespace {

// One unit right triangle (area 0.5, front +z) per source unless given more.
EmitterSource source(glm::dmat4 objectToWorld, glm::vec3 emission,
                     std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) {
  EmitterSource s;
  s.objectToWorld = objectToWorld;
  s.mirrored = glm::determinant(glm::dmat3(objectToWorld)) < 0.0;
  s.positions = std::move(positions);
  s.uvs.assign(s.positions.size(), glm::vec2(0.0f));
  s.emission = emission;
  s.luminance = 0.2126 * emission.x + 0.7152 * emission.y + 0.0722 * emission.z;
  return s;
}

glm::vec3 xyz(const gpu::float3& v) {
  return {v.x, v.y, v.z};
}

}  // namespace

TEST_CASE("emitter table: triangles are chosen in proportion to area x luminance",
          "[render][emitters]") {
  // A: area 0.5, white (luminance 1): power 0.5.
  // B: scaled by 2 -> area 2, red 2 (luminance 2 x 0.2126 = 0.4252): power 0.8504;
  //    plus a degenerate triangle (collinear corners): power 0.
  const glm::dmat4 scaled = glm::scale(glm::translate(glm::dmat4(1.0), {10, 0, 0}), {2, 2, 2});
  const std::vector<EmitterSource> sources = {
      source(glm::dmat4(1.0), {1, 1, 1}),
      source(scaled, {2, 0, 0},
             {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}})};
  const EmitterTable table = placeEmitters(sources, glm::dmat4(1.0));
  REQUIRE(table.triangles.size() == 3);
  REQUIRE(table.sampledCount == 3);
  const auto& t = table.triangles;
  const double total = 0.5 + 0.8504;
  CHECK(t[0].area == Approx(0.5));
  CHECK(t[1].area == Approx(2.0));
  CHECK(t[2].area == 0.0f);
  CHECK(t[0].probability == Approx(0.5 / total).epsilon(1e-6));     // 0.370261
  CHECK(t[1].probability == Approx(0.8504 / total).epsilon(1e-6));  // 0.629739
  CHECK(t[2].probability == 0.0f);                                  // never chosen
  CHECK(t[0].cumulativeProbability == Approx(0.5 / total).epsilon(1e-6));
  // The last triangle with power ends the running sum at exactly 1, and so
  // does every one after it: a uniform number in [0, 1) always lands on a
  // triangle that can be chosen.
  CHECK(t[1].cumulativeProbability == 1.0f);
  CHECK(t[2].cumulativeProbability == 1.0f);
  CHECK(xyz(t[1].radiance) == glm::vec3(2, 0, 0));  // the emission itself, not its luminance
}

TEST_CASE("emitter table: triangles are placed in render space", "[render][emitters]") {
  const glm::dmat4 world = glm::translate(glm::dmat4(1.0), {1e6, 0, 5});
  const glm::dmat4 toRenderSpace = glm::translate(glm::dmat4(1.0), {-1e6, 0, 0});
  const EmitterTable table = placeEmitters({source(world, {1, 1, 1})}, toRenderSpace);
  REQUIRE(table.triangles.size() == 1);
  // Placed in double before the float conversion: exact despite the 1e6 offset.
  CHECK(xyz(table.triangles[0].p0) == glm::vec3(0, 0, 5));
  CHECK(xyz(table.triangles[0].p1) == glm::vec3(1, 0, 5));
  CHECK(xyz(table.triangles[0].p2) == glm::vec3(0, 1, 5));
  CHECK(table.triangles[0].probability == 1.0f);
}

TEST_CASE("emitter table: a mirroring transform keeps the emitting side the front",
          "[render][emitters]") {
  // Mirrored in x, the corners (0,0,0) (-1,0,0) (0,1,0) wind clockwise seen
  // from +z; swapping two corners restores the front normal +z.
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), {-1, 1, 1});
  const EmitterTable table = placeEmitters({source(mirror, {1, 1, 1})}, glm::dmat4(1.0));
  REQUIRE(table.triangles.size() == 1);
  const auto& t = table.triangles[0];
  const glm::vec3 normal = glm::cross(xyz(t.p1) - xyz(t.p0), xyz(t.p2) - xyz(t.p0));
  CHECK(normal == glm::vec3(0, 0, 1));
  CHECK(t.area == Approx(0.5));
}

TEST_CASE("emitter table: without power NEE samples no triangle", "[render][emitters]") {
  const EmitterTable none = placeEmitters({}, glm::dmat4(1.0));
  CHECK(none.triangles.empty());
  CHECK(none.sampledCount == 0);
  // Only degenerate triangles: listed (their instances index them) but never chosen.
  const EmitterTable flat = placeEmitters(
      {source(glm::dmat4(1.0), {1, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})}, glm::dmat4(1.0));
  REQUIRE(flat.triangles.size() == 1);
  CHECK(flat.sampledCount == 0);
  CHECK(flat.triangles[0].probability == 0.0f);
}

TEST_CASE("emitter table: a scene instance's source follows its mesh's indices",
          "[render][emitters]") {
  scene::Scene scene;
  scene.materials.push_back(scene::Material::lambert("light", glm::vec3(0.0f), {1, 2, 3}));
  scene::Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene.meshes.push_back(quad);
  scene::Instance instance;
  instance.transform = glm::scale(glm::dmat4(1.0), {1, 1, -1});
  const EmitterSource s = emitterSource(scene, instance);
  CHECK(s.mirrored);
  REQUIRE(s.positions.size() == 6);
  CHECK(s.positions[4] == glm::vec3(1, 1, 0));  // index 2
  CHECK(s.positions[5] == glm::vec3(0, 1, 0));  // index 3
  CHECK(s.uvs[5] == glm::vec2(0, 1));
  CHECK(s.emission == glm::vec3(1, 2, 3));
  CHECK(s.luminance == Approx(0.2126 + 2 * 0.7152 + 3 * 0.0722));  // 1.8596
  CHECK(s.emissionTexture == PT_NO_TEXTURE);
}
