#version 460
#extension GL_GOOGLE_include_directive : require
#include "path_trace_common.glsl"

layout(location = PT_PAYLOAD_RADIANCE) rayPayloadInEXT SurfaceHit gHit;
hitAttributeEXT float2 gBarycentrics;

void main() {
  InstanceData instance = gInstances[gl_InstanceCustomIndexEXT];
  uint base = instance.firstIndex + 3u * uint(gl_PrimitiveID);
  uint i0 = gIndices[base] + instance.firstVertex;
  uint i1 = gIndices[base + 1u] + instance.firstVertex;
  uint i2 = gIndices[base + 2u] + instance.firstVertex;
  float3 p0 = gVertices[i0].xyz;
  float3 p1 = gVertices[i1].xyz;
  float3 p2 = gVertices[i2].xyz;
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, gBarycentrics);
  // Normals transform with the inverse transpose: n * WorldToObject (row
  // vector); tangents, like positions, with ObjectToWorld.
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  mat3 normalToWorld = mat3(gl_WorldToObjectEXT);
  gHit.position = gl_ObjectToWorldEXT * float4(objectPosition, 1.0);
  gHit.geometricNormal = normalize(objectNormal * normalToWorld);
  float3 vertexNormal =
      barycentricInterpolate(gNormals[i0].xyz, gNormals[i1].xyz, gNormals[i2].xyz, gBarycentrics);
  gHit.shadingNormal = resolveShadingNormal(vertexNormal * normalToWorld, gHit.geometricNormal);
  float3 vertexTangent =
      barycentricInterpolate(gTangents[i0].xyz, gTangents[i1].xyz, gTangents[i2].xyz, gBarycentrics);
  gHit.shadingTangent =
      resolveShadingTangent(gl_ObjectToWorldEXT * float4(vertexTangent, 0.0), gHit.shadingNormal);
  gHit.uv = barycentricInterpolate2(gTexCoords[i0].xy, gTexCoords[i1].xy, gTexCoords[i2].xy, gBarycentrics);
  gHit.hitT = gl_HitTEXT;
  gHit.instanceIndex = uint(gl_InstanceCustomIndexEXT);
  gHit.primitiveIndex = uint(gl_PrimitiveID);
}
