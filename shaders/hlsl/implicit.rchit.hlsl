// Closest hit of every implicit family (DXR twin of glsl/implicit.rchit): the
// intersection shader already found the distance and the object-space normal.
#include "path_trace_common.hlsli"
#include "implicit.hlsli"

[shader("closesthit")]
void main(inout SurfaceHit hit, in ImplicitAttributes attributes) {
  ImplicitData object = loadImplicit(InstanceID() + PrimitiveIndex());
  hit = implicitSurfaceHit(object, WorldRayOrigin(), WorldRayDirection(), RayTCurrent(),
                           attributes.objectNormal);
}
