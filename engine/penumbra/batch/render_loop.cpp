#include "penumbra/batch/render_loop.h"

#include <algorithm>

#include "penumbra/util/error.h"

namespace penumbra::render {

RenderLoopResult renderSamples(PathTracer& tracer, Denoiser* denoiser,
                               const PathTracerSettings& settings, const DenoiserSettings& denoise,
                               uint32_t spp, uint32_t sppPerFrame,
                               const std::function<void(uint32_t)>& progress) {
  if (spp == 0) throw Error("render: 0 samples per pixel");
  const bool denoising = denoiser && denoise.mode != DenoiseMode::Off;
  if (denoising && !settings.writeGuides)
    throw Error("render: the denoiser needs the guide buffers (PathTracerSettings::writeGuides)");
  const scene::Camera camera = tracer.camera();
  tracer.resetAccumulation();
  if (denoising) denoiser->resetHistory();
  RenderLoopResult result;
  uint32_t done = 0;
  while (done < spp) {
    const uint32_t n = std::min(std::max(sppPerFrame, 1u), spp - done);
    // The temporal denoiser integrates frames itself: each frame holds only
    // its own samples (the same samples as without it).
    if (denoising && denoise.mode == DenoiseMode::Svgf)
      tracer.startNewMean(tracer.nextSampleIndex());
    const FrameStats stats = tracer.renderFrame(settings, n);
    result.gpuSeconds += stats.gpuSeconds;
    result.rays += stats.rays;
    done += n;
    if (denoising && denoise.mode == DenoiseMode::Svgf)
      result.denoiseSeconds += denoiser->run(tracer, camera, n, denoise);
    if (progress) progress(done);
  }
  if (denoising && denoise.mode == DenoiseMode::Atrous)
    result.denoiseSeconds += denoiser->run(tracer, camera, tracer.accumulatedSamples(), denoise);
  return result;
}

}  // namespace penumbra::render
