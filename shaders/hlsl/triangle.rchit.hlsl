// Triangle closest hit (DXR twin of glsl/triangle.rchit): reports the
// world-space hit; all shading happens in the ray generation shader.
#include "path_trace_common.hlsli"

[shader("closesthit")]
void main(inout SurfaceHit hit, in BuiltInTriangleIntersectionAttributes attributes) {
  InstanceData instance = gInstances[InstanceID()];
  uint base = instance.firstIndex + 3u * PrimitiveIndex();
  float3 p0 = gVertices[gIndices[base] + instance.firstVertex].xyz;
  float3 p1 = gVertices[gIndices[base + 1u] + instance.firstVertex].xyz;
  float3 p2 = gVertices[gIndices[base + 2u] + instance.firstVertex].xyz;
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, attributes.barycentrics);
  // Normals transform with the inverse transpose: n * WorldToObject (row
  // vector), the GLSL twin's objectNormal * mat3(gl_WorldToObjectEXT).
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  hit.position = mul(ObjectToWorld3x4(), float4(objectPosition, 1.0));
  hit.geometricNormal = normalize(mul(objectNormal, (float3x3)WorldToObject3x4()));
  hit.hitT = RayTCurrent();
  hit.instanceIndex = InstanceID();
  hit.primitiveIndex = PrimitiveIndex();
}
