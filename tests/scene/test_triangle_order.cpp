// Triangle order made independent of the file (scene/triangle_order.h): the
// same triangles, each with its winding, in an order that depends on where
// they are and not on how they were stored.
#include <algorithm>
#include <array>
#include <catch2/catch_test_macros.hpp>
#include <random>

#include "penumbra/scene/triangle_order.h"

using namespace penumbra;

namespace {

// An n x n grid of unit quads in the xz plane, two triangles each, stored
// row by row (a good spatial order to start from).
scene::Mesh grid(uint32_t n) {
  scene::Mesh m;
  for (uint32_t z = 0; z <= n; ++z)
    for (uint32_t x = 0; x <= n; ++x) m.positions.emplace_back(float(x), 0.0f, float(z));
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t x = 0; x < n; ++x) {
      const uint32_t a = z * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  return m;
}

using Triangle = std::array<uint32_t, 3>;

// The triangles as rotations starting at their smallest index: the same
// triangle with the same winding compares equal wherever it is stored.
std::vector<Triangle> canonicalTriangles(const scene::Mesh& m) {
  std::vector<Triangle> out;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    Triangle tri{m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]};
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The mean distance between consecutive triangles' centroids, in grid cells.
double meanStep(const scene::Mesh& m) {
  auto centroid = [&](size_t t) {
    return (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
            m.positions[m.indices[3 * t + 2]]) /
           3.0f;
  };
  double sum = 0;
  for (size_t t = 1; t < m.triangleCount(); ++t)
    sum += double(glm::length(centroid(t) - centroid(t - 1)));
  return sum / double(m.triangleCount() - 1);
}

scene::Mesh shuffled(scene::Mesh m, uint32_t seed) {
  std::vector<Triangle> tris;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    tris.push_back({m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]});
  std::mt19937 rng(seed);
  std::shuffle(tris.begin(), tris.end(), rng);
  m.indices.clear();
  for (const auto& tri : tris) m.indices.insert(m.indices.end(), tri.begin(), tri.end());
  return m;
}

}  // namespace

TEST_CASE("triangle order: a shuffled mesh comes out local, whatever order it was stored in",
          "[scene]") {
  const scene::Mesh rows = grid(64);
  const scene::Mesh random = shuffled(rows, 7);
  // A random order steps about half the grid's width (~0.52 x 64 cells, the
  // mean distance of two random points in a square) from one triangle to
  // the next.
  REQUIRE(meanStep(random) > 20.0);

  scene::Mesh sortedRandom = random;
  scene::sortTrianglesSpatially(sortedRandom);
  CHECK(canonicalTriangles(sortedRandom) == canonicalTriangles(rows));
  CHECK(sortedRandom.positions == rows.positions);
  // A Z-order curve over a grid steps to a neighbouring cell most of the
  // time and jumps rarely: its mean step is about one cell (row order:
  // 1.5, with its 64 row jumps). A bound of 2 cells fails any order that is
  // not local, at 10x below the shuffled order's step.
  CHECK(meanStep(sortedRandom) < 2.0);

  // The result depends on the triangles only: the row-ordered and a
  // differently shuffled copy sort to the same index buffer.
  scene::Mesh sortedRows = rows;
  scene::sortTrianglesSpatially(sortedRows);
  scene::Mesh sortedOther = shuffled(rows, 12345);
  scene::sortTrianglesSpatially(sortedOther);
  CHECK(sortedRows.indices == sortedRandom.indices);
  CHECK(sortedOther.indices == sortedRandom.indices);
}

TEST_CASE("triangle order: single triangles, flat and coincident centroids are kept", "[scene]") {
  scene::Mesh one = grid(1);
  one.indices.resize(3);
  const auto before = one.indices;
  scene::sortTrianglesSpatially(one);
  CHECK(one.indices == before);
  // Two triangles with the same centroid (a quad's two windings) keep their
  // stored order: equal codes are a stable sort's ties.
  scene::Mesh twoSided = grid(1);
  twoSided.indices = {0, 1, 2, 2, 1, 0};
  scene::sortTrianglesSpatially(twoSided);
  CHECK(twoSided.indices == std::vector<uint32_t>{0, 1, 2, 2, 1, 0});
  twoSided.indices = {2, 1, 0, 0, 1, 2};
  scene::sortTrianglesSpatially(twoSided);
  CHECK(twoSided.indices == std::vector<uint32_t>{2, 1, 0, 0, 1, 2});
}
