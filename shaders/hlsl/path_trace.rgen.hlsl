// Ray generation of the path tracer (DXR twin of glsl/path_trace.rgen): the
// same camera, stratified samples, RNG and integrator from shaders/shared,
// so D3D12 and Vulkan render the same image.
#include "trace_wrappers.hlsli"

RWTexture2D<float4> gGuideAlbedo : PENUMBRA_REGISTER_U(PT_U_GUIDE_ALBEDO);
RWTexture2D<float4> gGuideNormalDepth : PENUMBRA_REGISTER_U(PT_U_GUIDE_NORMAL_DEPTH);
RWTexture2D<float4> gGuideEmission : PENUMBRA_REGISTER_U(PT_U_GUIDE_EMISSION);
RWTexture2D<float4> gGuideMoments : PENUMBRA_REGISTER_U(PT_U_GUIDE_MOMENTS);

// The guide buffers hold running means over all samples, as gAccumulation
// holds the radiance's: the guides one sample at a time, as its path closes
// them; the moments once per frame.
uint2 launchPixel() { return DispatchRaysIndex().xy; }
FrameConstants frameConstants() { return gPush.frame; }

float4 runningMean(float4 previous, float4 sum, uint samples, uint before) {
  return before > 0u ? (previous * float(before) + sum) / float(before + samples) : sum / float(samples);
}

void addGuideSample(uint2 p, uint samplesBefore, float3 albedo, float4 normalDepth, float3 emission) {
  gGuideAlbedo[p] = runningMean(gGuideAlbedo[p], float4(albedo, 0.0), 1u, samplesBefore);
  gGuideNormalDepth[p] = runningMean(gGuideNormalDepth[p], normalDepth, 1u, samplesBefore);
  gGuideEmission[p] = runningMean(gGuideEmission[p], float4(emission, 0.0), 1u, samplesBefore);
}

#include "path_tracer.hlsli"

[shader("raygeneration")]
void main() {
  FrameConstants frame = gPush.frame;
  uint2 pixel = DispatchRaysIndex().xy;
  float2 moments;
  float3 sum = tracePixel(moments);
  accumulate(pixel, sum, frame.image.z, frame.image.w);
#if PT_HAS_EFFECT(PT_OUTPUT_GUIDES)
  gGuideMoments[pixel] = runningMean(gGuideMoments[pixel], float4(moments, 0.0, 0.0), frame.image.z, frame.image.w);
#endif
}
