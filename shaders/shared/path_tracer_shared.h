// Data shared by the host and the path-tracing shaders. Every field is named;
// rows are 16 bytes (four scalars, a float4, a float3 and a scalar, two
// float2s, or a float2 after two scalars or before them), so std430 (Vulkan) and HLSL
// structured-buffer layouts match the C++ layout; the C++ side static_asserts sizes and row
// offsets.
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
// The table is kept aligned by hand.
// clang-format off
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
#define PT_T_COLORS 16             // float4 per vertex: COLOR_0, linear RGBA (with PT_VERTEX_COLORS)
#define PT_T_SHEEN_ALBEDO 17       // float: the glTF sheen's directional albedo table (sheen.hlsli)
// Texture2D[], bindless: the highest t register (a D3D12 unbounded range
// covers every register above its first).
#define PT_T_TEXTURES 18
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
// clang-format on
// Nodes along each axis of PT_T_SHEEN_ALBEDO's table (size^2 floats).
#define PT_SHEEN_ALBEDO_SIZE 16
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
#define PT_SLOT_COLORS PENUMBRA_T(PT_T_COLORS)
#define PT_SLOT_IMPLICITS PENUMBRA_T(PT_T_IMPLICITS)
#define PT_SLOT_PROBE_RAYS PENUMBRA_T(PT_T_PROBE_RAYS)
#define PT_SLOT_ENVIRONMENT_INFO PENUMBRA_T(PT_T_ENVIRONMENT_INFO)
#define PT_SLOT_ENVIRONMENT PENUMBRA_T(PT_T_ENVIRONMENT)
#define PT_SLOT_ENVIRONMENT_CDF PENUMBRA_T(PT_T_ENVIRONMENT_CDF)
#define PT_SLOT_SHEEN_ALBEDO PENUMBRA_T(PT_T_SHEEN_ALBEDO)
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
#define PT_SCENE_ORTHOGRAPHIC 4u     // parallel camera rays (CameraData.filmHalfHeight in metres)
#define PT_SCENE_BLADES_SHIFT 8u

// Rng.sampler (shaders/shared/rng.hlsli).
#define RNG_SAMPLER_RANDOM 0u
#define RNG_SAMPLER_SOBOL 1u
// Bits 8-9 of FrameConstants.flags: how non-delta directions are sampled.
#define PT_DIRECTIONS_BSDF 0u        // importance-sample the BSDF
#define PT_DIRECTIONS_UNIFORM 1u     // uniform over the hemisphere (sphere if transmissive)
#define PT_DIRECTIONS_COSINE 2u      // cosine-weighted about the side wo is on
#define PT_DIRECTIONS_SHIFT 8u

// MaterialData.model
#define MATERIAL_MODEL_DISNEY 0u
#define MATERIAL_MODEL_PHONG 1u
#define MATERIAL_MODEL_UNLIT 2u  // KHR_materials_unlit: baseColor is the radiance seen
// MaterialData.flags bits
#define MATERIAL_FLAG_THIN 1u
#define MATERIAL_FLAG_LAMBERT_DIFFUSE 2u
// The coat is glTF's KHR_materials_clearcoat (full strength, GGX) instead of
// Disney's; set with the Lambert diffuse for the Lambert (glTF) model.
#define MATERIAL_FLAG_GGX_COAT 4u
// The sheen is glTF's KHR_materials_sheen layer (Charlie fibres of
// sheenRoughness, sheen.hlsli) instead of Disney's; also the Lambert model's.
#define MATERIAL_FLAG_CHARLIE_SHEEN 8u

// MaterialData.alphaMode: glTF alpha modes.
#define MATERIAL_ALPHA_OPAQUE 0u
#define MATERIAL_ALPHA_MASK 1u
#define MATERIAL_ALPHA_BLEND 2u  // stochastic coverage: a ray stops with probability alpha

