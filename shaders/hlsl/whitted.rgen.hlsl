// Whitted ray tracing (DXR twin of glsl/whitted.rgen).
#include "trace_wrappers.hlsli"
#include "camera.hlsli"
#include "whitted.hlsli"

[shader("raygeneration")]
void main() {
  FrameConstants frame = gPush.frame;
  uint2 pixel = DispatchRaysIndex().xy;
  uint samples = frame.image.z;
  uint before = frame.image.w;
  float3 sum = zero3();
  for (uint s = 0u; s < samples; s += 1u) {
    Rng rng = sampleRng(frame, pixel, frame.lights.z + before + s);
    float2 jitter = pixelSample(rng, s, samples);
    float3 origin;
    float3 direction;
    cameraRay(frame, float2(pixel) + jitter, rng, origin, direction);
    sum += traceWhitted(frame, origin, direction);
  }
  accumulate(pixel, sum, samples, before);
}
