#version 460
#extension GL_GOOGLE_include_directive : require
#include "hlsl_prelude.glsl"
#include "bindings.hlsli"
#include "tonemap.hlsli"

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant, std430) uniform TonemapPush {
  uint2 gSize;
  float gExposure;
  uint gOperator;
};
layout(set = 0, binding = PENUMBRA_T(0), rgba32f) readonly uniform image2D gInput;
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Output { uint gPixels[]; };

void main() {
  uint2 p = gl_GlobalInvocationID.xy;
  if (p.x >= gSize.x || p.y >= gSize.y) return;
  float3 c = imageLoad(gInput, int2(p)).xyz;
  gPixels[p.y * gSize.x + p.x] = tonemapToRgba8(c, gExposure, gOperator);
}