// A MaterialData texture slot without a texture.
#define PT_NO_TEXTURE 0xffffffffu

#define PT_NO_EMISSION 0xffffffffu
// InstanceData.firstEmissiveTriangle of an emitter that next-event estimation
// cannot sample (implicit surfaces): BSDF-sampled hits count it in full.
#define PT_EMISSION_NOT_SAMPLED 0xfffffffeu

// ImplicitData.kind (= scene::ImplicitKind).
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
  // PT_VERTEX_* bits: the vertex attributes the mesh has (the others are zero
  // in their buffers and not read).
  uint vertexAttributes;
  uint unused0;
  uint unused1;
  uint unused2;
};

// InstanceData.vertexAttributes bits. Without normals a triangle shades
// with its face normal; without tangents its frame is built from the normal.
#define PT_VERTEX_NORMALS 1u
#define PT_VERTEX_TANGENTS 2u
#define PT_VERTEX_TEXCOORDS 4u
#define PT_VERTEX_COLORS 8u

// Disney parameters (docs/materials.md) and the Phong parameters of Whitted.
struct MaterialData {
  float3 baseColor;  // Phong: kd
  // The KHR_materials_* textures (TextureRefData indices or PT_NO_TEXTURE;
  // scene::Material says which channel scales what) fill the padding after
  // the float3s and in the uint rows.
  uint clearcoatTexture;
  float3 emission;  // radiance, emitted from the front (counter-clockwise) face
  uint clearcoatRoughnessTexture;
  float metallic;
  float roughness;
  float anisotropic;
  float specular;
  float specularTint;
  float sheen;
  float sheenTint;
  float clearcoat;
  float clearcoatGloss;
  float specTrans;
  float ior;  // Disney and Phong
  float subsurface;
  float ks;  // Phong (Whitted): specular weight
  float phongExponent;
  float reflectivity;  // Phong: mirror reflection
  float transparency;  // Phong: refraction
  uint model;          // MATERIAL_MODEL_*
  uint flags;          // MATERIAL_FLAG_* bits
  uint transmissionTexture;
  uint sheenColorTexture;
  // TextureRefData indices, PT_NO_TEXTURE where there is none.
  uint baseColorTexture;
  uint metallicRoughnessTexture;
  uint normalTexture;
  uint emissionTexture;
  uint occlusionTexture;
  uint alphaMode;  // MATERIAL_ALPHA_*
  uint specularTexture;
  uint specularColorTexture;
  float normalScale;
  float occlusionStrength;
  float alpha;        // base-colour alpha (the texture's alpha multiplies it)
  float alphaCutoff;  // alphaMode MASK
  float3 absorption;  // absorption coefficient of the medium inside (per world unit); 0: clear
  // KHR_materials_anisotropy: the GGX roughness along the direction grows to
  // lerp(alpha, 1, strength^2) (Disney's `anisotropic` composes with it).
  float anisotropyStrength;
  float2 anisotropyDirection;  // (cos, sin) of the rotation from the tangent towards the bitangent
  uint anisotropyTexture;  // rg: direction in tangent space, rotated further; b: scales strength
  // glTF's coat normal map (tangent space, xy scaled by clearcoatNormalScale);
  // without it the glTF coat follows the vertex normal.
  uint clearcoatNormalTexture;
  // Multiplies the dielectric F0 per channel before its clamp to 1 (glTF
  // KHR_materials_specular's colour times F0(ior) / 0.08; 1 for Disney).
  float3 specularColor;
  uint sheenRoughnessTexture;  // alpha scales sheenRoughness
  float3 sheenColor;  // multiplies the sheen per channel (glTF's sheen colour's hue; 1 for Disney)
  float sheenRoughness;  // glTF's sheen fibres (MATERIAL_FLAG_CHARLIE_SHEEN); unused by Disney's
  float clearcoatNormalScale;
  // KHR_materials_diffuse_transmission: the share of the diffuse lobe
  // transmitted (Lambertian, to the other side) with this colour.
  float diffuseTransmission;
  uint diffuseTransmissionTexture;       // alpha scales diffuseTransmission
  uint diffuseTransmissionColorTexture;  // rgb (sRGB) scales diffuseTransmissionColor
  float3 diffuseTransmissionColor;
  float specularF90;  // the dielectric layer's grazing reflectance at most (glTF's specularFactor)
  // KHR_materials_iridescence: the share of the specular layer's reflectance
  // that is the thin film's, the film's index and its thickness in nm
  // (minimum, maximum): the thickness texture's green picks between them,
  // else the maximum holds.
  float iridescence;
  float iridescenceIor;
  float2 iridescenceThickness;
  uint iridescenceTexture;           // red scales iridescence
  uint iridescenceThicknessTexture;  // green: the thickness between minimum and maximum
  // KHR_materials_dispersion: 20 / Abbe number of a refracting volume
  // (spectrum.hlsli); 0: one index for every wavelength.
  float dispersion;
  uint unused1;
};

