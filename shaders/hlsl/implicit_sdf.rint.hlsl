// Torus, rounded box and blend, sphere traced (DXR twin of glsl/implicit_sdf.rint).
// InstanceID() is the family's first ImplicitData and PrimitiveIndex()
// the object within it.
#include "path_trace_common.hlsli"
#include "implicit.hlsli"
#include "sdf.hlsli"

float implicitSdf(ImplicitData o, float3 p) { return sdfObjectDistance(o, p); }
#include "sphere_tracing.hlsli"

[shader("intersection")]
void main() {
  ImplicitData object = loadImplicit(InstanceID() + PrimitiveIndex());
  ObjectRay ray =
      objectRay(object, WorldRayOrigin(), WorldRayDirection(), RayTMin(), RayTCurrent());
  // Shadow rays skip the closest-hit shader, so they need no normal.
  bool needNormal = (RayFlags() & RAY_FLAG_SKIP_CLOSEST_HIT_SHADER) == 0u;
  ImplicitHit hit = sphereTrace(object, ray, needNormal);
  if (hit.s >= 0.0) {
    ImplicitAttributes attributes;
    attributes.objectNormal = hit.normal;
    ReportHit(hit.s * ray.tPerS, 0u, attributes);
  }
}
