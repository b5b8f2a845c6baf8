// Host-side spellings of the shading language's vector types, so *_shared.h
// headers compile unchanged as C++ and as HLSL/GLSL. Only 4-component vectors
// cross the boundary (16-byte aligned in std430 and in C++ alike).
#pragma once
#include <cstdint>

namespace penumbra::gpu {
using uint = uint32_t;
struct float4 {
  float x = 0, y = 0, z = 0, w = 0;
};
struct uint4 {
  uint x = 0, y = 0, z = 0, w = 0;
};
// Only in what never sits in a buffer (payloads_shared.h): a ray payload's
// and a hit's attributes are packed, not std430.
struct float3 {
  float x = 0, y = 0, z = 0;
};
static_assert(sizeof(float4) == 16 && sizeof(uint4) == 16 && sizeof(float3) == 12);
}  // namespace penumbra::gpu
