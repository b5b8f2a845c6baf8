#include "penumbra/scene/triangle_order.h"

#include <algorithm>
#include <numeric>

namespace penumbra::scene {
namespace {

// The low 10 bits of v, spread to every third bit.
uint32_t spreadBits(uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

}  // namespace

void sortTrianglesSpatially(Mesh& mesh) {
  const size_t count = mesh.indices.size() / 3;
  if (count < 2) return;
  std::vector<glm::vec3> centroids(count);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (size_t t = 0; t < count; ++t) {
    const glm::vec3 c =
        (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
         mesh.positions[mesh.indices[3 * t + 2]]) /
        3.0f;
    centroids[t] = c;
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  }
  const glm::vec3 extent = hi - lo;
  std::vector<uint32_t> codes(count);
  for (size_t t = 0; t < count; ++t) {
    uint32_t code = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const float u = extent[axis] > 0.0f ? (centroids[t][axis] - lo[axis]) / extent[axis] : 0.0f;
      const uint32_t cell = uint32_t(std::clamp(u * 1024.0f, 0.0f, 1023.0f));
      code |= spreadBits(cell) << (2 - axis);
    }
    codes[t] = code;
  }
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return codes[a] < codes[b]; });
  std::vector<uint32_t> sorted;
  sorted.reserve(mesh.indices.size());
  for (uint32_t t : order)
    sorted.insert(sorted.end(), mesh.indices.begin() + 3 * t, mesh.indices.begin() + 3 * t + 3);
  mesh.indices = std::move(sorted);
}

}  // namespace penumbra::scene
