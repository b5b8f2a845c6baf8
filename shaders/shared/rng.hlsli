// Deterministic per-pixel random numbers: a PCG hash of (pixel, sample index,
// seed) starts a stream, and a PCG-RXS-M-XS step advances it (Jarzynski &
// Olano 2020, "Hash Functions for GPU Rendering"). The same inputs give the
// same numbers on every device and backend.
#ifndef PENUMBRA_RNG_HLSLI
#define PENUMBRA_RNG_HLSLI

uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

struct Rng {
  uint state;
};

// `sampleIndex` counts samples of this pixel over the whole accumulation, so
// frame N's samples continue where frame N-1's stopped.
Rng rngCreate(uint2 pixel, uint sampleIndex, uint seed) {
  Rng r;
  r.state = pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(sampleIndex + pcgHash(seed))));
  return r;
}

// Uniform in [0, 1): 24 random bits, so 1.0 is never returned.
float rngNext(inout Rng r) {
  r.state = r.state * 747796405u + 2891336453u;
  uint word = ((r.state >> ((r.state >> 28u) + 4u)) ^ r.state) * 277803737u;
  word = (word >> 22u) ^ word;
  return float(word >> 8u) * (1.0 / 16777216.0);
}

#endif
