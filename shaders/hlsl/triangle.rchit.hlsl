// Triangle closest hit (DXR twin of glsl/triangle.rchit): reports the
// world-space hit; all shading happens in the ray generation shader.
#include "path_trace_common.hlsli"
#include "effects.h"

[shader("closesthit")]
void main(inout SurfaceHit hit, in BuiltInTriangleIntersectionAttributes attributes) {
  InstanceData instance = gInstances[InstanceID()];
  uint3 v = triangleVertices(instance, PrimitiveIndex());
  float3 p0 = gVertices[v.x].xyz;
  float3 p1 = gVertices[v.y].xyz;
  float3 p2 = gVertices[v.z].xyz;
  float2 b = attributes.barycentrics;
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, b);
  // Normals transform with the inverse transpose: n * WorldToObject (row
  // vector), the GLSL twin's objectNormal * mat3(gl_WorldToObjectEXT);
  // tangents, like positions, with ObjectToWorld.
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  float3x3 normalToWorld = (float3x3)WorldToObject3x4();
  hit.position = mul(ObjectToWorld3x4(), float4(objectPosition, 1.0));
  hit.geometricNormal = normalize(mul(objectNormal, normalToWorld));
  float3 vertexNormal = barycentricInterpolate(gNormals[v.x].xyz, gNormals[v.y].xyz, gNormals[v.z].xyz, b);
  float4 vertexTangent = barycentricInterpolate4(gTangents[v.x], gTangents[v.y], gTangents[v.z], b);
  hit.uv = barycentricInterpolate4(gTexCoords[v.x], gTexCoords[v.y], gTexCoords[v.z], b);
  float3 worldNormal = mul(vertexNormal, normalToWorld);
  float3 worldTangent = mul(ObjectToWorld3x4(), float4(vertexTangent.xyz, 0.0));
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  // The bitangent is built in object space, where the tangent's w states the
  // map's handedness, and transformed like the tangent.
  float3 objectBitangent = cross(vertexNormal, vertexTangent.xyz) * (vertexTangent.w < 0.0 ? -1.0 : 1.0);
  float3 worldBitangent = mul(ObjectToWorld3x4(), float4(objectBitangent, 0.0));
  MaterialData material = gMaterials[instance.materialIndex];
  worldNormal = applyNormalMap(material, hit.uv, worldNormal, worldTangent, worldBitangent);
#endif
  hit.shadingNormal = resolveShadingNormal(worldNormal, hit.geometricNormal);
  hit.shadingTangent = resolveShadingTangent(worldTangent, hit.shadingNormal);
  hit.hitT = RayTCurrent();
  hit.instanceIndex = InstanceID();
  hit.primitiveIndex = PrimitiveIndex();
}
