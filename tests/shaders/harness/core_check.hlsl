// The shading core compiled by glslang's HLSL front-end (docs/ARCHITECTURE.md, "Shaders"), as a
// compute shader that runs the path tracer in an analytic furnace: the camera
// sits inside a sphere of albedo rho emitting Le everywhere, so every sample
// must converge to Le / (1 - rho). Run by tests/shaders/test_hlsl_core.cpp,
// it proves the HLSL spelling of the core compiles and computes the same
// physics; the DXR entry points use the same files.
//
// The sphere is analytic, not triangles, so next-event estimation is off here
// (emissiveTriangleCount = 0); the Vulkan furnace test covers NEE and MIS.
#include "path_tracer_shared.h"
#include "math.hlsli"
#include "hit_record.hlsli"
#include "surface_hit.hlsli"
// The implicit-surface core, so an HLSL error in it fails this build too
// (the DXR intersection shaders include the same files).
#include "implicit.hlsli"
#include "probe.hlsli"
#include "sdf.hlsli"
float implicitSdf(ImplicitData o, float3 p) {
  return o.kind == IMPLICIT_MANDELBULB ? sdfMandelbulb(p, o.shape.x, uint(o.shape.y))
                                         : sdfObjectDistance(o, p);
}
#include "sphere_tracing.hlsli"

// Wrapped: glslang cannot copy a ConstantBuffer<FrameConstants> into a FrameConstants.
struct FramePush {
  FrameConstants frame;
};
[[vk::push_constant]] ConstantBuffer<FramePush> gPush;
// register(t0)/(u0) for DXIL; the same bindings spelled for the SPIR-V build.
// gSphere[0]: x albedo, y emitted radiance, z radius.
[[vk::binding(PENUMBRA_T(0), 0)]] StructuredBuffer<float4> gSphere : register(t0);
[[vk::binding(PENUMBRA_U(0), 0)]] RWStructuredBuffer<float4> gOutput : register(u0);

// Rays start inside the sphere (centred at the origin), so the hit is where
// they leave it: the implicit core's sphere, as compiled by this front-end,
// reported as the implicit object ImplicitData[0] (loadImplicit below).
// Any two points inside a sphere see each other: a shadow ray never hits.
HitRecord traceRay(float3 origin, float3 direction, float tMax, bool shadow) {
  HitRecord r = hitRecordMiss();
  if (shadow) return r;
  ImplicitHit leaving = intersectSphere(origin, direction, gSphere[0].z, 0.0, 1e30);
  if (leaving.s < 0.0) return r;
  r.hitT = leaving.s;
  r.primitive = PT_HIT_IMPLICIT;
  r.attributes = -leaving.normal;  // the emitting side faces inwards
  return r;
}

InstanceData loadInstanceData(uint index) {
  InstanceData m;
  m.firstIndex = 0u;
  m.firstVertex = 0u;
  m.materialIndex = 0u;
  m.firstEmissiveTriangle = 0u;
  m.objectToWorld0 = float4(1.0, 0.0, 0.0, 0.0);
  m.objectToWorld1 = float4(0.0, 1.0, 0.0, 0.0);
  m.objectToWorld2 = float4(0.0, 0.0, 1.0, 0.0);
  m.worldToObject0 = m.objectToWorld0;
  m.worldToObject1 = m.objectToWorld1;
  m.worldToObject2 = m.objectToWorld2;
  m.vertexAttributes = 0u;
  m.unused0 = 0u;
  m.unused1 = 0u;
  m.unused2 = 0u;
  return m;
}

// A Lambertian surface: Disney with Lambert diffuse and no specular layer.
MaterialData loadMaterial(uint index) {
  float albedo = gSphere[0].x;
  float emission = gSphere[0].y;
  MaterialData m = (MaterialData)0;
  m.baseColor = float3(albedo, albedo, albedo);
  m.emission = float3(emission, emission, emission);
  m.roughness = 1.0;
  m.ior = 1.5;
  m.model = MATERIAL_MODEL_DISNEY;
  m.flags = MATERIAL_FLAG_LAMBERT_DIFFUSE;
  m.baseColorTexture = PT_NO_TEXTURE;
  m.metallicRoughnessTexture = PT_NO_TEXTURE;
  m.normalTexture = PT_NO_TEXTURE;
  m.emissionTexture = PT_NO_TEXTURE;
  m.occlusionTexture = PT_NO_TEXTURE;
  m.alphaMode = MATERIAL_ALPHA_OPAQUE;
  m.normalScale = 1.0;
  m.clearcoatNormalTexture = PT_NO_TEXTURE;
  m.clearcoatNormalScale = 1.0;
  m.specularF90 = 1.0;
  m.diffuseTransmissionTexture = PT_NO_TEXTURE;
  m.diffuseTransmissionColorTexture = PT_NO_TEXTURE;
  m.iridescenceTexture = PT_NO_TEXTURE;
  m.iridescenceThicknessTexture = PT_NO_TEXTURE;
  m.occlusionStrength = 1.0;
  m.alpha = 1.0;
  m.alphaCutoff = 0.5;
  return m;
}

