#version 460
// The viewer's display pass: the accumulated HDR image, scaled to the window
// (nearest texel, so render scale 1 is a 1:1 copy), tone-mapped to RGBA8.
#extension GL_GOOGLE_include_directive : require
#include "hlsl_prelude.glsl"
#include "bindings.hlsli"
#include "tonemap.hlsli"

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant, std430) uniform DisplayPush {
  uint2 gSourceSize;
  uint2 gTargetSize;
  float gExposure;
  uint gOperator;
  uint gChannels;
};
layout(set = 0, binding = PENUMBRA_T(0), rgba32f) readonly uniform image2D gInput;
layout(set = 0, binding = PENUMBRA_U(0), rgba8) writeonly uniform image2D gOutput;

void main() {
  uint2 p = gl_GlobalInvocationID.xy;
  if (p.x >= gTargetSize.x || p.y >= gTargetSize.y) return;
  uint2 source = min((p * gSourceSize) / gTargetSize, gSourceSize - uint2(1, 1));
  float3 c = displayChannels(imageLoad(gInput, int2(source)), gChannels);
  imageStore(gOutput, int2(p), float4(tonemapToDisplay(c, gExposure, gOperator), 1.0));
}
