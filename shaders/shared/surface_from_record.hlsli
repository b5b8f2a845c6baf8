// The full SurfaceHit of a HitRecord, rebuilt in the ray generation shader
// after the trace (hit_record.hlsli says why).
//
// The entry point defines, before including this file:
//   InstanceData loadInstanceData(uint index);
//   MaterialData loadMaterial(uint index);
//   ImplicitData loadImplicit(uint index);
//   uint3 triangleVertices(InstanceData instance, uint primitive);
//   float3 loadVertexPosition(uint vertex);   // object space
//   float3 loadVertexNormal(uint vertex);     // object space, zero without
//   float4 loadVertexTangent(uint vertex);    // object space, w handedness, zero without
//   float4 loadVertexTexCoords(uint vertex);  // xy TEXCOORD_0, zw TEXCOORD_1
//   float4 loadVertexColor(uint vertex);      // COLOR_0, linear RGBA
// and, with PT_EFFECT_TEXTURES, textures.hlsli (applyNormalMap) and
//   FrameConstants frameConstants();          // the camera, for the ray cone
#ifndef PENUMBRA_SURFACE_FROM_RECORD_HLSLI
#define PENUMBRA_SURFACE_FROM_RECORD_HLSLI
#include "effects.h"
#include "hit_record.hlsli"
#include "implicit.hlsli"
#include "surface_hit.hlsli"
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
#include "camera.hlsli"
#endif

// Affine 3x4 transforms stored as three rows (InstanceData).
float3 transformPoint3x4(float4 r0, float4 r1, float4 r2, float3 p) {
  return float3(dot(r0.xyz, p) + r0.w, dot(r1.xyz, p) + r1.w, dot(r2.xyz, p) + r2.w);
}

float3 transformVector3x4(float4 r0, float4 r1, float4 r2, float3 v) {
  return float3(dot(r0.xyz, v), dot(r1.xyz, v), dot(r2.xyz, v));
}

// Normals transform with the inverse transpose of object-to-world: as a row
// vector times world-to-object.
float3 transformNormal3x4(float4 inv0, float4 inv1, float4 inv2, float3 n) {
  return n.x * inv0.xyz + n.y * inv1.xyz + n.z * inv2.xyz;
}

