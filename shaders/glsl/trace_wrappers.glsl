// traceClosest / traceVisibility for ray-generation shaders that declare the
// gHit (HitRecord) and gVisible payloads and the gRaysThisLaunch counter, plus the
// running-mean accumulation into gAccumulation.
// No opaque ray flag: geometry decides, and only alpha-masked meshes are
// non-opaque (their any-hit shader cuts texels away for both kinds of ray).
SurfaceHit traceClosest(float3 origin, float3 direction) {
  gRaysThisLaunch += 1u;
  traceRayEXT(gScene, gl_RayFlagsNoneEXT, 0xff, PT_RAY_RADIANCE, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_RADIANCE, origin,
              0.0, direction, 1e30, PT_PAYLOAD_RADIANCE);
  return surfaceFromRecord(origin, direction, gHit);
}

bool traceVisibility(float3 origin, float3 direction, float tMax) {
  gRaysThisLaunch += 1u;
  gVisible = 0u;
  traceRayEXT(gScene,
              gl_RayFlagsTerminateOnFirstHitEXT |
                  gl_RayFlagsSkipClosestHitShaderEXT,
              0xff, PT_RAY_SHADOW, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_SHADOW, origin, 0.0, direction, tMax,
              PT_PAYLOAD_SHADOW);
  return gVisible != 0u;
}

// Running mean over all frames: mean_n = (mean_{n-1} * before + sum) / n.
void accumulate(uint2 pixel, float3 sum, uint samples, uint before) {
  float3 previous = before > 0u ? imageLoad(gAccumulation, int2(pixel)).xyz : zero3();
  float3 mean = (previous * float(before) + sum) / float(before + samples);
  imageStore(gAccumulation, int2(pixel), float4(mean, 1.0));
  atomicAdd(gRayCount, gRaysThisLaunch);
}
