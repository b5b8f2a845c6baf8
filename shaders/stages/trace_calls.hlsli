// The ray-generation shaders' one trace call (traceRay) and what is built on
// it (traceClosest, traceVisibility), with the running-mean accumulation into
// gAccumulation and the count of rays traced (gRayCounter).
#ifndef PENUMBRA_TRACE_CALLS_HLSLI
#define PENUMBRA_TRACE_CALLS_HLSLI
#include "path_trace_resources.hlsli"

PT_TRACE_PAYLOAD(HitRecord);
static uint gRaysThisLaunch = 0u;

// No opaque ray flag: geometry decides, and only alpha-masked meshes are
// non-opaque (their any-hit shader cuts texels away for both kinds of ray).
// Shadow rays carry the HitRecord too, so both kinds can leave from one call
// site: they skip closest hits and stop at the first one, leaving the record
// as it was (hitT 0), and the radiance miss shader marks a miss (hitT < 0).
HitRecord traceRay(float3 origin, float3 direction, float tMax, bool shadow) {
  gRaysThisLaunch += 1u;
  HitRecord record = hitRecordMiss();
  record.hitT = 0.0;
  PT_TRACE_RAY(gScene, shadow ? PT_RAY_FLAG_SHADOW : PT_RAY_FLAG_NONE, PT_RAY_CONTRIBUTION,
               PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_RADIANCE, origin, 0.0, direction, tMax, record);
  return record;
}

SurfaceHit traceClosest(float3 origin, float3 direction) {
  return surfaceFromRecord(origin, direction, traceRay(origin, direction, 1e30, false));
}

bool traceVisibility(float3 origin, float3 direction, float tMax) {
  return traceRay(origin, direction, tMax, true).hitT < 0.0;
}

// Running mean over all frames: mean_n = (mean_{n-1} * before + sum) / n.
void accumulate(uint2 pixel, float3 sum, uint samples, uint before) {
  float3 previous = before > 0u ? PT_LOAD_RW_TEXTURE(gAccumulation, pixel).xyz : zero3();
  float3 mean = (previous * float(before) + sum) / float(before + samples);
  PT_STORE_RW_TEXTURE(gAccumulation, pixel, float4(mean, 1.0));
  PT_ATOMIC_ADD(gRayCounter[0], gRaysThisLaunch);
}

#endif
