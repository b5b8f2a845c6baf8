// Ray generation of the path tracer (DXR twin of glsl/path_trace.rgen): the
// same camera, stratified samples, RNG and integrator from shaders/shared,
// so D3D12 and Vulkan render the same image.
#include "path_trace_common.hlsli"

static uint gRaysThisLaunch = 0u;

SurfaceHit traceClosest(float3 origin, float3 direction) {
  gRaysThisLaunch += 1u;
  RayDesc ray;
  ray.Origin = origin;
  ray.Direction = direction;
  ray.TMin = 0.0;
  ray.TMax = 1e30;
  SurfaceHit hit = surfaceMiss();
  // Hit group offset 0, geometry multiplier 1, as in the GLSL twin.
  TraceRay(gScene, RAY_FLAG_FORCE_OPAQUE, 0xff, 0, 1, PT_MISS_RADIANCE, ray, hit);
  return hit;
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
           RAY_FLAG_FORCE_OPAQUE | RAY_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH |
               RAY_FLAG_SKIP_CLOSEST_HIT_SHADER,
           0xff, 0, 1, PT_MISS_SHADOW, ray, shadow);
  return shadow.visible != 0u;
}

#include "camera.hlsli"
#include "path_tracer.hlsli"

[shader("raygeneration")]
void main() {
  FrameConstants frame = gPush.frame;
  uint2 pixel = DispatchRaysIndex().xy;
  uint samples = frame.image.z;
  uint before = frame.image.w;
  float3 sum = zero3();
  for (uint s = 0u; s < samples; s += 1u) {
    Rng rng = rngCreate(pixel, before + s, frame.sampling.x);
    float2 jitter = jitteredPixelSample(s, samples, rngNext(rng), rngNext(rng));
    float3 direction = cameraRayDirection(frame, float2(pixel) + jitter);
    sum += tracePath(frame, frame.cameraPosition.xyz, direction, rng);
  }
  // Running mean over all frames: mean_n = (mean_{n-1} * before + sum) / n.
  float3 previous = before > 0u ? gAccumulation[pixel].xyz : zero3();
  float total = float(before + samples);
  float3 mean = (previous * float(before) + sum) / total;
  gAccumulation[pixel] = float4(mean, 1.0);
  InterlockedAdd(gRayCounter[0], gRaysThisLaunch);
}
