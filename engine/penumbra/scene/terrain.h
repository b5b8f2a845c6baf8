#pragma once
// A procedural heightfield: the high-polygon mesh of the performance scene,
// generated instead of shipped (millions of triangles, no data files).
#include "penumbra/scene/scene.h"

namespace penumbra::scene {

struct TerrainDesc {
  uint32_t resolution = 1024;  // vertices per side; 2 (resolution - 1)^2 triangles
  float size = 20.0f;          // side length, centred on the origin in x and z
  float height = 1.5f;         // peak-to-valley amplitude scale
  uint32_t octaves = 6;        // of the fractal value noise
  uint32_t seed = 1;
};

// Deterministic for a given desc: y = height * fBm(x, z); the counter-clockwise
// side faces +y. Throws penumbra::Error if the mesh would not fit 32-bit indices.
Mesh makeTerrain(const TerrainDesc& desc, uint32_t material);

// Fractal value noise in [-1, 1] (sum of octaves of smoothly interpolated
// lattice hashes), exposed for tests.
float fractalNoise(float x, float z, uint32_t octaves, uint32_t seed);

}  // namespace penumbra::scene
