// traceRay (the integrator's one trace call) and traceClosest /
// traceVisibility over it, for ray-generation shaders that declare the gHit
// (HitRecord) payload and the gRaysThisLaunch counter, plus the running-mean
// accumulation into gAccumulation.
// No opaque ray flag: geometry decides, and only alpha-masked meshes are
// non-opaque (their any-hit shader cuts texels away for both kinds of ray).
// Shadow rays carry the HitRecord too, so both kinds can leave from one call
// site: they skip closest hits and stop at the first one, leaving the record
// as it was (hitT 0), and the radiance miss shader marks a miss (hitT < 0).
HitRecord traceRay(float3 origin, float3 direction, float tMax, bool shadow) {
  gRaysThisLaunch += 1u;
  gHit.hitT = 0.0;
  traceRayEXT(gScene, shadow ? gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT : gl_RayFlagsNoneEXT,
              0xff, PT_RAY_CONTRIBUTION, PT_GEOMETRY_HIT_GROUP_STRIDE, PT_MISS_RADIANCE, origin,
              0.0, direction, tMax, PT_PAYLOAD_RADIANCE);
  return gHit;
}

SurfaceHit traceClosest(float3 origin, float3 direction) {
  return surfaceFromRecord(origin, direction, traceRay(origin, direction, 1e30, false));
}

bool traceVisibility(float3 origin, float3 direction, float tMax) {
  return traceRay(origin, direction, tMax, true).hitT < 0.0;
}

// Running mean over all frames: mean_n = (mean_{n-1} * before + sum) / n.
void accumulate(uint2 pixel, float3 sum, uint samples, uint before) {
  float3 previous = before > 0u ? imageLoad(gAccumulation, int2(pixel)).xyz : zero3();
  float3 mean = (previous * float(before) + sum) / float(before + samples);
  imageStore(gAccumulation, int2(pixel), float4(mean, 1.0));
  atomicAdd(gRayCount, gRaysThisLaunch);
}
