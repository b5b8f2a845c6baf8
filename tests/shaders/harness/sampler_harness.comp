#version 460
// Draws the path tracer's random numbers (shaders/shared/rng.hlsli) for
// tests/shaders/test_sampler.cpp: item i is sample firstIndex + i % samples
// of pixel firstPixel + (i / samples, 0); it writes `dimensions` numbers.
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
#include "rng.hlsli"

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push {
  uint gKind;  // RNG_SAMPLER_*
  uint gSeed;
  uint gFirstIndex;
  uint gSamples;
  uint2 gFirstPixel;
  uint gCount;
  uint gDimensions;
};
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { float gResults[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  uint2 pixel = gFirstPixel + uint2(i / gSamples, 0u);
  Rng rng = rngCreate(pixel, gFirstIndex + i % gSamples, gSeed, gKind);
  for (uint d = 0u; d < gDimensions; d += 1u) gResults[i * gDimensions + d] = rngNext(rng);
}
