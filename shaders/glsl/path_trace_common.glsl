// Resources and trace wrappers shared by the path tracer's GLSL stages.
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_nonuniform_qualifier : require
#include "hlsl_prelude.glsl"
#include "path_tracer_shared.h"
#include "math.hlsli"
#include "hit_record.hlsli"
#include "surface_hit.hlsli"

#define PT_PAYLOAD_RADIANCE 0
#define PT_MISS_RADIANCE 0

layout(push_constant, std430) uniform FramePush { FrameConstants gFrame; };
layout(set = 0, binding = PT_SLOT_SCENE) uniform accelerationStructureEXT gScene;
layout(set = 0, binding = PT_SLOT_VERTICES, std430) readonly buffer Vertices { float4 gVertices[]; };
layout(set = 0, binding = PT_SLOT_INDICES, std430) readonly buffer Indices { uint gIndices[]; };
layout(set = 0, binding = PT_SLOT_INSTANCES, std430) readonly buffer Instances { InstanceData gInstances[]; };
layout(set = 0, binding = PT_SLOT_MATERIALS, std430) readonly buffer Materials { MaterialData gMaterials[]; };
layout(set = 0, binding = PT_SLOT_EMISSIVE_TRIANGLES, std430) readonly buffer Emissive {
  EmissiveTriangle gEmissiveTriangles[];
};
layout(set = 0, binding = PT_SLOT_POINT_LIGHTS, std430) readonly buffer PointLights {
  PointLight gPointLights[];
};
layout(set = 0, binding = PT_SLOT_NORMALS, std430) readonly buffer Normals { float4 gNormals[]; };
layout(set = 0, binding = PT_SLOT_TANGENTS, std430) readonly buffer Tangents { float4 gTangents[]; };
layout(set = 0, binding = PT_SLOT_TEXCOORDS, std430) readonly buffer TexCoords { float4 gTexCoords[]; };
layout(set = 0, binding = PT_SLOT_IMPLICITS, std430) readonly buffer Implicits {
  ImplicitData gImplicits[];
};
layout(set = 0, binding = PT_SLOT_TEXTURE_REFS, std430) readonly buffer TextureRefs {
  TextureRefData gTextureRefs[];
};
layout(set = 0, binding = PT_SLOT_ENVIRONMENT_INFO, std430) readonly buffer EnvironmentInfo {
  EnvironmentData gEnvironment;
};
layout(set = 0, binding = PT_SLOT_ENVIRONMENT, std430) readonly buffer EnvironmentTexels {
  float4 gEnvironmentTexels[];
};
layout(set = 0, binding = PT_SLOT_ENVIRONMENT_CDF, std430) readonly buffer EnvironmentCdf {
  float gEnvironmentCdf[];
};
layout(set = 0, binding = PT_SLOT_TEXTURES) uniform texture2D gTextures[];
layout(set = 0, binding = PT_SLOT_SAMPLERS) uniform sampler gSamplers[];
layout(set = 0, binding = PT_SLOT_ACCUMULATION, rgba32f) uniform image2D gAccumulation;
layout(set = 0, binding = PT_SLOT_RAY_COUNTER, std430) buffer RayCounter { uint gRayCount; };

InstanceData loadInstanceData(uint index) { return gInstances[index]; }
MaterialData loadMaterial(uint index) { return gMaterials[index]; }
EmissiveTriangle loadEmissiveTriangle(uint index) { return gEmissiveTriangles[index]; }
PointLight loadPointLight(uint index) { return gPointLights[index]; }
ImplicitData loadImplicit(uint index) { return gImplicits[index]; }
TextureRefData loadTextureRef(uint index) { return gTextureRefs[index]; }
EnvironmentData loadEnvironment() { return gEnvironment; }
float4 loadEnvironmentTexel(uint index) { return gEnvironmentTexels[index]; }
float loadEnvironmentCdf(uint index) { return gEnvironmentCdf[index]; }
// Indices differ between neighbouring rays, hence nonuniformEXT.
float4 sampleTextureLod0(uint textureIndex, uint samplerIndex, float2 uv) {
  return textureLod(sampler2D(gTextures[nonuniformEXT(textureIndex)], gSamplers[nonuniformEXT(samplerIndex)]),
                    uv, 0.0);
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
