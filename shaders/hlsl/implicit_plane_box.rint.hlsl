// Planes and boxes, analytic slabs (DXR twin of glsl/implicit_plane_box.rint).
// InstanceID() is the family's first ImplicitData and PrimitiveIndex()
// the object within it.
#include "path_trace_common.hlsli"
#include "implicit.hlsli"

[shader("intersection")]
void main() {
  ImplicitData object = loadImplicit(InstanceID() + PrimitiveIndex());
  ObjectRay ray =
      objectRay(object, WorldRayOrigin(), WorldRayDirection(), RayTMin(), RayTCurrent());
  ImplicitHit hit;
  if (object.info.x == IMPLICIT_PLANE)
    hit = intersectPlane(ray.origin, ray.direction, object.shape.xy, ray.sMin, ray.sMax);
  else
    hit = intersectBox(ray.origin, ray.direction, object.shape.xyz, ray.sMin, ray.sMax);
  if (hit.s >= 0.0) {
    ImplicitAttributes attributes;
    attributes.objectNormal = hit.normal;
    ReportHit(hit.s * ray.tPerS, 0u, attributes);
  }
}
