// Closest hit of every implicit family (DXR twin of glsl/implicit.rchit): the
// intersection shader already found the distance and the object-space normal.
#include "path_trace_common.hlsli"
#include "implicit.hlsli"

[shader("closesthit")]
void main(inout HitRecord hit, in ImplicitAttributes attributes) {
  hit.hitT = RayTCurrent();
  hit.instance = 0u;
  hit.primitive = PT_HIT_IMPLICIT | (InstanceID() + PrimitiveIndex());
  hit.attributes = attributes.objectNormal;
}
