#include "penumbra/render/environment_map.h"

#include <cmath>

namespace penumbra::render {

gpu::EnvironmentData environmentInfo(const scene::Environment& env) {
  gpu::EnvironmentData info{};
  const double radians = double(env.rotationDegrees) * (3.14159265358979323846 / 180.0);
  info.width = std::max(env.width, 1u);
  info.height = std::max(env.height, 1u);
  info.cosRotation = float(std::cos(radians));
  info.sinRotation = float(std::sin(radians));
  info.intensity = env.present() ? env.intensity : 0.0f;
  return info;
}

EnvironmentTables buildEnvironmentTables(const scene::Environment& env) {
  EnvironmentTables t;
  t.info = environmentInfo(env);
  if (!env.present()) {
    t.texels = {{0.0f, 0.0f, 0.0f, 0.0f}};
    t.cdf = {1.0f, 1.0f};
    return t;
  }
  const uint32_t w = env.width, h = env.height;
  // Weights in double: the largest map has 2^27 texels.
  std::vector<double> weight(size_t(w) * h);
  std::vector<double> rowSum(h, 0.0);
  double total = 0.0;
  for (uint32_t y = 0; y < h; ++y) {
    const double sinTheta = std::sin((y + 0.5) / h * 3.14159265358979323846);
    for (uint32_t x = 0; x < w; ++x) {
      const glm::vec3 r = env.radiance[size_t(y) * w + x];
      const double wt = (0.2126 * r.x + 0.7152 * r.y + 0.0722 * r.z) * sinTheta;
      weight[size_t(y) * w + x] = wt;
      rowSum[y] += wt;
    }
    total += rowSum[y];
  }
  t.cdf.resize(h + size_t(w) * h);
  double rowsSoFar = 0.0;
  for (uint32_t y = 0; y < h; ++y) {
    rowsSoFar += rowSum[y];
    t.cdf[y] = total > 0.0 ? float(rowsSoFar / total) : float(y + 1) / float(h);
    double columnsSoFar = 0.0;
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      columnsSoFar += weight[i];
      t.cdf[h + i] = rowSum[y] > 0.0 ? float(columnsSoFar / rowSum[y]) : float(x + 1) / float(w);
    }
    // Exactly 1 at each table's end, whatever the rounding: the search's
    // u < 1 always finds an entry.
    t.cdf[h + size_t(y) * w + (w - 1)] = 1.0f;
  }
  t.cdf[h - 1] = 1.0f;
  // Each texel's probability is the one the sampler draws it with: the
  // product of its steps in the float tables, not weight / total. The two
  // differ by the tables' rounding, which for a dim texel beside a bright
  // one is most of its step (a step of 1e-12 after 0.9 is 0 or 6e-8 in
  // float); MIS and the NEE estimate must divide by what was drawn.
  t.texels.resize(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y) {
    const double rowStep = double(t.cdf[y]) - (y > 0 ? double(t.cdf[y - 1]) : 0.0);
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const double columnStep = double(t.cdf[h + i]) - (x > 0 ? double(t.cdf[h + i - 1]) : 0.0);
      const glm::vec3 r = env.radiance[i];
      t.texels[i] = {r.x, r.y, r.z, float(rowStep * columnStep)};
    }
  }
  return t;
}

}  // namespace penumbra::render