// No point lights in this harness (pointLightCount = 0).
PointLight loadPointLight(uint index) {
  PointLight p = (PointLight)0;
  p.cosInner = 1.0;
  p.direction = float3(0.0, 0.0, 1.0);
  p.type = PT_LIGHT_POINT;
  return p;
}

// No triangle lights in this harness (emissiveTriangleCount 0 keeps NEE from calling it).
EmissiveTriangle loadEmissiveTriangle(uint index) {
  EmissiveTriangle t;
  t.p0 = float3(0.0, 0.0, 0.0);
  t.probability = 0.0;
  t.p1 = float3(0.0, 0.0, 0.0);
  t.area = 1.0;
  t.p2 = float3(0.0, 0.0, 0.0);
  t.emissionTexture = PT_NO_TEXTURE;
  t.radiance = float3(0.0, 0.0, 0.0);
  t.cumulativeProbability = 1.0;
  t.uv0 = float2(0.0, 0.0);
  t.uv1 = float2(0.0, 0.0);
  t.uv2 = float2(0.0, 0.0);
  t.unused = float2(0.0, 0.0);
  return t;
}

// The sphere has no textures (every material slot is PT_NO_TEXTURE); the
// texture core still compiles through this front-end.
TextureRefData loadTextureRef(uint index) {
  TextureRefData r = (TextureRefData)0;
  r.column0 = float2(1.0, 0.0);
  r.column1 = float2(0.0, 1.0);
  return r;
}
float4 sampleTextureLevel(uint textureIndex, uint samplerIndex, float2 uv, float level) { return float4(1.0, 1.0, 1.0, 1.0); }
#include "textures.hlsli"

// The harness has no meshes; these only let the triangle half of the record
// decoding (surface_from_record.hlsli) compile through this front-end.
// The furnace sphere as ImplicitData[0]: at the origin, unscaled, InstanceData 0.
ImplicitData loadImplicit(uint index) {
  ImplicitData o = (ImplicitData)0;
  o.worldToObject0 = float4(1.0, 0.0, 0.0, 0.0);
  o.worldToObject1 = float4(0.0, 1.0, 0.0, 0.0);
  o.worldToObject2 = float4(0.0, 0.0, 1.0, 0.0);
  o.kind = IMPLICIT_SPHERE;
  o.instanceIndex = 0u;
  return o;
}
uint3 triangleVertices(InstanceData instance, uint primitive) { return uint3(0u, 1u, 2u); }
float3 loadVertexPosition(uint vertex) { return float3(float(vertex == 1u), float(vertex == 2u), 0.0); }
float3 loadVertexNormal(uint vertex) { return float3(0.0, 0.0, 1.0); }
float4 loadVertexTangent(uint vertex) { return float4(1.0, 0.0, 0.0, 1.0); }
float4 loadVertexTexCoords(uint vertex) { return float4(0.0, 0.0, 0.0, 0.0); }
float4 loadVertexColor(uint vertex) { return float4(1.0, 1.0, 1.0, 1.0); }
// The camera of the run (the ray cone's, for textures; the sphere has none).
FrameConstants frameConstants() { return gPush.frame; }
#include "surface_from_record.hlsli"

// No environment in this harness (no PT_EFFECT_ENVIRONMENT); its code compiles through
// this front-end all the same.
EnvironmentData loadEnvironment() {
  EnvironmentData e = (EnvironmentData)0;
  e.width = 1u;
  e.height = 1u;
  e.cosRotation = 1.0;
  return e;
}
float4 loadEnvironmentTexel(uint index) { return float4(0.0, 0.0, 0.0, 1.0); }
float loadEnvironmentCdf(uint index) { return 1.0; }
// The furnace's sphere has no glTF sheen: the table is never read.
float loadSheenAlbedo(uint index) { return 0.0; }

// The harness keeps no guides.
static uint2 gPixel;
uint2 launchPixel() { return gPixel; }
void addGuideSample(uint2 pixel, uint samplesBefore, float3 albedo, float4 normalDepth, float3 emission) {}

#include "camera.hlsli"
#include "path_tracer.hlsli"

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  FrameConstants c = gPush.frame;
  uint pixelIndex = id.x;
  uint2 pixel = uint2(pixelIndex % c.width, pixelIndex / c.width);
  if (pixel.y >= c.height) return;
  gPixel = pixel;
  float2 moments;
  float3 sum = tracePixel(moments);
  gOutput[pixelIndex] = float4(sum / float(c.samplesThisFrame), 1.0);
}
