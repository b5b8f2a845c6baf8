// The sphere-traced families' intersection: the stage defines
//   float implicitSdf(ImplicitData object, float3 p);
// before including this file.
#include "sphere_tracing.hlsli"

ImplicitHit intersectImplicit(ImplicitData object, ObjectRay ray) {
  // Shadow rays skip the closest-hit shader, so they need no normal.
  return sphereTrace(object, ray, !PT_INCOMING_RAY_SKIPS_CLOSEST_HIT);
}
#include "implicit_intersection.hlsli"
