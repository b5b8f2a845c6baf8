// Resources and trace wrappers shared by the path tracer's DXR entry points:
// the twin of glsl/path_trace_common.glsl, with the same registers (the
// PT_T_*/PT_U_* numbers of path_tracer_shared.h; space 0).
#ifndef PENUMBRA_PATH_TRACE_COMMON_HLSLI
#define PENUMBRA_PATH_TRACE_COMMON_HLSLI
#include "path_tracer_shared.h"
#include "math.hlsli"
#include "payloads.hlsli"

#define PT_MISS_RADIANCE 0

// Wrapped in a struct so entry points can copy the frame out as a plain
// FrameConstants value (a ConstantBuffer<T> is not a T).
struct FramePush {
  FrameConstants frame;
};
[[vk::push_constant]] ConstantBuffer<FramePush> gPush : PENUMBRA_PUSH_CONSTANTS;
RaytracingAccelerationStructure gScene : PENUMBRA_REGISTER_T(PT_T_SCENE);
StructuredBuffer<float4> gVertices : PENUMBRA_REGISTER_T(PT_T_VERTICES);
StructuredBuffer<uint> gIndices : PENUMBRA_REGISTER_T(PT_T_INDICES);
StructuredBuffer<InstanceData> gInstances : PENUMBRA_REGISTER_T(PT_T_INSTANCES);
StructuredBuffer<MaterialData> gMaterials : PENUMBRA_REGISTER_T(PT_T_MATERIALS);
StructuredBuffer<EmissiveTriangle> gEmissiveTriangles : PENUMBRA_REGISTER_T(PT_T_EMISSIVE_TRIANGLES);
StructuredBuffer<PointLight> gPointLights : PENUMBRA_REGISTER_T(PT_T_POINT_LIGHTS);
StructuredBuffer<float4> gNormals : PENUMBRA_REGISTER_T(PT_T_NORMALS);
StructuredBuffer<float4> gTangents : PENUMBRA_REGISTER_T(PT_T_TANGENTS);
StructuredBuffer<float4> gTexCoords : PENUMBRA_REGISTER_T(PT_T_TEXCOORDS);
StructuredBuffer<ImplicitData> gImplicits : PENUMBRA_REGISTER_T(PT_T_IMPLICITS);
StructuredBuffer<TextureRefData> gTextureRefs : PENUMBRA_REGISTER_T(PT_T_TEXTURE_REFS);
StructuredBuffer<EnvironmentData> gEnvironment : PENUMBRA_REGISTER_T(PT_T_ENVIRONMENT_INFO);
StructuredBuffer<float4> gEnvironmentTexels : PENUMBRA_REGISTER_T(PT_T_ENVIRONMENT);
StructuredBuffer<float> gEnvironmentCdf : PENUMBRA_REGISTER_T(PT_T_ENVIRONMENT_CDF);
Texture2D<float4> gTextures[] : PENUMBRA_REGISTER_T(PT_T_TEXTURES);
SamplerState gSamplers[] : PENUMBRA_REGISTER_S(PT_S_SAMPLERS);
RWTexture2D<float4> gAccumulation : PENUMBRA_REGISTER_U(PT_U_ACCUMULATION);
RWStructuredBuffer<uint> gRayCounter : PENUMBRA_REGISTER_U(PT_U_RAY_COUNTER);

InstanceData loadInstanceData(uint index) { return gInstances[index]; }
MaterialData loadMaterial(uint index) { return gMaterials[index]; }
EmissiveTriangle loadEmissiveTriangle(uint index) { return gEmissiveTriangles[index]; }
PointLight loadPointLight(uint index) { return gPointLights[index]; }
ImplicitData loadImplicit(uint index) { return gImplicits[index]; }
TextureRefData loadTextureRef(uint index) { return gTextureRefs[index]; }
EnvironmentData loadEnvironment() { return gEnvironment[0]; }
float4 loadEnvironmentTexel(uint index) { return gEnvironmentTexels[index]; }
float loadEnvironmentCdf(uint index) { return gEnvironmentCdf[index]; }
// Indices differ between neighbouring rays, hence NonUniformResourceIndex.
float4 sampleTextureLod0(uint textureIndex, uint samplerIndex, float2 uv) {
  return gTextures[NonUniformResourceIndex(textureIndex)].SampleLevel(
      gSamplers[NonUniformResourceIndex(samplerIndex)], uv, 0.0);
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
#include "surface_from_record.hlsli"

#endif
