// The alpha any-hit shader's body, for the radiance and the shadow hit group
// of the triangles (PT_EFFECT_ALPHA_MASK): only alpha-cut meshes are
// non-opaque geometry, so only they run it. MASK drops texels below the
// cutoff; BLEND drops a hit with probability 1 - alpha. GLSL any-hit shaders
// need not declare the payload, so both entry points are this file.
hitAttributeEXT float2 gBarycentrics;

void main() {
  uint instanceIndex = uint(gl_InstanceCustomIndexEXT) + uint(gl_GeometryIndexEXT);  // as triangle.rchit
  InstanceData instance = gInstances[instanceIndex];
  MaterialData material = gMaterials[instance.materialIndex];
  if (material.textures2.y == MATERIAL_ALPHA_OPAQUE) return;
  uint3 v = triangleVertices(instance, uint(gl_PrimitiveID));
  float4 uv = barycentricInterpolate4(gTexCoords[v.x], gTexCoords[v.y], gTexCoords[v.z], gBarycentrics);
  float u = alphaCoverageRandom(gl_LaunchIDEXT.xy, gFrame.lights.z + gFrame.image.w, gFrame.sampling.x, gl_WorldRayOriginEXT,
                                gl_WorldRayDirectionEXT, instanceIndex, uint(gl_PrimitiveID));
  if (!alphaKeepsHit(material, uv, u)) ignoreIntersectionEXT;
}
