// Ray generation of the path tracer (DXR twin of glsl/path_trace.rgen): the
// same camera, stratified samples, RNG and integrator from shaders/shared,
// so D3D12 and Vulkan render the same image.
#include "trace_wrappers.hlsli"
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
  accumulate(pixel, sum, samples, before);
}
