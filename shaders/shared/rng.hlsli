// Deterministic per-pixel random numbers, from one of two samplers:
//
// RNG_SAMPLER_RANDOM: a PCG hash of (pixel, sample index, seed) starts a
//   stream, and a PCG-RXS-M-XS step advances it (Jarzynski & Olano 2020,
//   "Hash Functions for GPU Rendering").
// RNG_SAMPLER_SOBOL: Owen-scrambled Sobol points, padded by dimension pairs
//   (Burley 2020, "Practical Hash-based Owen Scrambling"). Dimensions 2k and
//   2k+1 of a path are the first two Sobol dimensions (a (0,2)-sequence) at
//   the sample index shuffled by a nested uniform scramble seeded by (pixel,
//   seed, k), each coordinate then Owen-scrambled with its own seed. Any
//   aligned run of 2^m samples of a pixel, the first 2^m included, is then a
//   (0,m,2)-net in every pair, whatever the spp, so a progressive
//   accumulation keeps the stratification; the shuffle and scrambles
//   decorrelate pairs from one another and pixels from their neighbours.
//
// The same inputs give the same numbers on every device and backend.
#ifndef PENUMBRA_RNG_HLSLI
#define PENUMBRA_RNG_HLSLI

// RNG_SAMPLER_* come from path_tracer_shared.h, included before.

uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

struct Rng {
  uint state;      // random: the PCG state; sobol: the pixel's scramble seed
  uint index;      // sobol: the sample index
  uint dimension;  // sobol: the next dimension
  uint kind;       // RNG_SAMPLER_*
};

// `sampleIndex` counts samples of this pixel over the whole accumulation, so
// frame N's samples continue where frame N-1's stopped.
Rng rngCreate(uint2 pixel, uint sampleIndex, uint seed, uint kind) {
  Rng r;
  r.kind = kind;
  r.index = sampleIndex;
  r.dimension = 0u;
  if (kind == RNG_SAMPLER_SOBOL)
    r.state = pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(seed ^ 0x9e3779b9u)));
  else
    r.state = pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(sampleIndex + pcgHash(seed))));
  return r;
}

// A bijection of 32-bit words in which bit k flips as a function of the bits
// below it only: with reversed bits, an Owen scramble. Laine & Karras's
// construction (2011) with Vegdahl's constants and seed-dependent multiplier
// (2021, "Building a Better LK Hash"): Burley's original constants leave
// the shuffles of different dimension pairs visibly correlated.
uint laineKarrasPermutation(uint x, uint seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16u) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// Each bit flips as a function of the bits above it: for a Sobol coordinate
// (most significant bit first) an Owen scramble; for a sample index a
// shuffle that keeps aligned runs of 2^m indices together.
uint nestedUniformScramble(uint x, uint seed) {
  return reversebits(laineKarrasPermutation(reversebits(x), seed));
}

// The first two Sobol dimensions of `index`, bits reversed (least
// significant bit = first binary digit), the form an Owen scramble works on.
// The first dimension is the van der Corput sequence: reversed, the index
// itself. The second's generator matrix is Pascal's triangle mod 2: digit i
// is the parity of the index bits j with (i & j) == i (Lucas), a superset
// sum that five masked shifts compute (rather than a loop over 32 columns).
uint sobolReversed(uint index, uint dimension) {
  if (dimension == 0u) return index;
  index ^= (index >> 1u) & 0x55555555u;
  index ^= (index >> 2u) & 0x33333333u;
  index ^= (index >> 4u) & 0x0f0f0f0fu;
  index ^= (index >> 8u) & 0x00ff00ffu;
  index ^= (index >> 16u) & 0x0000ffffu;
  return index;
}

// 24 bits of a 32-bit fraction, so 1.0 is never returned.
float rngToUnitFloat(uint bits) { return float(bits >> 8u) * (1.0 / 16777216.0); }

// Uniform in [0, 1), the next dimension of this sample.
float rngNext(inout Rng r) {
  if (r.kind == RNG_SAMPLER_SOBOL) {
    uint pair = r.dimension >> 1u;
    uint pairSeed = pcgHash(r.state ^ (pair * 0x68bc21ebu));
    uint shuffled = nestedUniformScramble(r.index, pairSeed);
    // The coordinate's Owen scramble, nestedUniformScramble without the
    // reversal sobolReversed saves.
    uint bits = reversebits(laineKarrasPermutation(sobolReversed(shuffled, r.dimension & 1u),
                                                   pcgHash(pairSeed + 1u + (r.dimension & 1u))));
    r.dimension += 1u;
    return rngToUnitFloat(bits);
  }
  r.state = r.state * 747796405u + 2891336453u;
  uint word = ((r.state >> ((r.state >> 28u) + 4u)) ^ r.state) * 277803737u;
  word = (word >> 22u) ^ word;
  return rngToUnitFloat(word);
}

#endif