// The world-space hit on triangle `primitive` of `instance` at barycentrics b.
SurfaceHit triangleSurfaceHit(InstanceData instance, uint instanceIndex, uint primitive, float2 b, float hitT) {
  uint3 v = triangleVertices(instance, primitive);
  float3 p0 = loadVertexPosition(v.x);
  float3 p1 = loadVertexPosition(v.y);
  float3 p2 = loadVertexPosition(v.z);
  float3 objectPosition = barycentricInterpolate(p0, p1, p2, b);
  float3 objectNormal = cross(p1 - p0, p2 - p0);
  SurfaceHit hit;
  hit.position = transformPoint3x4(instance.objectToWorld0, instance.objectToWorld1, instance.objectToWorld2,
                                   objectPosition);
  hit.hitT = hitT;
  hit.geometricNormal = normalize(transformNormal3x4(instance.worldToObject0, instance.worldToObject1,
                                                     instance.worldToObject2, objectNormal));
  hit.instanceIndex = instanceIndex;
  hit.primitiveIndex = primitive;
  // Attributes the mesh lacks are zero, as in their buffers, without the
  // loads (a tenth of a Cornell box frame).
  uint attributes = instance.vertexAttributes;
  float3 vertexNormal = zero3();
  if ((attributes & PT_VERTEX_NORMALS) != 0u)
    vertexNormal = barycentricInterpolate(loadVertexNormal(v.x), loadVertexNormal(v.y), loadVertexNormal(v.z), b);
  float4 vertexTangent = float4(0.0, 0.0, 0.0, 0.0);
  if ((attributes & PT_VERTEX_TANGENTS) != 0u)
    vertexTangent =
        barycentricInterpolate4(loadVertexTangent(v.x), loadVertexTangent(v.y), loadVertexTangent(v.z), b);
  hit.uv = float4(0.0, 0.0, 0.0, 0.0);
  if ((attributes & PT_VERTEX_TEXCOORDS) != 0u)
    hit.uv = barycentricInterpolate4(loadVertexTexCoords(v.x), loadVertexTexCoords(v.y),
                                     loadVertexTexCoords(v.z), b);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  // The camera's pixel cone here (camera.hlsli): W / |cos| on the surface,
  // times the square root of the triangle's texture-coordinate area over its
  // world area (textures.hlsli). Guards keep log2 finite on degenerate
  // mappings.
  hit.textureFootprint = float2(-1.0e4, -1.0e4);
  float4 cone = pixelCone(frameConstants(), hit.position);
  if ((attributes & PT_VERTEX_TEXCOORDS) != 0u && cone.w > 0.0) {
    float4 t0 = loadVertexTexCoords(v.x);
    float4 t1 = loadVertexTexCoords(v.y);
    float4 t2 = loadVertexTexCoords(v.z);
    float3 e1 = transformVector3x4(instance.objectToWorld0, instance.objectToWorld1,
                                   instance.objectToWorld2, p1 - p0);
    float3 e2 = transformVector3x4(instance.objectToWorld0, instance.objectToWorld1,
                                   instance.objectToWorld2, p2 - p0);
    float4 d1 = t1 - t0;
    float4 d2 = t2 - t0;
    float2 uvArea = abs(float2(d1.x * d2.y - d1.y * d2.x, d1.z * d2.w - d1.w * d2.z));
    float cosine = max(abs(dot(cone.xyz, hit.geometricNormal)), 1e-4);
    float base = log2(cone.w / cosine) - 0.5 * log2(max(length(cross(e1, e2)), 1e-30));
    hit.textureFootprint = float2(base, base) + 0.5 * log2(max(uvArea, float2(1e-30, 1e-30)));
  }
#endif
  hit.color = float4(1.0, 1.0, 1.0, 1.0);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  if ((attributes & PT_VERTEX_COLORS) != 0u)
    hit.color = barycentricInterpolate4(loadVertexColor(v.x), loadVertexColor(v.y), loadVertexColor(v.z), b);
#endif
  float3 worldNormal =
      transformNormal3x4(instance.worldToObject0, instance.worldToObject1, instance.worldToObject2, vertexNormal);
  float3 worldTangent = transformVector3x4(instance.objectToWorld0, instance.objectToWorld1,
                                           instance.objectToWorld2, vertexTangent.xyz);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  // The bitangent is built in object space, where the tangent's w states the
  // map's handedness, and transformed like the tangent.
  float3 objectBitangent = cross(vertexNormal, vertexTangent.xyz) * (vertexTangent.w < 0.0 ? -1.0 : 1.0);
  float3 worldBitangent = transformVector3x4(instance.objectToWorld0, instance.objectToWorld1,
                                             instance.objectToWorld2, objectBitangent);
  MaterialData material = loadMaterial(instance.materialIndex);
#if PT_COAT_NORMALS
  // The coat's own map, or the vertex normal: not the base's map (glTF).
  hit.coatNormal = resolveShadingNormal(
      mapNormal(material.clearcoatNormalTexture, material.clearcoatNormalScale, hit.uv,
                hit.textureFootprint, worldNormal, worldTangent, worldBitangent),
      hit.geometricNormal);
#endif
  worldNormal = applyNormalMap(material, hit.uv, hit.textureFootprint, worldNormal, worldTangent,
                               worldBitangent);
  if (material.anisotropyStrength > 0.0)
    worldTangent =
        anisotropyTangent(material, hit.uv, hit.textureFootprint, worldTangent, worldBitangent);
#endif
  hit.shadingNormal = resolveShadingNormal(worldNormal, hit.geometricNormal);
  hit.shadingTangent = resolveShadingTangent(worldTangent, hit.shadingNormal);
  return hit;
}

// The SurfaceHit of a record returned along (origin, direction).
SurfaceHit surfaceFromRecord(float3 origin, float3 direction, HitRecord r) {
  if (r.hitT < 0.0) return surfaceMiss();
  if ((r.primitive & PT_HIT_IMPLICIT) != 0u) {
    ImplicitData object = loadImplicit(r.primitive & ~PT_HIT_IMPLICIT);
    return implicitSurfaceHit(object, origin, direction, r.hitT, r.attributes);
  }
  return triangleSurfaceHit(loadInstanceData(r.instance), r.instance, r.primitive, r.attributes.xy, r.hitT);
}

#endif
