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
#define PT_U_ACCUMULATION 0        // RGBA32F running mean
#define PT_U_RAY_COUNTER 1         // uint: rays traced this dispatch
#define PT_SLOT_SCENE PENUMBRA_T(PT_T_SCENE)
#define PT_SLOT_VERTICES PENUMBRA_T(PT_T_VERTICES)
#define PT_SLOT_INDICES PENUMBRA_T(PT_T_INDICES)
#define PT_SLOT_INSTANCES PENUMBRA_T(PT_T_INSTANCES)
#define PT_SLOT_MATERIALS PENUMBRA_T(PT_T_MATERIALS)
#define PT_SLOT_EMISSIVE_TRIANGLES PENUMBRA_T(PT_T_EMISSIVE_TRIANGLES)
#define PT_SLOT_ACCUMULATION PENUMBRA_U(PT_U_ACCUMULATION)
#define PT_SLOT_RAY_COUNTER PENUMBRA_U(PT_U_RAY_COUNTER)

// FrameConstants.sampling.w bits.
#define PT_FLAG_NEE 1u              // next-event estimation on emissive triangles
#define PT_FLAG_MIS 2u              // MIS (power heuristic) between NEE and BSDF sampling
#define PT_FLAG_RUSSIAN_ROULETTE 4u

#define PT_NO_EMISSION 0xffffffffu

// Push constants (D3D12 root constants), 112 bytes.
struct FrameConstants {
  float4 cameraPosition;  // xyz; w = tan(vertical fov / 2)
  float4 cameraRight;     // xyz unit vector; w = aspect ratio (width / height)
  float4 cameraUp;        // xyz unit vector
  float4 cameraForward;   // xyz unit vector
  uint4 image;            // x width, y height, z samples this frame, w samples accumulated before
  uint4 sampling;         // x seed, y max depth (bounces), z Russian roulette start depth, w flags
  uint4 lights;           // x emissive triangle count
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

struct MaterialData {
  float4 albedo;    // rgb diffuse reflectance
  float4 emission;  // rgb radiance, emitted from the front (counter-clockwise) face
};

// An emitting triangle in world space, for next-event estimation.
struct EmissiveTriangle {
  float4 p0;        // w: probability of choosing this triangle
  float4 p1;        // w: area
  float4 p2;
  float4 radiance;  // rgb; w: cumulative probability up to and including this one
};

#ifdef __cplusplus
static_assert(sizeof(FrameConstants) == 112);
static_assert(sizeof(InstanceData) == 16);
static_assert(sizeof(MaterialData) == 32);
static_assert(sizeof(EmissiveTriangle) == 64);
}  // namespace penumbra::gpu
#endif
#endif