// One use of a texture (scene::TextureRef): uv' = c0 * u + c1 * v + c2 on the
// chosen texture coordinates (KHR_texture_transform), then sampled at the
// mip level of the ray's footprint (textures.hlsli).
struct TextureRefData {
  float2 column0;  // c0
  float2 column1;  // c1
  float2 column2;  // c2
  float2 unused0;
  uint textureIndex;  // into PT_T_TEXTURES
  uint samplerIndex;  // into PT_S_SAMPLERS
  uint texCoordSet;   // 0: TEXCOORD_0, 1: TEXCOORD_1
  // 0.5 log2 of the texels one unit of the set's texture-coordinate area
  // covers: width x height x |det(c0, c1)|. A footprint's level is this plus
  // its own (SurfaceHit.textureFootprint).
  float lodOffset;
};

// A delta light: point, spot or directional (scene::PointLight).
struct PointLight {
  float3 position;  // render space; none for a directional light
  // A spot light's cos(inner cone angle); a directional light's cos(angular
  // radius) (1: a delta light; less: a soft sun).
  float cosInner;
  float3 intensity;  // radiant intensity (W/sr); a directional light's irradiance (W/m^2)
  float range;       // beyond which the light does not reach (0: no limit)
  float3 direction;  // the direction a spot light faces or a directional light travels
  float cosOuter;    // a spot light's cos(outer cone angle)
  uint type;         // PT_LIGHT_*
  uint unused0;
  uint unused1;
  uint unused2;
};
#define PT_LIGHT_POINT 0u
#define PT_LIGHT_SPOT 1u
#define PT_LIGHT_DIRECTIONAL 2u
// A directional light's shadow rays end this far away (world units).
#define PT_DIRECTIONAL_SHADOW_LENGTH 1e30

// The environment map's layout and placement (shaders/shared/environment.hlsli).
struct EnvironmentData {
  uint width;  // texels
  uint height;
  uint unused0;
  uint unused1;
  float cosRotation;  // of the rotation about +y
  float sinRotation;
  float intensity;  // scales the radiance
  float unused2;
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
  float3 boundsMin;  // object-space box holding the surface
  float tolerance;   // sphere tracing: a hit is this close
  float3 boundsMax;
  float blendRadius;   // IMPLICIT_BLEND: the smooth union's radius
  uint kind;           // IMPLICIT_*
  uint instanceIndex;  // InstanceData index
  uint maxSteps;       // sphere tracing
  uint blendCount;     // IMPLICIT_BLEND: primitives used of blendKinds/Offsets/Shapes
  uint4 blendKinds;    // IMPLICIT_* kind of each blend primitive (one per component)
  float4 blendOffsets[IMPLICIT_MAX_BLEND_PRIMITIVES];  // xyz: where each primitive's origin lies
  float4 blendShapes[IMPLICIT_MAX_BLEND_PRIMITIVES];   // each primitive's parameters, as `shape`
};

