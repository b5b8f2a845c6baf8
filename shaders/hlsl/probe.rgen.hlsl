// PathTracer::traceProbeRays (DXR twin of glsl/probe.rgen): one radiance ray
// per dispatch index through the production hit groups.
#include "path_trace_common.hlsli"
#include "probe.hlsli"

StructuredBuffer<ProbeRay> gProbeRays : PENUMBRA_REGISTER_T(PT_T_PROBE_RAYS);
RWStructuredBuffer<ProbeHit> gProbeHits : PENUMBRA_REGISTER_U(PT_U_PROBE_HITS);

[shader("raygeneration")]
void main() {
  uint index = DispatchRaysIndex().x;
  ProbeRay probe = gProbeRays[index];
  RayDesc ray;
  ray.Origin = probe.origin.xyz;
  ray.Direction = probe.direction.xyz;
  ray.TMin = 0.0;
  ray.TMax = probe.origin.w;
  HitRecord record = hitRecordMiss();
  TraceRay(gScene, RAY_FLAG_NONE, 0xff, PT_RAY_CONTRIBUTION, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_RADIANCE, ray, record);
  gProbeHits[index] = packProbeHit(surfaceFromRecord(ray.Origin, ray.Direction, record));
}
