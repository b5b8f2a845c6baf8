// Procedural content in scene files (engine/penumbra/scene/scene_generators.h) and the
// performance scene built from it.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

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

// Generator parameters are bounded before anything is allocated
// (scene/input_limits.h, docs/security.md): the error names the entry, the
// field and the limit.
TEST_CASE("generated: sizes past the input limits are refused before allocating", "[scene]") {
  auto fails = [](const std::string& generated, const std::vector<std::string>& mentions,
                  const scene::InputLimits& limits = {}) {
    try {
      scene::parseScene(sceneWith(generated), "g.json", "", {}, limits);
      FAIL("no error");
    } catch (const Error& e) {
      const std::string message = e.what();
      INFO(message);
      CHECK(message.find('\n') == std::string::npos);
      CHECK_THAT(message, ContainsSubstring("scene 'g.json' generated[0]"));
      for (const auto& m : mentions) CHECK_THAT(message, ContainsSubstring(m));
    }
  };
  // 6000: 36 million vertices; 46340, the old cap: 2.1 billion.
  for (const char* r : {"6000", "46340"})
    fails(std::string(R"([{"kind": "terrain", "material": "a", "resolution": )") + r + "}]",
          {"\"resolution\" " + std::string(r) + " exceeds the limit 4096",
           "InputLimits::maxTerrainResolution"});
  fails(R"([{"kind": "terrain", "material": "a", "resolution": -1}])",
        {"\"resolution\" -1 is not a whole number"});
  fails(R"([{"kind": "terrain", "material": "a", "resolution": 1e300}])",
        {"\"resolution\" 1e+300 is not a whole number"});
  fails(R"([{"kind": "spheres", "material": "a", "count": [1, 1], "origin": [0, 0, 0],
             "subdivisions": 10}])",
        {"\"subdivisions\" 10 exceeds the limit 9", "InputLimits::maxSphereSubdivisions"});
  // 16.7 million implicit objects.
  fails(R"([{"kind": "implicitGrid", "materials": ["a"], "count": [256, 256, 256],
             "origin": [0, 0, 0]}])",
        {"implicit object count with the grid 16777216", "InputLimits::maxImplicitObjects"});
  fails(R"([{"kind": 5}])", {"\"kind\" is not a string (got a number)"});
  fails(R"([{"kind": "spheres", "material": "a", "count": [2, "3"], "origin": [0, 0, 0]}])",
        {"\"count[1]\" is not a whole number (got a string)"});
  fails(R"([{"kind": "terrain", "material": "a", "size": 1e39}])",
        {"\"size\" 1e+39 does not fit a float"});

  // At a limit (lowered here, so the test stays small) the entry loads; one past, it does not.
  scene::InputLimits limits;
  limits.maxTerrainResolution = 64;
  limits.maxTriangles = 2 * 63 * 63;
  const auto terrain =
      scene::parseScene(sceneWith(R"([{"kind": "terrain", "material": "a", "resolution": 64}])"),
                        "g.json", "", {}, limits);
  CHECK(terrain.triangleCount() == 2u * 63u * 63u);
  fails(R"([{"kind": "terrain", "material": "a", "resolution": 65}])",
        {"\"resolution\" 65 exceeds the limit 64"}, limits);
  limits.maxTriangles -= 1;
  fails(
      R"([{"kind": "terrain", "material": "a", "resolution": 64}])",
      {"triangle count with the terrain 7938 exceeds the limit 7937", "InputLimits::maxTriangles"},
      limits);
  limits = {};
  limits.maxInstances = 6;
  const std::string grid =
      R"([{"kind": "spheres", "material": "a", "count": [3, 2], "origin": [0, 0, 0], "subdivisions": 1}])";
  CHECK(scene::parseScene(sceneWith(grid), "g.json", "", {}, limits).instances.size() == 6u);
  limits.maxInstances = 5;
  fails(grid, {"instance count with the grid 6 exceeds the limit 5", "InputLimits::maxInstances"},
        limits);
  limits = {};
  limits.maxImplicitObjects = 8;
  const std::string implicits =
      R"([{"kind": "implicitGrid", "materials": ["a"], "count": [2, 2, 2], "origin": [0, 0, 0]}])";
  CHECK(scene::parseScene(sceneWith(implicits), "g.json", "", {}, limits).implicits.size() == 8u);
  limits.maxImplicitObjects = 7;
  fails(implicits, {"InputLimits::maxImplicitObjects"}, limits);
}
