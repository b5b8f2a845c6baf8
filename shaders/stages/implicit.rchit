// Closest hit of every implicit family: the intersection shader already
// found the distance and the object-space normal; the ray generation shader
// rebuilds the surface (surface_from_record.hlsli).
#include "path_trace_resources.hlsli"
#include "implicit.hlsli"

PT_CLOSEST_HIT(main, HitRecord, hit, ImplicitAttributes, attributes) {
  hit.hitT = PT_HIT_T;
  hit.instance = 0u;
  hit.primitive = PT_HIT_IMPLICIT | (PT_INSTANCE_ID + PT_PRIMITIVE_INDEX);
  hit.attributes = attributes.objectNormal;
}
