#version 460
#extension GL_GOOGLE_include_directive : require
#include "path_trace_common.glsl"
#include "effects.h"

layout(location = PT_PAYLOAD_RADIANCE) rayPayloadInEXT SurfaceHit gHit;
hitAttributeEXT float2 gBarycentrics;

void main() {
  InstanceData instance = gInstances[gl_InstanceCustomIndexEXT];
  uint3 v = triangleVertices(instance, uint(gl_PrimitiveID));
  float3 p0 = gVertices[v.x].xyz;
  float3 p1 = gVertices[v.y].xyz;
  float3 p2 = gVertices[v.z].xyz;
  float2 b = gBarycentrics;
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, b);
  // Normals transform with the inverse transpose: n * WorldToObject (row
  // vector); tangents, like positions, with ObjectToWorld.
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  mat3 normalToWorld = mat3(gl_WorldToObjectEXT);
  gHit.position = gl_ObjectToWorldEXT * float4(objectPosition, 1.0);
  gHit.geometricNormal = normalize(objectNormal * normalToWorld);
  float3 vertexNormal = barycentricInterpolate(gNormals[v.x].xyz, gNormals[v.y].xyz, gNormals[v.z].xyz, b);
  float4 vertexTangent = barycentricInterpolate4(gTangents[v.x], gTangents[v.y], gTangents[v.z], b);
  gHit.uv = barycentricInterpolate4(gTexCoords[v.x], gTexCoords[v.y], gTexCoords[v.z], b);
  float3 worldNormal = vertexNormal * normalToWorld;
  float3 worldTangent = gl_ObjectToWorldEXT * float4(vertexTangent.xyz, 0.0);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  // The bitangent is built in object space, where the tangent's w states the
  // map's handedness, and transformed like the tangent.
  float3 objectBitangent = cross(vertexNormal, vertexTangent.xyz) * (vertexTangent.w < 0.0 ? -1.0 : 1.0);
  float3 worldBitangent = gl_ObjectToWorldEXT * float4(objectBitangent, 0.0);
  MaterialData material = gMaterials[instance.materialIndex];
  worldNormal = applyNormalMap(material, gHit.uv, worldNormal, worldTangent, worldBitangent);
#endif
  gHit.shadingNormal = resolveShadingNormal(worldNormal, gHit.geometricNormal);
  gHit.shadingTangent = resolveShadingTangent(worldTangent, gHit.shadingNormal);
  gHit.hitT = gl_HitTEXT;
  gHit.instanceIndex = uint(gl_InstanceCustomIndexEXT);
  gHit.primitiveIndex = uint(gl_PrimitiveID);
}
