// traceClosest / traceVisibility and the running-mean accumulation for the
// DXR ray-generation shaders: the twin of glsl/trace_wrappers.glsl.
#ifndef PENUMBRA_TRACE_WRAPPERS_HLSLI
#define PENUMBRA_TRACE_WRAPPERS_HLSLI
#include "path_trace_common.hlsli"

static uint gRaysThisLaunch = 0u;

// No opaque ray flag: geometry decides, and only alpha-masked meshes are
// non-opaque (their any-hit shader cuts texels away for both kinds of ray).
SurfaceHit traceClosest(float3 origin, float3 direction) {
  gRaysThisLaunch += 1u;
  RayDesc ray;
  ray.Origin = origin;
  ray.Direction = direction;
  ray.TMin = 0.0;
  ray.TMax = 1e30;
  HitRecord record = hitRecordMiss();
  TraceRay(gScene, RAY_FLAG_NONE, 0xff, PT_RAY_RADIANCE, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_RADIANCE, ray, record);
  return surfaceFromRecord(origin, direction, record);
}

bool traceVisibility(float3 origin, float3 direction, float tMax) {
  gRaysThisLaunch += 1u;
  RayDesc ray;
  ray.Origin = origin;
  ray.Direction = direction;
  ray.TMin = 0.0;
  ray.TMax = tMax;
  ShadowPayload shadow;
  shadow.visible = 0u;
  TraceRay(gScene,
           RAY_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH |
               RAY_FLAG_SKIP_CLOSEST_HIT_SHADER,
           0xff, PT_RAY_SHADOW, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_SHADOW, ray, shadow);
  return shadow.visible != 0u;
}

// Running mean over all frames: mean_n = (mean_{n-1} * before + sum) / n.
void accumulate(uint2 pixel, float3 sum, uint samples, uint before) {
  float3 previous = before > 0u ? gAccumulation[pixel].xyz : zero3();
  float3 mean = (previous * float(before) + sum) / float(before + samples);
  gAccumulation[pixel] = float4(mean, 1.0);
  InterlockedAdd(gRayCounter[0], gRaysThisLaunch);
}

#endif
