// The viewer's display pass: the accumulated HDR image, scaled to the window
// (nearest texel, so render scale 1 is a 1:1 copy), tone-mapped to RGBA8.
#include "display_shared.h"
#include "tonemap.hlsli"

PT_PUSH_CONSTANTS(DisplayPush, displayPush);
PT_TEXTURE(gInput, TM_T_INPUT);
PT_RW_TEXTURE_RGBA8(gOutput, TM_U_OUTPUT);

PT_COMPUTE(main, 8, 8) {
  DisplayPush push = displayPush();
  uint2 p = PT_DISPATCH_THREAD_ID.xy;
  if (p.x >= push.targetWidth || p.y >= push.targetHeight) return;
  uint2 sourceSize = uint2(push.sourceWidth, push.sourceHeight);
  uint2 source = min((p * sourceSize) / uint2(push.targetWidth, push.targetHeight), sourceSize - uint2(1, 1));
  float3 c = displayChannels(PT_LOAD_TEXTURE(gInput, source), push.channels);
  PT_STORE_RW_TEXTURE(gOutput, p, float4(tonemapToDisplay(c, push.exposure, push.toneOperator), 1.0));
}
