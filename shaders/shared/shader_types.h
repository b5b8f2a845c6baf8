// Host-side spellings of the shading language's vector types, so *_shared.h
// headers compile unchanged as C++ and as HLSL/GLSL. Vectors cross the
// boundary as float4/uint4 rows, or as a float3 followed by a float in one
// 16-byte row (camera_shared.h), which std430, HLSL and C++ lay out alike.
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
// In a buffer only as a float3 + float row (camera_shared.h, FrameConstants);
// ray payloads and hit attributes (payloads_shared.h) are packed, not std430.
struct float3 {
  float x = 0, y = 0, z = 0;
};
struct float2 {
  float x = 0, y = 0;
};
static_assert(sizeof(float4) == 16 && sizeof(uint4) == 16 && sizeof(float3) == 12 &&
              sizeof(float2) == 8);
}  // namespace penumbra::gpu
