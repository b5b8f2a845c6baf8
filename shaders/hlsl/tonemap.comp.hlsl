// Tone mapping to RGBA8 (DXC twin of glsl/tonemap.comp), compiled -T cs_6_3.
#include "bindings.hlsli"
#include "tonemap.hlsli"

struct TonemapPush {
  uint2 size;
  float exposure;
  uint toneOperator;
};
[[vk::push_constant]] ConstantBuffer<TonemapPush> gPush : PENUMBRA_PUSH_CONSTANTS;
Texture2D<float4> gInput : register(t0);        // PENUMBRA_T(0) in the GLSL twin
RWStructuredBuffer<uint> gPixels : register(u0);  // PENUMBRA_U(0)

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint2 p = id.xy;
  if (p.x >= gPush.size.x || p.y >= gPush.size.y) return;
  float3 c = gInput.Load(int3(int2(p), 0)).xyz;
  gPixels[p.y * gPush.size.x + p.x] = tonemapToRgba8(c, gPush.exposure, gPush.toneOperator);
}
