// The radiance ray's payload: what a closest-hit shader knows that the ray
// generation shader cannot recompute (which primitive, where on it), 24
// bytes. The ray generation shader rebuilds the full SurfaceHit from it
// (surface_from_record.hlsli). Whatever a payload holds is saved and
// restored around every trace call and every hit shader, so the hit shaders
// only store these few words and all surface reconstruction runs after the
// trace, once per ray, in the ray generation shader.
#ifndef PENUMBRA_HIT_RECORD_HLSLI
#define PENUMBRA_HIT_RECORD_HLSLI

// primitive's top bit: the hit is the implicit object ImplicitData[rest].
#define PT_HIT_IMPLICIT 0x80000000u

// RayTracingPipelineDesc::maxPayloadBytes of the path tracer: 24.
struct HitRecord {
  float hitT;          // < 0: the ray missed everything
  uint instance;       // InstanceData index (triangles; implicits find theirs in ImplicitData)
  uint primitive;      // triangle within the mesh, or PT_HIT_IMPLICIT | ImplicitData index
  float3 attributes;   // triangles: barycentrics (b1, b2, 0); implicits: object-space normal
};

HitRecord hitRecordMiss() {
  HitRecord r;
  r.hitT = -1.0;
  r.instance = 0u;
  r.primitive = 0u;
  r.attributes = float3(0.0, 0.0, 0.0);
  return r;
}

#endif
