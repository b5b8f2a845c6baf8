// The viewer's display pass (DXC twin of glsl/display.comp), compiled -T cs_6_3.
#include "bindings.hlsli"
#include "tonemap.hlsli"

struct DisplayPush {
  uint2 sourceSize;
  uint2 targetSize;
  float exposure;
  uint toneOperator;
  uint channels;
};
[[vk::push_constant]] ConstantBuffer<DisplayPush> gPush : PENUMBRA_PUSH_CONSTANTS;
Texture2D<float4> gInput : register(t0);          // PENUMBRA_T(0) in the GLSL twin
RWTexture2D<unorm float4> gOutput : register(u0);  // PENUMBRA_U(0)

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint2 p = id.xy;
  if (p.x >= gPush.targetSize.x || p.y >= gPush.targetSize.y) return;
  uint2 source = min((p * gPush.sourceSize) / gPush.targetSize, gPush.sourceSize - uint2(1, 1));
  float3 c = displayChannels(gInput.Load(int3(int2(source), 0)), gPush.channels);
  gOutput[p] = float4(tonemapToDisplay(c, gPush.exposure, gPush.toneOperator), 1.0);
}
