// Alpha-mask any-hit (DXR twin of glsl/triangle_alpha.rahit): texels whose
// base-colour alpha is below the material's cutoff are no hit.
#include "path_trace_common.hlsli"

[shader("anyhit")]
void main(inout SurfaceHit hit, in BuiltInTriangleIntersectionAttributes attributes) {
  InstanceData instance = gInstances[InstanceID()];
  MaterialData material = gMaterials[instance.materialIndex];
  if (material.textures2.y != MATERIAL_ALPHA_MASK) return;
  uint3 v = triangleVertices(instance, PrimitiveIndex());
  float4 uv = barycentricInterpolate4(gTexCoords[v.x], gTexCoords[v.y], gTexCoords[v.z],
                                      attributes.barycentrics);
  if (materialAlpha(material, uv) < material.textureParams.w) IgnoreHit();
}
