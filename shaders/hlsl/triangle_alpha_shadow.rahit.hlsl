// Alpha any-hit of the triangles' shadow hit group (DXR twin of
// glsl/triangle_alpha_shadow.rahit): the shadow ray's payload.
#include "alpha_any_hit.hlsli"

[shader("anyhit")]
void main(inout ShadowPayload shadow, in BuiltInTriangleIntersectionAttributes attributes) {
  if (!alphaAnyHitKeeps(attributes)) IgnoreHit();
}
