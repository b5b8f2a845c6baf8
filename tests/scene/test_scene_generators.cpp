// Procedural content in scene files (engine/scene/scene_generators.h) and the
// performance scene built from it.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "scene/scene_loader.h"
#include "util/error.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;

namespace {
std::string sceneWith(const std::string& generated) {
  return R"({"format": "penumbra-scene", "version": 1, "name": "g",
    "camera": {"position": [0, 1, -5], "forward": [0, 0, 1], "up": [0, 1, 0], "verticalFovDegrees": 40},
    "materials": {"a": {"model": "lambert"}, "b": {"model": "disney"}},
    "generated": )" +
         generated + "}";
}
}  // namespace

TEST_CASE("generated: terrain, sphere grids and implicit grids", "[scene]") {
  const auto s = scene::parseScene(sceneWith(R"([
      {"kind": "terrain", "material": "a", "resolution": 11, "size": 2, "translate": [0, -1, 0]},
      {"kind": "spheres", "material": "b", "count": [3, 2], "spacing": 2, "origin": [0, 0, 0],
       "radius": 0.5, "subdivisions": 1},
      {"kind": "implicitGrid", "materials": ["a", "b"], "count": [2, 3, 4], "spacing": 1,
       "origin": [0, 2, 0], "size": 0.25}])"),
                                   "test");
  // Terrain: 2 * 10^2 triangles; icosphere level 1: 80 triangles, one mesh, 6 instances.
  REQUIRE(s.meshes.size() == 2u);
  REQUIRE(s.meshes[0].triangleCount() == 200u);
  REQUIRE(s.meshes[1].triangleCount() == 80u);
  REQUIRE(s.instances.size() == 7u);
  REQUIRE(s.instances[0].transform[3].y == -1.0f);
  REQUIRE(s.triangleCount() == 200u + 6u * 80u);
  // Sphere centres on the grid: x = 2 i, z = 2 j.
  REQUIRE(s.instances[6].transform[3] == glm::dvec4(4.0, 0.0, 2.0, 1.0));
  // 24 implicit objects cycling through 4 kinds and 2 materials.
  REQUIRE(s.implicits.size() == 24u);
  REQUIRE(s.implicits[0].kind() == scene::ImplicitKind::Sphere);
  REQUIRE(s.implicits[1].kind() == scene::ImplicitKind::Box);
  REQUIRE(s.implicits[2].kind() == scene::ImplicitKind::Torus);
  REQUIRE(s.implicits[3].kind() == scene::ImplicitKind::RoundedBox);
  REQUIRE(s.implicits[0].material != s.implicits[1].material);
  REQUIRE(s.implicits[23].transform[3] == glm::dvec4(1.0, 4.0, 3.0, 1.0));
}

TEST_CASE("generated: bad entries are clear errors", "[scene]") {
  auto fails = [](const std::string& generated, const std::string& message) {
    REQUIRE_THROWS_WITH(scene::parseScene(sceneWith(generated), "test"),
                        ContainsSubstring(message));
  };
  fails(R"([{"kind": "forest"}])", "unknown kind 'forest'");
  fails(R"([{"kind": "terrain", "material": "z"}])", "unknown material 'z'");
  fails(R"([{"kind": "terrain", "material": "a", "resolution": 1}])",
        "\"resolution\" must be at least 2");
  fails(R"([{"kind": "spheres", "material": "a", "count": [2], "origin": [0, 0, 0]}])",
        "\"count\" must be an array of 2");
  fails(R"([{"kind": "implicitGrid", "materials": [], "count": [1, 1, 1], "origin": [0, 0, 0]}])",
        "non-empty array");
  fails(R"({"kind": "terrain"})", "\"generated\" must be an array");
}

TEST_CASE(
    "the performance scene holds at least 5 million triangles and hundreds of implicit objects",
    "[scene]") {
  const auto s = scene::loadScene("performance");
  REQUIRE(s.triangleCount() >= 5'000'000u);
  REQUIRE(s.implicits.size() >= 200u);
}
