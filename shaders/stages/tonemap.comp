// Tone mapping to RGBA8 pixels for PNG files (engine/penumbra/render/tonemapper.h).
#include "display_shared.h"
#include "tonemap.hlsli"

PT_PUSH_CONSTANTS(TonemapPush, tonemapPush);
PT_TEXTURE(gInput, TM_T_INPUT);
PT_RW_BUFFER(uint, gPixels, TM_U_OUTPUT);

PT_COMPUTE(main, 8, 8) {
  TonemapPush push = tonemapPush();
  uint2 p = PT_DISPATCH_THREAD_ID.xy;
  if (p.x >= push.width || p.y >= push.height) return;
  float3 c = PT_LOAD_TEXTURE(gInput, p).xyz;
  gPixels[p.y * push.width + p.x] = tonemapToRgba8(c, push.exposure, push.toneOperator);
}
