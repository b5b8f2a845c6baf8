// Shadow-ray miss (DXR twin of glsl/shadow.rmiss). Shadow rays skip
// closest-hit shaders: reaching the miss shader means nothing blocked the
// segment.
#include "payloads.hlsli"

[shader("miss")]
void main(inout ShadowPayload shadow) { shadow.visible = 1u; }
