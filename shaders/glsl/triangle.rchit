#version 460
#extension GL_GOOGLE_include_directive : require
#include "path_trace_common.glsl"

// Triangle closest hit: which triangle and where on it. The ray generation
// shader rebuilds the surface (surface_from_record.hlsli).
layout(location = PT_PAYLOAD_RADIANCE) rayPayloadInEXT HitRecord gHit;
hitAttributeEXT float2 gBarycentrics;

void main() {
  gHit.hitT = gl_HitTEXT;
  // A TLAS instance holds one mesh, or (the merged BLAS) one per geometry.
  gHit.instance = uint(gl_InstanceCustomIndexEXT) + uint(gl_GeometryIndexEXT);
  gHit.primitive = uint(gl_PrimitiveID);
  gHit.attributes = float3(gBarycentrics, 0.0);
}
