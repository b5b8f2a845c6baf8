#version 460
#extension GL_GOOGLE_include_directive : require
#include "path_trace_common.glsl"
#include "implicit.hlsli"

// Closest hit of every implicit family: the intersection shader already
// found the distance and the object-space normal.
layout(location = PT_PAYLOAD_RADIANCE) rayPayloadInEXT SurfaceHit gHit;
hitAttributeEXT ImplicitAttributes gAttributes;

void main() {
  ImplicitData object = loadImplicit(uint(gl_InstanceCustomIndexEXT) + uint(gl_PrimitiveID));
  gHit = implicitSurfaceHit(object, gl_WorldRayOriginEXT, gl_WorldRayDirectionEXT, gl_HitTEXT,
                            gAttributes.objectNormal);
}
