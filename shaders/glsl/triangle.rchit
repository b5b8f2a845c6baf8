#version 460
#extension GL_GOOGLE_include_directive : require
#include "path_trace_common.glsl"

layout(location = PT_PAYLOAD_RADIANCE) rayPayloadInEXT SurfaceHit gHit;
hitAttributeEXT float2 gBarycentrics;

void main() {
  InstanceData instance = gInstances[gl_InstanceCustomIndexEXT];
  uint base = instance.firstIndex + 3u * uint(gl_PrimitiveID);
  float3 p0 = gVertices[gIndices[base] + instance.firstVertex].xyz;
  float3 p1 = gVertices[gIndices[base + 1u] + instance.firstVertex].xyz;
  float3 p2 = gVertices[gIndices[base + 2u] + instance.firstVertex].xyz;
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, gBarycentrics);
  // Normals transform with the inverse transpose: n * WorldToObject (row vector).
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  gHit.position = gl_ObjectToWorldEXT * float4(objectPosition, 1.0);
  gHit.geometricNormal = normalize(objectNormal * mat3(gl_WorldToObjectEXT));
  gHit.hitT = gl_HitTEXT;
  gHit.instanceIndex = uint(gl_InstanceCustomIndexEXT);
  gHit.primitiveIndex = uint(gl_PrimitiveID);
}
