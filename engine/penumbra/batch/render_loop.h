#pragma once
// The loop every batch render runs (`penumbra render`, `penumbra study`):
// samples in frames of up to 16 per pixel, each timed on the GPU, with the
// denoiser where one is asked for.
#include <cstdint>
#include <functional>

#include "penumbra/render/denoiser.h"
#include "penumbra/render/path_tracer.h"

namespace penumbra::render {

struct RenderLoopResult {
  double gpuSeconds = 0;      // path tracing, GPU timestamps
  double denoiseSeconds = 0;  // the denoiser's passes, GPU timestamps
  uint64_t rays = 0;
};

// Renders `spp` samples per pixel (frames of `sppPerFrame`) into a fresh
// accumulation. With `denoiser` (and settings.mode not Off): Svgf denoises
// every frame, each frame a mean of its own new samples; Atrous filters the
// final mean once. `settings.writeGuides` must be set for a denoiser.
// `progress` gets the samples done after each frame. The image is then
// denoiser->output() with a denoiser, tracer.accumulation() without.
RenderLoopResult renderSamples(PathTracer& tracer, Denoiser* denoiser,
                               const PathTracerSettings& settings, const DenoiserSettings& denoise,
                               uint32_t spp, uint32_t sppPerFrame,
                               const std::function<void(uint32_t)>& progress = {});

}  // namespace penumbra::render
