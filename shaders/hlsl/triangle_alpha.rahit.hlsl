// Alpha any-hit of the triangles' radiance hit group (DXR twin of
// glsl/triangle_alpha.rahit).
#include "alpha_any_hit.hlsli"

[shader("anyhit")]
void main(inout HitRecord hit, in BuiltInTriangleIntersectionAttributes attributes) {
  if (!alphaAnyHitKeeps(attributes)) IgnoreHit();
}
