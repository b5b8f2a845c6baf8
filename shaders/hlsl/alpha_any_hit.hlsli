// The alpha any-hit test shared by the radiance and shadow entry points (the
// twin of glsl/alpha_any_hit.glsl): whether the candidate hit stays. DXR
// needs one entry point per payload type.
#ifndef PENUMBRA_ALPHA_ANY_HIT_HLSLI
#define PENUMBRA_ALPHA_ANY_HIT_HLSLI
#include "path_trace_common.hlsli"

bool alphaAnyHitKeeps(BuiltInTriangleIntersectionAttributes attributes) {
  uint instanceIndex = InstanceID() + GeometryIndex();  // as triangle.rchit
  InstanceData instance = gInstances[instanceIndex];
  MaterialData material = gMaterials[instance.materialIndex];
  if (material.textures2.y == MATERIAL_ALPHA_OPAQUE) return true;
  uint3 v = triangleVertices(instance, PrimitiveIndex());
  float4 uv = barycentricInterpolate4(gTexCoords[v.x], gTexCoords[v.y], gTexCoords[v.z],
                                      attributes.barycentrics);
  FrameConstants frame = gPush.frame;
  float u = alphaCoverageRandom(DispatchRaysIndex().xy, frame.lights.z + frame.image.w, frame.sampling.x, WorldRayOrigin(),
                                WorldRayDirection(), instanceIndex, PrimitiveIndex());
  return alphaKeepsHit(material, uv, u);
}

#endif
