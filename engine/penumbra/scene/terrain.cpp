#include "penumbra/scene/terrain.h"

#include <fmt/format.h>

#include <cmath>
#include <new>

#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

// A 32-bit integer hash (Wang / Jenkins mix) of a lattice point, in [0, 1).
float latticeValue(int32_t x, int32_t z, uint32_t seed) {
  uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(z) * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

float smooth(float t) {
  return t * t * (3.0f - 2.0f * t);
}

float valueNoise(float x, float z, uint32_t seed) {
  const float fx = std::floor(x), fz = std::floor(z);
  const int32_t ix = int32_t(fx), iz = int32_t(fz);
  const float tx = smooth(x - fx), tz = smooth(z - fz);
  const float a = latticeValue(ix, iz, seed), b = latticeValue(ix + 1, iz, seed);
  const float c = latticeValue(ix, iz + 1, seed), d = latticeValue(ix + 1, iz + 1, seed);
  const float top = a + (b - a) * tx, bottom = c + (d - c) * tx;
  return 2.0f * (top + (bottom - top) * tz) - 1.0f;
}

}  // namespace

float fractalNoise(float x, float z, uint32_t octaves, uint32_t seed) {
  float sum = 0.0f, amplitude = 0.5f, frequency = 1.0f, norm = 0.0f;
  for (uint32_t o = 0; o < octaves; ++o) {
    sum += amplitude * valueNoise(x * frequency, z * frequency, seed + o);
    norm += amplitude;
    amplitude *= 0.5f;
    frequency *= 2.0f;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}

Mesh makeTerrain(const TerrainDesc& desc, uint32_t material) {
  const uint64_t n = desc.resolution;
  if (n < 2 || n * n > (uint64_t(1) << 31))
    throw Error(fmt::format("terrain: resolution {} must be 2..46340", desc.resolution));
  if (!(desc.size > 0.0f) || !std::isfinite(desc.height))
    throw Error("terrain: size must be positive and height finite");
  Mesh mesh;
  mesh.name = fmt::format("terrain {}x{}", n, n);
  mesh.material = material;
  try {
    mesh.positions.reserve(n * n);
    mesh.indices.reserve((n - 1) * (n - 1) * 6);
  } catch (const std::bad_alloc&) {
    const double bytes =
        double(n * n * sizeof(glm::vec3) + (n - 1) * (n - 1) * 6 * sizeof(uint32_t));
    throw Error(
        fmt::format("terrain: {}x{} needs {:.1f} GiB for its vertices and indices alone, more than "
                    "this process "
                    "can allocate; lower \"resolution\"",
                    n, n, bytes / double(1ull << 30)));
  }
  const float step = desc.size / float(n - 1);
  // Five noise features across the terrain, whatever its size.
  const float noiseScale = 5.0f / desc.size;
  for (uint64_t j = 0; j < n; ++j) {
    for (uint64_t i = 0; i < n; ++i) {
      const float x = -0.5f * desc.size + step * float(i);
      const float z = -0.5f * desc.size + step * float(j);
      const float y =
          desc.height * fractalNoise(x * noiseScale, z * noiseScale, desc.octaves, desc.seed);
      mesh.positions.emplace_back(x, y, z);
    }
  }
  for (uint64_t j = 0; j + 1 < n; ++j) {
    for (uint64_t i = 0; i + 1 < n; ++i) {
      const uint32_t a = uint32_t(j * n + i), b = a + 1, c = uint32_t(a + n), d = c + 1;
      // x right, z forward: (a, c, b) winds counter-clockwise seen from +y.
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  }
  return mesh;
}

}  // namespace penumbra::scene
