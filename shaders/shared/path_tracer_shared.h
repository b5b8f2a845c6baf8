// Data shared by the host and the path-tracing shaders. Every struct is made
// of 16-byte vectors so std430 (Vulkan) and HLSL structured-buffer layouts
// match the C++ layout; the C++ side static_asserts the sizes.
#ifndef PENUMBRA_PATH_TRACER_SHARED_H
#define PENUMBRA_PATH_TRACER_SHARED_H

#include "camera_shared.h"  // its own namespace: before this file's

#ifdef __cplusplus
#include <cstddef>  // offsetof

#include "shader_types.h"
namespace penumbra::gpu {
#endif

#include "bindings.hlsli"

// Resources of the path tracer (space 0): the HLSL register number of each
// (register(tN) / register(uN) in the DXR entry points, through
// PENUMBRA_REGISTER_T/U) and the Vulkan binding it shifts to (PT_SLOT_*).
#define PT_T_SCENE 0               // top-level acceleration structure
#define PT_T_VERTICES 1            // float4 positions (object space)
#define PT_T_INDICES 2             // uint triangle indices
#define PT_T_INSTANCES 3           // InstanceData per TLAS instance (= InstanceID())
#define PT_T_MATERIALS 4           // MaterialData
#define PT_T_EMISSIVE_TRIANGLES 5  // EmissiveTriangle, world space
#define PT_T_POINT_LIGHTS 6        // PointLight (delta lights)
#define PT_T_NORMALS 7             // float4 vertex normals (object space; xyz 0: none), as PT_T_VERTICES
#define PT_T_TANGENTS 8            // float4 vertex tangents (object space; w handedness; 0: none)
#define PT_T_TEXCOORDS 9           // float4 per vertex: xy TEXCOORD_0, zw TEXCOORD_1 (0 without)
#define PT_T_IMPLICITS 10          // ImplicitData by family: InstanceID() + PrimitiveIndex()
#define PT_T_PROBE_RAYS 11         // ProbeRay: rays of PathTracer::traceProbeRays
#define PT_T_TEXTURE_REFS 12       // TextureRefData: Scene::textureRefs
#define PT_T_ENVIRONMENT_INFO 13   // EnvironmentData, one (a 1x1 black map when the scene has none)
#define PT_T_ENVIRONMENT 14        // float4 per texel of the map: rgb radiance, w the texel's probability
#define PT_T_ENVIRONMENT_CDF 15    // float: the rows' cumulative probabilities, then each row's own
#define PT_T_TEXTURES 16           // Texture2D[] (bindless, so the highest t register: D3D12 unbounded ranges cover all above)
#define PT_S_SAMPLERS 0            // SamplerState[] (bindless): the distinct samplers of the texture refs
#define PT_U_ACCUMULATION 0        // RGBA32F running mean
#define PT_U_RAY_COUNTER 1         // uint: rays traced this dispatch
#define PT_U_PROBE_HITS 2          // ProbeHit per ProbeRay
// The denoiser's guide buffers (path_trace.rgen; running means like the
// accumulation, over the first non-delta vertex of each sample's path):
#define PT_U_GUIDE_ALBEDO 3        // rgb demodulation albedo (times the delta chain's throughput)
#define PT_U_GUIDE_NORMAL_DEPTH 4  // xyz shading normal (mean, not renormalised); w linear view depth, 0: no surface
#define PT_U_GUIDE_EMISSION 5      // rgb radiance emitted there towards the camera (not filtered)
#define PT_U_GUIDE_MOMENTS 6       // x mean luminance of (radiance - emission) per sample, y its mean square
#define PT_SLOT_SCENE PENUMBRA_T(PT_T_SCENE)
#define PT_SLOT_VERTICES PENUMBRA_T(PT_T_VERTICES)
#define PT_SLOT_INDICES PENUMBRA_T(PT_T_INDICES)
#define PT_SLOT_INSTANCES PENUMBRA_T(PT_T_INSTANCES)
#define PT_SLOT_MATERIALS PENUMBRA_T(PT_T_MATERIALS)
#define PT_SLOT_EMISSIVE_TRIANGLES PENUMBRA_T(PT_T_EMISSIVE_TRIANGLES)
#define PT_SLOT_POINT_LIGHTS PENUMBRA_T(PT_T_POINT_LIGHTS)
#define PT_SLOT_NORMALS PENUMBRA_T(PT_T_NORMALS)
#define PT_SLOT_TANGENTS PENUMBRA_T(PT_T_TANGENTS)
#define PT_SLOT_TEXCOORDS PENUMBRA_T(PT_T_TEXCOORDS)
#define PT_SLOT_IMPLICITS PENUMBRA_T(PT_T_IMPLICITS)
#define PT_SLOT_PROBE_RAYS PENUMBRA_T(PT_T_PROBE_RAYS)
#define PT_SLOT_ENVIRONMENT_INFO PENUMBRA_T(PT_T_ENVIRONMENT_INFO)
#define PT_SLOT_ENVIRONMENT PENUMBRA_T(PT_T_ENVIRONMENT)
#define PT_SLOT_ENVIRONMENT_CDF PENUMBRA_T(PT_T_ENVIRONMENT_CDF)
#define PT_SLOT_TEXTURES PENUMBRA_T(PT_T_TEXTURES)
#define PT_SLOT_TEXTURE_REFS PENUMBRA_T(PT_T_TEXTURE_REFS)
#define PT_SLOT_SAMPLERS PENUMBRA_S(PT_S_SAMPLERS)
#define PT_SLOT_ACCUMULATION PENUMBRA_U(PT_U_ACCUMULATION)
#define PT_SLOT_RAY_COUNTER PENUMBRA_U(PT_U_RAY_COUNTER)
#define PT_SLOT_PROBE_HITS PENUMBRA_U(PT_U_PROBE_HITS)
#define PT_SLOT_GUIDE_ALBEDO PENUMBRA_U(PT_U_GUIDE_ALBEDO)
#define PT_SLOT_GUIDE_NORMAL_DEPTH PENUMBRA_U(PT_U_GUIDE_NORMAL_DEPTH)
#define PT_SLOT_GUIDE_EMISSION PENUMBRA_U(PT_U_GUIDE_EMISSION)
#define PT_SLOT_GUIDE_MOMENTS PENUMBRA_U(PT_U_GUIDE_MOMENTS)

// One hit group per geometry kind serves every ray: shadow rays skip its
// closest hit by ray flag and share its any-hit shader, its miss shader and
// the HitRecord payload (DXR requires an any-hit shader's payload type to be
// the tracing ray's). So TraceRay's ray contribution is 0.
#define PT_RAY_CONTRIBUTION 0
// TraceRay's geometry multiplier: 0, so every geometry of a BLAS uses its
// instance's hit groups. The merged BLAS holds one geometry per mesh
// (PathTracer::uploadScene), all of them triangles; the closest hit tells
// them apart by geometry index.
#define PT_GEOMETRY_HIT_GROUP_STRIDE 0

// FrameConstants.flags bits.
#define PT_FLAG_NEE 1u               // next-event estimation on emissive triangles and point lights
#define PT_FLAG_MIS 2u               // MIS between NEE and BSDF sampling (area lights only)
#define PT_FLAG_RUSSIAN_ROULETTE 4u
#define PT_FLAG_BALANCE_HEURISTIC 8u // balance instead of power heuristic
#define PT_FLAG_SOBOL 16u            // Owen-scrambled Sobol samples instead of hashed random ones

// FrameConstants.sceneFlags: bits 0-7 flags, bits 8-15 the thin lens's
// aperture blades (0: round).
#define PT_SCENE_ENVIRONMENT 1u      // rays that leave the scene see the environment, NEE samples it
#define PT_SCENE_BACKGROUND 2u       // camera rays that miss see it too (else black)
#define PT_SCENE_BLADES_SHIFT 8u

// Rng.sampler (shaders/shared/rng.hlsli).
#define RNG_SAMPLER_RANDOM 0u
#define RNG_SAMPLER_SOBOL 1u
// Bits 8-9 of sampling.w: how non-delta directions are sampled.
#define PT_DIRECTIONS_BSDF 0u        // importance-sample the BSDF
#define PT_DIRECTIONS_UNIFORM 1u     // uniform over the hemisphere (sphere if transmissive)
#define PT_DIRECTIONS_COSINE 2u      // cosine-weighted about the side wo is on
#define PT_DIRECTIONS_SHIFT 8u

// MaterialData.flags.x
#define MATERIAL_MODEL_DISNEY 0u
#define MATERIAL_MODEL_PHONG 1u
// MaterialData.flags.y bits
#define MATERIAL_FLAG_THIN 1u
#define MATERIAL_FLAG_LAMBERT_DIFFUSE 2u

// MaterialData.textures2.y: glTF alpha modes.
#define MATERIAL_ALPHA_OPAQUE 0u
#define MATERIAL_ALPHA_MASK 1u
#define MATERIAL_ALPHA_BLEND 2u  // stochastic coverage: a ray stops with probability alpha

// A MaterialData texture slot without a texture.
#define PT_NO_TEXTURE 0xffffffffu

#define PT_NO_EMISSION 0xffffffffu
// InstanceData.firstEmissiveTriangle of an emitter that next-event estimation
// cannot sample (implicit surfaces): BSDF-sampled hits count it in full.
#define PT_EMISSION_NOT_SAMPLED 0xfffffffeu

// ImplicitData.info.x: the kind (= scene::ImplicitKind).
#define IMPLICIT_SPHERE 0u
#define IMPLICIT_PLANE 1u
#define IMPLICIT_BOX 2u
#define IMPLICIT_TORUS 3u
#define IMPLICIT_ROUNDED_BOX 4u
#define IMPLICIT_BLEND 5u
#define IMPLICIT_MANDELBULB 6u
#define IMPLICIT_MAX_BLEND_PRIMITIVES 4

// Push constants (D3D12 root constants), 128 bytes: the most Vulkan guarantees.
struct FrameConstants {
  CameraData camera;
  uint width;
  uint height;
  uint samplesThisFrame;  // samples per pixel this frame adds (1..16)
  uint samplesBefore;     // samples per pixel already in the running mean
  uint seed;
  uint maxDepth;            // bounces after the camera ray (Whitted: recursion depth)
  uint rouletteStartDepth;  // Russian roulette from this bounce on
  uint flags;               // PT_FLAG_* bits and PT_DIRECTIONS_* << PT_DIRECTIONS_SHIFT
  uint emissiveTriangleCount;
  uint pointLightCount;
  // The sample index the mean started at: sample s of this frame is sample
  // firstSample + samplesBefore + s of the sequence (PathTracer::startNewMean).
  uint firstSample;
  uint sceneFlags;      // PT_SCENE_* bits and the lens's blade count
  float3 ambient;       // Whitted ambient radiance
  float radianceClamp;  // largest channel of one sample's contribution; 0 = off
};

// One per top-level instance: where its mesh lies in the shared vertex and
// index buffers, its material, and its emitters (instances of an emissive mesh
// each get their own world-space EmissiveTriangles).
struct InstanceData {
  uint firstIndex;             // into the index buffer
  uint firstVertex;            // added to each index
  uint materialIndex;
  uint firstEmissiveTriangle;  // PT_NO_EMISSION, or this mesh's first EmissiveTriangle
  // Rows of the 3x4 object-to-world transform and of its inverse (the TLAS
  // instance's, so the ray generation shader can rebuild a hit from a
  // HitRecord); identity for implicit objects, which keep theirs in ImplicitData.
  float4 objectToWorld0;
  float4 objectToWorld1;
  float4 objectToWorld2;
  float4 worldToObject0;
  float4 worldToObject1;
  float4 worldToObject2;
  // x: PT_VERTEX_* bits, the vertex attributes the mesh has (the others are
  // zero in their buffers and not read); yzw unused.
  uint4 vertexAttributes;
};

// InstanceData.vertexAttributes.x bits. Without normals a triangle shades
// with its face normal; without tangents its frame is built from the normal.
#define PT_VERTEX_NORMALS 1u
#define PT_VERTEX_TANGENTS 2u
#define PT_VERTEX_TEXCOORDS 4u

// Disney parameters (docs/materials.md) and the Phong parameters of Whitted.
struct MaterialData {
  float4 baseColor;  // rgb; Phong: kd
  float4 emission;   // rgb radiance, emitted from the front (counter-clockwise) face
  float4 disney0;    // x metallic, y roughness, z anisotropic, w specular
  float4 disney1;    // x specularTint, y sheen, z sheenTint, w clearcoat
  float4 disney2;    // x clearcoatGloss, y specTrans, z ior, w subsurface
  float4 phong;      // x ks, y exponent, z reflectivity, w transparency (ior: disney2.z)
  uint4 flags;       // x MATERIAL_MODEL_*, y MATERIAL_FLAG_* bits
  // TextureRefData indices (PT_NO_TEXTURE: none): x base colour, y
  // metallic-roughness, z normal, w emission.
  uint4 textures;
  uint4 textures2;        // x occlusion texture, y MATERIAL_ALPHA_* mode
  float4 textureParams;   // x normal scale, y occlusion strength, z base-colour alpha, w alpha cutoff
  float4 absorption;      // rgb absorption coefficient of the medium inside (per world unit); 0: clear
};

// One use of a texture (scene::TextureRef): uv' = c0 * u + c1 * v + c2 on the
// chosen texture coordinates (KHR_texture_transform), then sampled at LOD 0.
struct TextureRefData {
  float4 transform;  // xy column c0, zw column c1
  float4 offset;     // xy column c2
  uint4 ids;         // x texture (PT_T_TEXTURES index), y sampler (PT_S_SAMPLERS index), z texCoord set (0, 1)
};

// A delta light: point, spot or directional (scene::PointLight).
struct PointLight {
  float4 position;   // xyz (none for a directional light); w cos(inner cone angle) of a spot light,
                     // a directional light's cos(angular radius) (1: a delta light; less: a soft sun)
  float4 intensity;  // rgb radiant intensity (W/sr), a directional light's irradiance (W/m^2);
                     // w range (0: none), beyond which the light does not reach
  float4 spot;       // xyz the direction the light faces (spot) or travels (directional);
                     // w cos(outer cone angle) of a spot, else PT_LIGHT_POINT or PT_LIGHT_DIRECTIONAL
};
#define PT_LIGHT_POINT -2.0
#define PT_LIGHT_DIRECTIONAL -3.0
// A directional light's shadow rays end this far away (world units).
#define PT_DIRECTIONAL_SHADOW_LENGTH 1e30

// The environment map's layout and placement (shaders/shared/environment.hlsli).
struct EnvironmentData {
  uint4 size;        // x width, y height (texels)
  float4 transform;  // x cos, y sin of the rotation about +y; z intensity (scales the radiance)
};

// An emitting triangle in world space, for next-event estimation. A textured
// emitter's radiance is the material's factor; the shader multiplies in the
// texture at the sampled point, interpolating the corners' coordinates.
struct EmissiveTriangle {
  float3 p0;          // corners, render space, counter-clockwise seen from the front
  float probability;  // of choosing this triangle
  float3 p1;
  float area;
  float3 p2;
  uint emissionTexture;  // TextureRefData index; PT_NO_TEXTURE: untextured
  float3 radiance;
  float cumulativeProbability;  // up to and including this triangle
  float2 uv0;  // the corners' texture coordinates (the set the emission texture reads)
  float2 uv1;
  float2 uv2;
  float2 unused;
};

// An implicit surface (scene::ImplicitObject): its kind's parameters in its
// own object space and the world-to-object transform its intersection shader
// applies (the TLAS instances of implicit objects carry the identity).
struct ImplicitData {
  float4 worldToObject0;  // rows of the 3x4 affine world-to-object transform
  float4 worldToObject1;
  float4 worldToObject2;
  // sphere: x radius; plane: xy half extents in x and z; box: xyz half
  // extents; torus: x major, y minor radius; rounded box: xyz half extents,
  // w corner radius; mandelbulb: x power, y iterations
  float4 shape;
  float4 boundsMin;  // xyz object-space box holding the surface; w sphere-tracing tolerance
  float4 boundsMax;  // xyz; w blend radius
  // x IMPLICIT_* kind, y InstanceData index, z max sphere-tracing steps,
  // w blend primitive count
  uint4 info;
  uint4 blendKinds;                                    // IMPLICIT_* kind of each blend primitive
  float4 blendOffsets[IMPLICIT_MAX_BLEND_PRIMITIVES];  // xyz: where each primitive's origin lies
  float4 blendShapes[IMPLICIT_MAX_BLEND_PRIMITIVES];   // each primitive's parameters, as `shape`
};

// A world-space ray of PathTracer::traceProbeRays (tMin 0).
struct ProbeRay {
  float4 origin;     // xyz; w tMax
  float4 direction;  // xyz (hitT is in units of its length)
};

// What the closest hit reported for one ProbeRay (SurfaceHit's fields).
struct ProbeHit {
  float4 position;  // xyz world position; w hitT (< 0: miss)
  float4 normal;    // xyz geometric normal (front side)
  uint4 ids;        // x instance index, y primitive index
};

#ifdef __cplusplus
static_assert(sizeof(ImplicitData) == 256);
static_assert(offsetof(ImplicitData, info) == 96);
static_assert(offsetof(ImplicitData, blendOffsets) == 128);
static_assert(offsetof(ImplicitData, blendShapes) == 192);
static_assert(sizeof(ProbeRay) == 32);
static_assert(sizeof(ProbeHit) == 48);
// The offsets std430 and HLSL packing give (each float3 opens a 16-byte row).
static_assert(sizeof(FrameConstants) == 128);
static_assert(offsetof(FrameConstants, width) == 64 && offsetof(FrameConstants, seed) == 80 &&
              offsetof(FrameConstants, emissiveTriangleCount) == 96 &&
              offsetof(FrameConstants, ambient) == 112 &&
              offsetof(FrameConstants, radianceClamp) == 124);
static_assert(sizeof(PointLight) == 48);
static_assert(sizeof(InstanceData) == 128);
static_assert(sizeof(MaterialData) == 176);
static_assert(sizeof(TextureRefData) == 48);
static_assert(sizeof(EmissiveTriangle) == 96 && offsetof(EmissiveTriangle, p1) == 16 &&
              offsetof(EmissiveTriangle, emissionTexture) == 44 &&
              offsetof(EmissiveTriangle, uv0) == 64 && offsetof(EmissiveTriangle, uv2) == 80);
static_assert(sizeof(EnvironmentData) == 32);
}  // namespace penumbra::gpu
#endif
#endif
