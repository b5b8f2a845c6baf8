// Sphere tracing (Hart 1996, "Sphere Tracing: A Geometric Method for the
// Antialiased Ray Tracing of Implicit Surfaces") of a 1-Lipschitz distance
// bound, in object space. The entry point defines, before including this:
//   float implicitSdf(ImplicitData o, float3 p);
#ifndef PENUMBRA_SPHERE_TRACING_HLSLI
#define PENUMBRA_SPHERE_TRACING_HLSLI
#include "implicit.hlsli"

// Gradient direction by the tetrahedron technique (four samples instead of
// six central differences, Quilez), at the scale of the hit tolerance so it
// sees the surface that was hit rather than detail below it. Zero where the
// field is flat.
float3 sdfGradient(ImplicitData o, float3 p, float h) {
  float3 k0 = float3(1.0, -1.0, -1.0);
  float3 k1 = float3(-1.0, -1.0, 1.0);
  float3 k2 = float3(-1.0, 1.0, -1.0);
  float3 k3 = float3(1.0, 1.0, 1.0);
  float3 g = k0 * implicitSdf(o, p + h * k0) + k1 * implicitSdf(o, p + h * k1) +
             k2 * implicitSdf(o, p + h * k2) + k3 * implicitSdf(o, p + h * k3);
  float len = length(g);
  if (len > 0.0) return g / len;
  return zero3();
}

// March from where the ray enters the object's bounds (boundsMin/Max, padded
// by the host so that entry point is clear of the surface) until the
// distance drops below the tolerance. Steps are at least the tolerance, so a
// step may end just past the surface; the distance is then negative and
// still reports the hit. info.z distance evaluations without a hit is a
// miss, as is leaving the bounds or passing sMax.
ImplicitHit sphereTrace(ImplicitData o, ObjectRay ray) {
  float tolerance = o.boundsMin.w;
  SlabSpan span = intersectSlabs(ray.origin, ray.direction, o.boundsMin.xyz, o.boundsMax.xyz);
  float s = max(ray.sMin, span.sEnter);
  float sEnd = min(ray.sMax, span.sExit);
  if (!(s <= sEnd)) return implicitMiss();

  float side = 1.0;  // -1 while marching inside the object
  bool leaving = false;
  for (uint i = 0u; i < o.info.z; i += 1u) {
    float3 p = ray.origin + s * ray.direction;
    float value = implicitSdf(o, p);
    if (i == 0u) {
      if (abs(value) < tolerance) {
        // Starting on the surface (a ray spawned at an earlier hit): the ray
        // belongs to the side it points into and must first get clear of
        // the surface, or it would hit it again at s = 0.
        side = dot(sdfGradient(o, p, tolerance), ray.direction) >= 0.0 ? 1.0 : -1.0;
        leaving = true;
      } else {
        side = value < 0.0 ? -1.0 : 1.0;
      }
    }
    float clearance = side * value;
    if (leaving) {
      leaving = clearance < tolerance;
    } else if (clearance < tolerance) {
      // One more step of the signed distance lands nearer the surface
      // (forward if short of it, back if past it).
      float sHit = clamp(s + clearance, ray.sMin, sEnd);
      float3 normal = sdfGradient(o, ray.origin + sHit * ray.direction, tolerance);
      if (dot(normal, normal) == 0.0) normal = -ray.direction;
      return implicitHitAt(sHit, normal);
    }
    s += max(abs(clearance), tolerance);
    if (s > sEnd) return implicitMiss();
  }
  return implicitMiss();
}

#endif
