// Spheres, analytic (DXR twin of glsl/implicit_sphere.rint).
// InstanceID() is the family's first ImplicitData and PrimitiveIndex()
// the object within it.
#include "path_trace_common.hlsli"
#include "implicit.hlsli"

[shader("intersection")]
void main() {
  ImplicitData object = loadImplicit(InstanceID() + PrimitiveIndex());
  ObjectRay ray =
      objectRay(object, WorldRayOrigin(), WorldRayDirection(), RayTMin(), RayTCurrent());
  ImplicitHit hit = intersectSphere(ray.origin, ray.direction, object.shape.x, ray.sMin, ray.sMax);
  if (hit.s >= 0.0) {
    ImplicitAttributes attributes;
    attributes.objectNormal = hit.normal;
    ReportHit(hit.s * ray.tPerS, 0u, attributes);
  }
}
