// The procedural terrain of the performance scene (engine/penumbra/scene/terrain.h).
#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "penumbra/scene/terrain.h"
#include "penumbra/util/error.h"

using namespace penumbra;

TEST_CASE("terrain: grid size, winding up, heights within the amplitude, deterministic", "[scene]") {
  scene::TerrainDesc desc;
  desc.resolution = 65;
  desc.size = 8.0f;
  desc.height = 0.5f;
  const auto mesh = scene::makeTerrain(desc, 3);
  REQUIRE(mesh.positions.size() == 65u * 65u);
  REQUIRE(mesh.triangleCount() == 2u * 64u * 64u);
  REQUIRE(mesh.material == 3u);
  float lo = 1e9f, hi = -1e9f;
  for (const auto& p : mesh.positions) {
    REQUIRE(std::abs(p.x) <= 4.0f + 1e-5f);
    REQUIRE(std::abs(p.z) <= 4.0f + 1e-5f);
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  // fBm is normalised to [-1, 1]; real terrain spans a good part of it.
  REQUIRE(lo >= -0.5f);
  REQUIRE(hi <= 0.5f);
  REQUIRE(hi - lo > 0.1f);
  // Every triangle faces up (+y) in a heightfield.
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const auto& a = mesh.positions[mesh.indices[t]];
    const auto& b = mesh.positions[mesh.indices[t + 1]];
    const auto& c = mesh.positions[mesh.indices[t + 2]];
    REQUIRE(glm::cross(b - a, c - a).y > 0.0f);
  }
  const auto again = scene::makeTerrain(desc, 3);
  REQUIRE(again.positions == mesh.positions);
  desc.seed = 2;
  REQUIRE(scene::makeTerrain(desc, 3).positions != mesh.positions);
}

TEST_CASE("terrain: noise is continuous and bad sizes are errors", "[scene]") {
  // Value noise with smoothstep interpolation is continuous: tiny steps, tiny changes.
  for (float x = -3.0f; x < 3.0f; x += 0.37f) {
    const float a = scene::fractalNoise(x, 0.7f, 4, 1);
    const float b = scene::fractalNoise(x + 1e-4f, 0.7f, 4, 1);
    REQUIRE(std::abs(a - b) < 1e-2f);
    REQUIRE(std::abs(a) <= 1.0f);
  }
  scene::TerrainDesc desc;
  desc.resolution = 1;
  REQUIRE_THROWS_AS(scene::makeTerrain(desc, 0), Error);
  desc.resolution = 100000;
  REQUIRE_THROWS_AS(scene::makeTerrain(desc, 0), Error);
}
