#pragma once
// Helpers of the renderer tests: render a scene on the test device.
#include "image/image.h"
#include "render/path_tracer.h"
#include "test_device.h"

namespace penumbra::test {

// Renders `spp` samples per pixel in frames of up to 16 and returns the mean.
inline image::Image renderScene(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                                uint32_t height, uint32_t spp,
                                const render::PathTracerSettings& settings = {}) {
  render::PathTracer tracer(device, scene, width, height);
  while (tracer.accumulatedSamples() < spp)
    tracer.renderFrame(settings, std::min(render::PathTracer::kMaxSamplesPerFrame,
                                          spp - tracer.accumulatedSamples()));
  return tracer.readback();
}

}  // namespace penumbra::test
