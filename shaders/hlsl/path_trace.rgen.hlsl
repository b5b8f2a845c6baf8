// Ray generation of the path tracer (DXR twin of glsl/path_trace.rgen): the
// same camera, stratified samples, RNG and integrator from shaders/shared,
// so D3D12 and Vulkan render the same image.
#include "trace_wrappers.hlsli"
#include "camera.hlsli"
#include "path_tracer.hlsli"
#include "guide_sums.hlsli"

RWTexture2D<float4> gGuideAlbedo : PENUMBRA_REGISTER_U(PT_U_GUIDE_ALBEDO);
RWTexture2D<float4> gGuideNormalDepth : PENUMBRA_REGISTER_U(PT_U_GUIDE_NORMAL_DEPTH);
RWTexture2D<float4> gGuideEmission : PENUMBRA_REGISTER_U(PT_U_GUIDE_EMISSION);
RWTexture2D<float4> gGuideMoments : PENUMBRA_REGISTER_U(PT_U_GUIDE_MOMENTS);

// Running means over all frames, as accumulate() keeps the radiance's.
float4 runningMean(float4 previous, float4 sum, uint samples, uint before) {
  return before > 0u ? (previous * float(before) + sum) / float(before + samples) : sum / float(samples);
}

void accumulateGuides(uint2 p, GuideSums g, uint samples, uint before) {
  gGuideAlbedo[p] = runningMean(gGuideAlbedo[p], float4(g.albedo, 0.0), samples, before);
  gGuideNormalDepth[p] = runningMean(gGuideNormalDepth[p], g.normalDepth, samples, before);
  gGuideEmission[p] = runningMean(gGuideEmission[p], float4(g.emission, 0.0), samples, before);
  gGuideMoments[p] = runningMean(gGuideMoments[p], float4(g.moments, 0.0, 0.0), samples, before);
}

[shader("raygeneration")]
void main() {
  FrameConstants frame = gPush.frame;
  uint2 pixel = DispatchRaysIndex().xy;
  uint samples = frame.image.z;
  uint before = frame.image.w;
  float3 sum = zero3();
  GuideSums guides = noGuideSums();
  for (uint s = 0u; s < samples; s += 1u) {
    Rng rng = rngCreate(pixel, frame.lights.z + before + s, frame.sampling.x);
    float2 jitter = jitteredPixelSample(s, samples, rngNext(rng), rngNext(rng));
    float3 direction = cameraRayDirection(frame, float2(pixel) + jitter);
    PathGuides g;
    float3 radiance = tracePath(frame, frame.cameraPosition.xyz, direction, rng, g);
    sum += radiance;
    addGuides(guides, g, radiance, dot(direction, frame.cameraForward.xyz));
  }
  accumulate(pixel, sum, samples, before);
  accumulateGuides(pixel, guides, samples, before);
}
