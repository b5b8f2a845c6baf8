// traceClosest / traceVisibility and the running-mean accumulation for the
// DXR ray-generation shaders: the twin of glsl/trace_wrappers.glsl.
#ifndef PENUMBRA_TRACE_WRAPPERS_HLSLI
#define PENUMBRA_TRACE_WRAPPERS_HLSLI
#include "path_trace_common.hlsli"

static uint gRaysThisLaunch = 0u;

// No opaque ray flag: geometry decides, and only alpha-masked meshes are
// non-opaque (their any-hit shader cuts texels away for both kinds of ray).
// Shadow rays carry the HitRecord too, so both kinds can leave from one call
// site: they skip closest hits and stop at the first one, leaving the record
// as it was (hitT 0), and the radiance miss shader marks a miss (hitT < 0).
HitRecord traceRay(float3 origin, float3 direction, float tMax, bool shadow) {
  gRaysThisLaunch += 1u;
  RayDesc ray;
  ray.Origin = origin;
  ray.Direction = direction;
  ray.TMin = 0.0;
  ray.TMax = tMax;
  HitRecord record = hitRecordMiss();
  record.hitT = 0.0;
  TraceRay(gScene, shadow ? RAY_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH | RAY_FLAG_SKIP_CLOSEST_HIT_SHADER : RAY_FLAG_NONE,
           0xff, PT_RAY_CONTRIBUTION, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_RADIANCE, ray, record);
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
  float3 previous = before > 0u ? gAccumulation[pixel].xyz : zero3();
  float3 mean = (previous * float(before) + sum) / float(before + samples);
  gAccumulation[pixel] = float4(mean, 1.0);
  InterlockedAdd(gRayCounter[0], gRaysThisLaunch);
}

#endif
