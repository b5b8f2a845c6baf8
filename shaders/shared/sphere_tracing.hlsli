// Sphere tracing (Hart 1996, "Sphere Tracing: A Geometric Method for the
// Antialiased Ray Tracing of Implicit Surfaces") of a 1-Lipschitz distance
// bound, in object space. The entry point defines, before including this:
//   float implicitSdf(ImplicitData o, float3 p);
//
// implicitSdf is called from one place only. Ray-tracing compilers inline
// intersection shaders into every trace call of every ray-generation shader
// (lavapipe does), so each extra call site of a distance function multiplies
// pipeline compile time; the normal's samples therefore run through the
// march loop too.
#ifndef PENUMBRA_SPHERE_TRACING_HLSLI
#define PENUMBRA_SPHERE_TRACING_HLSLI
#include "implicit.hlsli"

// Central differences (second-order accurate, unlike the tetrahedron
// technique, whose error grows with h times the curvature) at the scale of
// the hit tolerance, so the normal sees the surface that was hit rather than
// detail below it. The scale does not go below 1e-3 |p|: distances carry
// float rounding of a few 1e-7 |p|, which divided by a smaller step would
// tilt the normal by more than 1e-3.
static const uint kGradientSamples = 6u;

float gradientStep(float tolerance, float3 p) { return max(tolerance, 1e-3 * length(p)); }

// Sample k of the central differences: +-h along axis k / 2.
float3 gradientSampleOffset(uint k, float h) {
  return axisVector(k / 2u, (k & 1u) == 0u ? h : -h);
}

// March from where the ray enters the object's bounds (boundsMin/Max, padded
// by the host so that entry point is clear of the surface) until the
// distance drops below the tolerance. Steps are at least the tolerance, so a
// step may end just past the surface; the distance is then negative and
// still reports the hit. maxSteps distance evaluations without a hit is a
// miss, as is leaving the bounds or passing sMax. Without `needNormal` (a
// shadow ray, which runs no closest-hit shader) the hit's normal is not
// estimated: that saves the gradient's six distance evaluations per hit.
ImplicitHit sphereTrace(ImplicitData o, ObjectRay ray, bool needNormal) {
  float tolerance = o.tolerance;
  uint maxSteps = o.maxSteps;
  SlabSpan span = intersectSlabs(ray.origin, ray.direction, o.boundsMin, o.boundsMax);
  float s = max(ray.sMin, span.sEnter);
  float sEnd = min(ray.sMax, span.sExit);
  if (!(s <= sEnd)) return implicitMiss();

  float side = 1.0;  // -1 while marching inside the object; 0 until known
  bool leaving = false;
  float firstValue = 0.0;
  uint steps = 0u;
  // After a hit: which gradient sample is next (0 = still marching).
  uint gradientSample = 0u;
  float sHit = 0.0;
  float3 hitPoint = zero3();
  float h = 0.0;
  float3 gradient = zero3();
  for (uint i = 0u; i < maxSteps + kGradientSamples; i += 1u) {
    float3 p = ray.origin + s * ray.direction;
    if (gradientSample > 0u) p = hitPoint + gradientSampleOffset(gradientSample - 1u, h);
    float value = implicitSdf(o, p);

    if (gradientSample > 0u) {
      gradient += gradientSampleOffset(gradientSample - 1u, value);
      if (gradientSample == kGradientSamples) {
        if (dot(gradient, gradient) == 0.0) return implicitHitAt(sHit, -ray.direction);
        return implicitHitAt(sHit, normalize(gradient));
      }
      gradientSample += 1u;
      continue;
    }

    if (steps == 0u) {
      firstValue = value;
      if (abs(value) < tolerance) {
        // Starting on the surface (a ray spawned at an earlier hit): the ray
        // belongs to the side it moves into, which the next distance tells,
        // and it must get clear of the surface first, or it would hit it
        // again at s = 0.
        side = 0.0;
        leaving = true;
      } else {
        side = value < 0.0 ? -1.0 : 1.0;
      }
    } else if (side == 0.0) {
      side = value >= firstValue ? 1.0 : -1.0;
    }
    steps += 1u;
    float clearance = side == 0.0 ? abs(value) : side * value;
    if (leaving) {
      leaving = side == 0.0 || clearance < tolerance;
    } else if (clearance < tolerance) {
      // One more step of the signed distance lands nearer the surface
      // (forward if short of it, back if past it); then the normal's samples.
      sHit = clamp(s + clearance, ray.sMin, sEnd);
      if (!needNormal) return implicitHitAt(sHit, -ray.direction);
      hitPoint = ray.origin + sHit * ray.direction;
      h = gradientStep(tolerance, hitPoint);
      gradientSample = 1u;
      continue;
    }
    if (steps >= maxSteps) return implicitMiss();
    s += max(abs(clearance), tolerance);
    if (s > sEnd) return implicitMiss();
  }
  return implicitMiss();
}

#endif