// A world-space ray of PathTracer::traceProbeRays (tMin 0).
struct ProbeRay {
  float3 origin;
  float tMax;
  float3 direction;  // hitT is in units of its length
  float unused0;
};

// What the closest hit reported for one ProbeRay (SurfaceHit's fields).
struct ProbeHit {
  float3 position;  // world
  float hitT;       // < 0: a miss
  float3 normal;    // geometric, front side
  float unused0;
  uint instanceIndex;
  uint primitiveIndex;
  uint unused1;
  uint unused2;
};

#ifdef __cplusplus
static_assert(sizeof(ImplicitData) == 256);
static_assert(offsetof(ImplicitData, boundsMin) == 64 && offsetof(ImplicitData, boundsMax) == 80 &&
              offsetof(ImplicitData, kind) == 96);
static_assert(offsetof(ImplicitData, blendOffsets) == 128);
static_assert(offsetof(ImplicitData, blendShapes) == 192);
static_assert(sizeof(ProbeRay) == 32 && offsetof(ProbeRay, direction) == 16);
static_assert(sizeof(ProbeHit) == 48 && offsetof(ProbeHit, normal) == 16 &&
              offsetof(ProbeHit, instanceIndex) == 32);
// The offsets std430 and HLSL packing give (each float3 opens a 16-byte row).
static_assert(sizeof(FrameConstants) == 128);
static_assert(offsetof(FrameConstants, width) == 64 && offsetof(FrameConstants, seed) == 80 &&
              offsetof(FrameConstants, emissiveTriangleCount) == 96 &&
              offsetof(FrameConstants, ambient) == 112 &&
              offsetof(FrameConstants, radianceClamp) == 124);
static_assert(sizeof(PointLight) == 64 && offsetof(PointLight, intensity) == 16 &&
              offsetof(PointLight, direction) == 32 && offsetof(PointLight, type) == 48);
static_assert(sizeof(InstanceData) == 128 && offsetof(InstanceData, objectToWorld0) == 16 &&
              offsetof(InstanceData, vertexAttributes) == 112);
static_assert(sizeof(MaterialData) == 288 && offsetof(MaterialData, emission) == 16 &&
              offsetof(MaterialData, metallic) == 32 && offsetof(MaterialData, model) == 96 &&
              offsetof(MaterialData, baseColorTexture) == 112 &&
              offsetof(MaterialData, normalScale) == 144 &&
              offsetof(MaterialData, absorption) == 160 &&
              offsetof(MaterialData, anisotropyDirection) == 176 &&
              offsetof(MaterialData, specularColor) == 192 &&
              offsetof(MaterialData, sheenColor) == 208 &&
              offsetof(MaterialData, sheenRoughness) == 220 &&
              offsetof(MaterialData, clearcoatNormalScale) == 224 &&
              offsetof(MaterialData, diffuseTransmissionColor) == 240 &&
              offsetof(MaterialData, specularF90) == 252 &&
              offsetof(MaterialData, iridescenceThickness) == 264 &&
              offsetof(MaterialData, dispersion) == 280);
static_assert(sizeof(TextureRefData) == 48 && offsetof(TextureRefData, column2) == 16 &&
              offsetof(TextureRefData, textureIndex) == 32 &&
              offsetof(TextureRefData, lodOffset) == 44);
static_assert(sizeof(EmissiveTriangle) == 96 && offsetof(EmissiveTriangle, p1) == 16 &&
              offsetof(EmissiveTriangle, emissionTexture) == 44 &&
              offsetof(EmissiveTriangle, uv0) == 64 && offsetof(EmissiveTriangle, uv2) == 80);
static_assert(sizeof(EnvironmentData) == 32 && offsetof(EnvironmentData, cosRotation) == 16);
}  // namespace penumbra::gpu
#endif
#endif
