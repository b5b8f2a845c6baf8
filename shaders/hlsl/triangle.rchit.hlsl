// Triangle closest hit (DXR twin of glsl/triangle.rchit): reports the
// world-space hit; all shading happens in the ray generation shader.
#include "path_trace_common.hlsli"

[shader("closesthit")]
void main(inout SurfaceHit hit, in BuiltInTriangleIntersectionAttributes attributes) {
  InstanceData instance = gInstances[InstanceID()];
  uint base = instance.firstIndex + 3u * PrimitiveIndex();
  uint i0 = gIndices[base] + instance.firstVertex;
  uint i1 = gIndices[base + 1u] + instance.firstVertex;
  uint i2 = gIndices[base + 2u] + instance.firstVertex;
  float3 p0 = gVertices[i0].xyz;
  float3 p1 = gVertices[i1].xyz;
  float3 p2 = gVertices[i2].xyz;
  float2 b = attributes.barycentrics;
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, b);
  // Normals transform with the inverse transpose: n * WorldToObject (row
  // vector), the GLSL twin's objectNormal * mat3(gl_WorldToObjectEXT);
  // tangents, like positions, with ObjectToWorld.
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  float3x3 normalToWorld = (float3x3)WorldToObject3x4();
  hit.position = mul(ObjectToWorld3x4(), float4(objectPosition, 1.0));
  hit.geometricNormal = normalize(mul(objectNormal, normalToWorld));
  float3 vertexNormal = barycentricInterpolate(gNormals[i0].xyz, gNormals[i1].xyz, gNormals[i2].xyz, b);
  hit.shadingNormal = resolveShadingNormal(mul(vertexNormal, normalToWorld), hit.geometricNormal);
  float3 vertexTangent =
      barycentricInterpolate(gTangents[i0].xyz, gTangents[i1].xyz, gTangents[i2].xyz, b);
  hit.shadingTangent =
      resolveShadingTangent(mul(ObjectToWorld3x4(), float4(vertexTangent, 0.0)), hit.shadingNormal);
  hit.uv = barycentricInterpolate2(gTexCoords[i0].xy, gTexCoords[i1].xy, gTexCoords[i2].xy, b);
  hit.hitT = RayTCurrent();
  hit.instanceIndex = InstanceID();
  hit.primitiveIndex = PrimitiveIndex();
}
