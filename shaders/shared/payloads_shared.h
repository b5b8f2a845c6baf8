// What travels between the ray-tracing stages, read by the shaders and by the
// C++ that sizes the pipeline (RayTracingPipelineDesc::maxPayloadBytes and
// maxAttributeBytes): every ray's payload and the implicit hit groups'
// attributes. Whatever a payload holds is saved and restored around every
// trace call and every hit shader, so it holds only what the ray generation
// shader cannot recompute: which primitive, and where on it. The ray
// generation shader rebuilds the full SurfaceHit from it
// (surface_from_record.hlsli).
#ifndef PENUMBRA_PAYLOADS_SHARED_H
#define PENUMBRA_PAYLOADS_SHARED_H

#ifdef __cplusplus
#include "shader_types.h"
namespace penumbra::gpu {
#endif

// primitive's top bit: the hit is the implicit object ImplicitData[rest].
#define PT_HIT_IMPLICIT 0x80000000u

// The payload of radiance and shadow rays alike.
struct HitRecord {
  float hitT;         // < 0: the ray missed everything
  uint instance;      // InstanceData index (triangles; implicits find theirs in ImplicitData)
  uint primitive;     // triangle within the mesh, or PT_HIT_IMPLICIT | ImplicitData index
  float3 attributes;  // triangles: barycentrics (b1, b2, 0); implicits: object-space normal
};

// Hit attributes of the implicit hit groups (triangles' built-in ones are
// 8 bytes of barycentrics; DXR allows 32).
struct ImplicitAttributes {
  float3 objectNormal;
};

#ifdef __cplusplus
static_assert(sizeof(HitRecord) == 24);
static_assert(sizeof(ImplicitAttributes) == 12);
}  // namespace penumbra::gpu
#endif
#endif
