// What a closest-hit shader reports back to the integrator (the radiance
// ray's payload). World space throughout.
#ifndef PENUMBRA_SURFACE_HIT_HLSLI
#define PENUMBRA_SURFACE_HIT_HLSLI

struct SurfaceHit {
  float3 position;
  float hitT;             // < 0: the ray missed everything
  float3 geometricNormal; // unit, front side by counter-clockwise winding
  uint instanceIndex;
  uint primitiveIndex;
};

SurfaceHit surfaceMiss() {
  SurfaceHit h;
  h.position = float3(0.0, 0.0, 0.0);
  h.hitT = -1.0;
  h.geometricNormal = float3(0.0, 0.0, 1.0);
  h.instanceIndex = 0u;
  h.primitiveIndex = 0u;
  return h;
}

// Interpolates a triangle hit from its object-space corners and the hit's
// barycentrics (b1, b2); the entry point supplies the object-to-world transform.
float3 barycentricInterpolate(float3 p0, float3 p1, float3 p2, float2 b) {
  return p0 * (1.0 - b.x - b.y) + p1 * b.x + p2 * b.y;
}

#endif
