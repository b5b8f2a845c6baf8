// Next-event estimation on emissive triangles. Needs the entry point's
// loadEmissiveTriangle(index).
#ifndef PENUMBRA_LIGHTS_HLSLI
#define PENUMBRA_LIGHTS_HLSLI
#include "sampling.hlsli"

struct LightSample {
  float3 position;
  float3 normal;    // front face of the emitter
  float3 radiance;
  float pdfArea;    // per unit area, including the choice of triangle
};

// Chooses a triangle in proportion to its emitted power (binary search of the
// cumulative probabilities), then a uniform point on it.
LightSample sampleEmissiveTriangles(uint count, float u0, float u1, float u2) {
  uint lo = 0u;
  uint hi = count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (loadEmissiveTriangle(mid).radiance.w > u0)
      hi = mid;
    else
      lo = mid + 1u;
  }
  EmissiveTriangle tri = loadEmissiveTriangle(lo);
  float2 b = sampleUniformTriangle(u1, u2);
  LightSample s;
  s.position = barycentricInterpolate(tri.p0.xyz, tri.p1.xyz, tri.p2.xyz, b);
  s.normal = normalize(cross(tri.p1.xyz - tri.p0.xyz, tri.p2.xyz - tri.p0.xyz));
  s.radiance = tri.radiance.xyz;
  s.pdfArea = tri.p0.w / tri.p1.w;
  return s;
}

// Area density with which sampleEmissiveTriangles picks a point on triangle `index`.
float emissiveTrianglePdfArea(uint index) {
  EmissiveTriangle tri = loadEmissiveTriangle(index);
  return tri.p0.w / tri.p1.w;
}

// Converts an area density at a point seen at `distance` under `cosLight` to
// a solid-angle density at the receiver.
float areaToSolidAnglePdf(float pdfArea, float distance, float cosLight) {
  return cosLight > 0.0 ? pdfArea * distance * distance / cosLight : 0.0;
}

#endif
