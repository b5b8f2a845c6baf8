// The procedural quads and boxes that analytic render tests are built from:
// their winding decides which side emits and which way Whitted and the path
// tracer see "entering" glass, so it is checked, not assumed.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <map>
#include <utility>

#include "penumbra/scene/mesh_builders.h"

using namespace penumbra;
using Catch::Approx;

namespace {
glm::vec3 corner(const scene::Mesh& m, size_t triangle, int k) {
  return m.positions[m.indices[triangle * 3 + k]];
}
glm::vec3 areaNormal(const scene::Mesh& m, size_t t) {
  return 0.5f * glm::cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0));
}
// Signed volume by the divergence theorem: positive when the front faces
// point outwards of a closed mesh.
double signedVolume(const scene::Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    v += glm::dot(corner(m, t, 0), glm::cross(corner(m, t, 1), corner(m, t, 2))) / 6.0;
  return v;
}
// Closed and consistently wound: every directed edge appears once and its
// reverse once.
bool isClosedManifold(const scene::Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) ++edges[{m.indices[t * 3 + k], m.indices[t * 3 + (k + 1) % 3]}];
  for (const auto& [e, n] : edges) {
    if (n != 1) return false;
    auto reverse = edges.find({e.second, e.first});
    if (reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}
}  // namespace

TEST_CASE("a quad covers its parallelogram and faces cross(u, v)", "[scene]") {
  const glm::vec3 origin(1, 2, 3), u(2, 0, 0), v(0.5f, 0, -3);
  const auto q = scene::makeQuad(origin, u, v, 4);
  REQUIRE(q.material == 4u);
  REQUIRE(q.triangleCount() == 2u);
  const glm::vec3 expectedArea = glm::cross(u, v);  // |u x v| = 6, pointing +y
  glm::vec3 total(0.0f);
  for (size_t t = 0; t < 2; ++t) {
    const glm::vec3 n = areaNormal(q, t);
    REQUIRE(glm::dot(glm::normalize(n), glm::normalize(expectedArea)) == Approx(1.0f));
    total += n;
  }
  REQUIRE(total.y == Approx(expectedArea.y));
  REQUIRE(glm::length(total) == Approx(glm::length(expectedArea)));
  // The four corners, in order.
  REQUIRE(q.positions.size() == 4u);
  REQUIRE(q.positions[0] == origin);
  REQUIRE(q.positions[1] == origin + u);
  REQUIRE(q.positions[2] == origin + u + v);
  REQUIRE(q.positions[3] == origin + v);
}

TEST_CASE("a box is closed, has the right area and volume, and faces out or in", "[scene]") {
  const glm::vec3 lo(-1, 0, 2), hi(2, 0.5f, 6);  // 3 x 0.5 x 4
  for (bool inward : {false, true}) {
    INFO("inward facing " << inward);
    const auto box = scene::makeBox(lo, hi, inward, 1);
    REQUIRE(box.material == 1u);
    REQUIRE(box.triangleCount() == 12u);
    REQUIRE(isClosedManifold(box));
    double area = 0;
    const glm::vec3 centre = 0.5f * (lo + hi);
    for (size_t t = 0; t < 12; ++t) {
      const glm::vec3 n = areaNormal(box, t);
      area += glm::length(n);
      const glm::vec3 mid = (corner(box, t, 0) + corner(box, t, 1) + corner(box, t, 2)) / 3.0f;
      // Axis-aligned faces: the normal is one axis, pointing away from (or to) the centre.
      const glm::vec3 axis = glm::normalize(n);
      REQUIRE(std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z) == Approx(1.0f));
      REQUIRE((glm::dot(n, mid - centre) > 0.0f) == !inward);
    }
    REQUIRE(area == Approx(2.0 * (3 * 0.5 + 0.5 * 4 + 3 * 4)));
    REQUIRE(signedVolume(box) == Approx(inward ? -6.0 : 6.0));
    for (const auto& p : box.positions) {
      REQUIRE((p.x == lo.x || p.x == hi.x));
      REQUIRE((p.y == lo.y || p.y == hi.y));
      REQUIRE((p.z == lo.z || p.z == hi.z));
    }
  }
}
