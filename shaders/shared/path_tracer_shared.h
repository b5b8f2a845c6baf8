// Data shared by the host and the path-tracing shaders. Every struct is made
// of 16-byte vectors so std430 (Vulkan) and HLSL structured-buffer layouts
// match the C++ layout; the C++ side static_asserts the sizes.
#ifndef PENUMBRA_PATH_TRACER_SHARED_H
#define PENUMBRA_PATH_TRACER_SHARED_H

#ifdef __cplusplus
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
#define PT_T_TEXCOORDS 9           // float4 per vertex: xy TEXCOORD_0 (0 without); zw reserved (0)
#define PT_U_ACCUMULATION 0        // RGBA32F running mean
#define PT_U_RAY_COUNTER 1         // uint: rays traced this dispatch
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
#define PT_SLOT_ACCUMULATION PENUMBRA_U(PT_U_ACCUMULATION)
#define PT_SLOT_RAY_COUNTER PENUMBRA_U(PT_U_RAY_COUNTER)

// FrameConstants.sampling.w bits.
#define PT_FLAG_NEE 1u               // next-event estimation on emissive triangles and point lights
#define PT_FLAG_MIS 2u               // MIS between NEE and BSDF sampling (area lights only)
#define PT_FLAG_RUSSIAN_ROULETTE 4u
#define PT_FLAG_BALANCE_HEURISTIC 8u // balance instead of power heuristic
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

#define PT_NO_EMISSION 0xffffffffu

// Push constants (D3D12 root constants), 128 bytes: the most Vulkan guarantees.
struct FrameConstants {
  float4 cameraPosition;  // xyz; w = tan(vertical fov / 2)
  float4 cameraRight;     // xyz unit vector; w = aspect ratio (width / height)
  float4 cameraUp;        // xyz unit vector
  float4 cameraForward;   // xyz unit vector
  uint4 image;            // x width, y height, z samples this frame, w samples accumulated before
  uint4 sampling;         // x seed, y max depth (bounces), z Russian roulette start depth, w flags
  uint4 lights;           // x emissive triangle count, y point light count
  float4 shading;         // xyz Whitted ambient radiance; w radiance clamp per sample (0 = off)
};

// One per top-level instance: where its mesh lies in the shared vertex and
// index buffers, its material, and its emitters (instances of an emissive mesh
// each get their own world-space EmissiveTriangles).
struct InstanceData {
  uint firstIndex;             // into the index buffer
  uint firstVertex;            // added to each index
  uint materialIndex;
  uint firstEmissiveTriangle;  // PT_NO_EMISSION, or this mesh's first EmissiveTriangle
};

// Disney parameters (docs/materials.md) and the Phong parameters of Whitted.
struct MaterialData {
  float4 baseColor;  // rgb; Phong: kd
  float4 emission;   // rgb radiance, emitted from the front (counter-clockwise) face
  float4 disney0;    // x metallic, y roughness, z anisotropic, w specular
  float4 disney1;    // x specularTint, y sheen, z sheenTint, w clearcoat
  float4 disney2;    // x clearcoatGloss, y specTrans, z ior, w subsurface
  float4 phong;      // x ks, y exponent, z reflectivity, w transparency (ior: disney2.z)
  uint4 flags;       // x MATERIAL_MODEL_*, y MATERIAL_FLAG_* bits
};

// A point or spot light: a delta light, sampled by next-event estimation only.
struct PointLight {
  float4 position;   // xyz; w cos(inner cone angle) of a spot light
  float4 intensity;  // rgb radiant intensity (W/sr)
  float4 spot;       // xyz direction a spot light faces; w cos(outer cone angle), -2 for a point light
};

// An emitting triangle in world space, for next-event estimation.
struct EmissiveTriangle {
  float4 p0;        // w: probability of choosing this triangle
  float4 p1;        // w: area
  float4 p2;
  float4 radiance;  // rgb; w: cumulative probability up to and including this one
};

#ifdef __cplusplus
static_assert(sizeof(FrameConstants) == 128);
static_assert(sizeof(PointLight) == 48);
static_assert(sizeof(InstanceData) == 16);
static_assert(sizeof(MaterialData) == 112);
static_assert(sizeof(EmissiveTriangle) == 64);
}  // namespace penumbra::gpu
#endif
#endif
