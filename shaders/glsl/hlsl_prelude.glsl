// Maps the HLSL dialect of shaders/shared onto GLSL (docs/ARCHITECTURE.md, "Shaders"): include
// first in every GLSL entry point, before any shared header.
#ifndef PENUMBRA_HLSL_PRELUDE
#define PENUMBRA_HLSL_PRELUDE
#define float2 vec2
#define float3 vec3
#define float4 vec4
#define int2 ivec2
#define int3 ivec3
#define int4 ivec4
#define uint2 uvec2
#define uint3 uvec3
#define uint4 uvec4
#define static
#define lerp mix
#define frac fract
#define rsqrt inversesqrt
#define atan2 atan
#define asuint floatBitsToUint
#define reversebits bitfieldReverse
#define asint floatBitsToInt
float asfloat(uint x) { return uintBitsToFloat(x); }
float asfloat(int x) { return intBitsToFloat(x); }
float3 asfloat(uint3 x) { return uintBitsToFloat(x); }
float3 asfloat(int3 x) { return intBitsToFloat(x); }
float saturate(float x) { return clamp(x, 0.0, 1.0); }
float3 saturate(float3 x) { return clamp(x, float3(0.0, 0.0, 0.0), float3(1.0, 1.0, 1.0)); }
#endif
