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
  return render::renderImage(device, scene, width, height, spp, settings);
}

}  // namespace penumbra::test
