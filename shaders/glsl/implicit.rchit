#version 460
#extension GL_GOOGLE_include_directive : require
#include "path_trace_common.glsl"
#include "implicit.hlsli"

// Closest hit of every implicit family: the intersection shader already
// found the distance and the object-space normal; the ray generation shader
// rebuilds the surface (surface_from_record.hlsli).
layout(location = PT_PAYLOAD_RADIANCE) rayPayloadInEXT HitRecord gHit;
hitAttributeEXT ImplicitAttributes gAttributes;

void main() {
  gHit.hitT = gl_HitTEXT;
  gHit.instance = 0u;
  gHit.primitive = PT_HIT_IMPLICIT | (uint(gl_InstanceCustomIndexEXT) + uint(gl_PrimitiveID));
  gHit.attributes = gAttributes.objectNormal;
}
