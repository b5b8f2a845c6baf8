// The path tracer's resources (the PT_T_*/PT_U_*/PT_S_* registers of
// path_tracer_shared.h) and their accessors, for every ray-tracing stage.
#ifndef PENUMBRA_PATH_TRACE_RESOURCES_HLSLI
#define PENUMBRA_PATH_TRACE_RESOURCES_HLSLI
#include "path_tracer_shared.h"
#include "math.hlsli"
#include "hit_record.hlsli"
#include "surface_hit.hlsli"

#define PT_MISS_RADIANCE 0

PT_PUSH_CONSTANTS(FrameConstants, frameConstants);
PT_ACCELERATION_STRUCTURE(gScene, PT_T_SCENE);
PT_BUFFER(float4, gVertices, PT_T_VERTICES);
PT_BUFFER(uint, gIndices, PT_T_INDICES);
PT_BUFFER(InstanceData, gInstances, PT_T_INSTANCES);
PT_BUFFER(MaterialData, gMaterials, PT_T_MATERIALS);
PT_BUFFER(EmissiveTriangle, gEmissiveTriangles, PT_T_EMISSIVE_TRIANGLES);
PT_BUFFER(PointLight, gPointLights, PT_T_POINT_LIGHTS);
PT_BUFFER(float4, gNormals, PT_T_NORMALS);
PT_BUFFER(float4, gTangents, PT_T_TANGENTS);
PT_BUFFER(float4, gTexCoords, PT_T_TEXCOORDS);
PT_BUFFER(float4, gColors, PT_T_COLORS);
PT_BUFFER(ImplicitData, gImplicits, PT_T_IMPLICITS);
PT_BUFFER(TextureRefData, gTextureRefs, PT_T_TEXTURE_REFS);
PT_BUFFER(EnvironmentData, gEnvironment, PT_T_ENVIRONMENT_INFO);
PT_BUFFER(float4, gEnvironmentTexels, PT_T_ENVIRONMENT);
PT_BUFFER(float, gEnvironmentCdf, PT_T_ENVIRONMENT_CDF);
PT_BUFFER(float, gSheenAlbedo, PT_T_SHEEN_ALBEDO);
PT_TEXTURE_ARRAY(gTextures, PT_T_TEXTURES);
PT_SAMPLER_ARRAY(gSamplers, PT_S_SAMPLERS);
PT_RW_TEXTURE(gAccumulation, PT_U_ACCUMULATION);
PT_RW_BUFFER(uint, gRayCounter, PT_U_RAY_COUNTER);

InstanceData loadInstanceData(uint index) { return gInstances[index]; }
MaterialData loadMaterial(uint index) { return gMaterials[index]; }
EmissiveTriangle loadEmissiveTriangle(uint index) { return gEmissiveTriangles[index]; }
PointLight loadPointLight(uint index) { return gPointLights[index]; }
ImplicitData loadImplicit(uint index) { return gImplicits[index]; }
TextureRefData loadTextureRef(uint index) { return gTextureRefs[index]; }
EnvironmentData loadEnvironment() { return gEnvironment[0]; }
float4 loadEnvironmentTexel(uint index) { return gEnvironmentTexels[index]; }
float loadEnvironmentCdf(uint index) { return gEnvironmentCdf[index]; }
float loadSheenAlbedo(uint index) {
  return gSheenAlbedo[index];
}
float4 sampleTextureLevel(uint textureIndex, uint samplerIndex, float2 uv, float level) {
  return PT_SAMPLE_LEVEL(gTextures, gSamplers, textureIndex, samplerIndex, uv, level);
}
#include "textures.hlsli"
#include "environment.hlsli"

// The vertex indices of triangle `primitive` of an instance's mesh.
uint3 triangleVertices(InstanceData instance, uint primitive) {
  uint base = instance.firstIndex + 3u * primitive;
  return uint3(gIndices[base], gIndices[base + 1u], gIndices[base + 2u]) + instance.firstVertex;
}
float3 loadVertexPosition(uint vertex) { return gVertices[vertex].xyz; }
float3 loadVertexNormal(uint vertex) { return gNormals[vertex].xyz; }
float4 loadVertexTangent(uint vertex) { return gTangents[vertex]; }
float4 loadVertexTexCoords(uint vertex) { return gTexCoords[vertex]; }
float4 loadVertexColor(uint vertex) { return gColors[vertex]; }
#include "surface_from_record.hlsli"

#endif
