// Alpha any-hit (DXR twin of glsl/triangle_alpha.rahit): MASK drops texels
// below the cutoff; BLEND drops a hit with probability 1 - alpha.
#include "path_trace_common.hlsli"

[shader("anyhit")]
void main(inout SurfaceHit hit, in BuiltInTriangleIntersectionAttributes attributes) {
  InstanceData instance = gInstances[InstanceID()];
  MaterialData material = gMaterials[instance.materialIndex];
  if (material.textures2.y == MATERIAL_ALPHA_OPAQUE) return;
  uint3 v = triangleVertices(instance, PrimitiveIndex());
  float4 uv = barycentricInterpolate4(gTexCoords[v.x], gTexCoords[v.y], gTexCoords[v.z],
                                      attributes.barycentrics);
  FrameConstants frame = gPush.frame;
  float u = alphaCoverageRandom(DispatchRaysIndex().xy, frame.image.w, frame.sampling.x, WorldRayOrigin(),
                                WorldRayDirection(), InstanceID(), PrimitiveIndex());
  if (!alphaKeepsHit(material, uv, u)) IgnoreHit();
}
