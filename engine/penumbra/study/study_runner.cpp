#include "penumbra/study/study_runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "penumbra/batch/render_loop.h"
#include "penumbra/image/image_compare.h"
#include "penumbra/util/error.h"

namespace penumbra::study {
namespace {

double luminance(const float* p) {
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

}  // namespace

ErrorMetrics measureError(const image::Image& image, const image::Image& reference) {
  if (image.width != reference.width || image.height != reference.height)
    throw Error(fmt::format("study: image {}x{} against a reference of {}x{}", image.width,
                            image.height, reference.width, reference.height));
  ErrorMetrics m;
  m.relMse = image::compareImages(image, reference, 0.0).relativeMse;
  double absolute = 0, sumImage = 0, sumReference = 0;
  const size_t pixels = size_t(image.width) * image.height;
  for (size_t i = 0; i < pixels; ++i) {
    const float* a = &image.rgba[4 * i];
    const float* r = &reference.rgba[4 * i];
    for (int c = 0; c < 3; ++c) absolute += std::abs(a[c] - r[c]) / (std::abs(r[c]) + 1e-2);
    sumImage += luminance(a);
    sumReference += luminance(r);
  }
  m.mape = pixels ? absolute / (3.0 * pixels) : 0.0;
  m.ssim = image::ssim(image, reference);
  m.bias = sumReference > 0 ? (sumImage - sumReference) / sumReference : 0.0;
  return m;
}

StudyRunner::StudyRunner(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                         uint32_t height)
    : device_(device), scene_(scene), width_(width), height_(height) {}

StudyRunner::~StudyRunner() = default;

image::Image StudyRunner::render(const Technique& technique, uint32_t spp, uint32_t seed,
                                 double* gpuMs, double* denoiseMs, uint64_t* rays,
                                 const std::function<void(uint32_t)>& progress) {
  auto& tracer = tracers_[technique.settings.allEffects];
  if (!tracer) {
    render::PipelineOptions options;
    options.allEffects = technique.settings.allEffects;
    tracer = std::make_unique<render::PathTracer>(device_, scene_, width_, height_, options);
  }
  const bool denoising = render::denoises(technique.settings);
  if (denoising && !denoiser_)
    denoiser_ = std::make_unique<render::Denoiser>(device_, width_, height_);
  const render::DenoiserSettings& denoise = technique.settings.denoiser;
  // A GPU left idle while the host measured the last point clocks down, and
  // its first frames then run slow (on the H200 a 16-spp Cornell box read
  // 171 ms after a pause against 30 ms in a steady run): frames of this
  // point's settings, untimed, until 100 ms of GPU time have passed.
  if (gpuMs) {
    double warm = 0;
    for (int frame = 0; frame < 64 && warm < 0.1; ++frame)
      warm += tracer->renderFrame(technique.frameSettings(seed), std::min(spp, 16u)).gpuSeconds;
  }
  // Timed renders repeat (the same seed renders the same image) and the
  // median counts: on a shared GPU a single render read up to 1.6x its
  // steady time (the H200, Cornell box, 64 spp: 120 and 197 ms).
  std::vector<render::RenderLoopResult> timings;
  const uint32_t repeats = gpuMs ? timingRepeats_ : 1u;
  for (uint32_t k = 0; k < repeats; ++k)
    timings.push_back(render::renderSamples(
        *tracer, denoising ? denoiser_.get() : nullptr, technique.frameSettings(seed), denoise, spp,
        render::PathTracer::kMaxSamplesPerFrame, k + 1 == repeats ? progress : nullptr));
  std::sort(timings.begin(), timings.end(), [](const auto& a, const auto& b) {
    return a.gpuSeconds + a.denoiseSeconds < b.gpuSeconds + b.denoiseSeconds;
  });
  const render::RenderLoopResult& r = timings[timings.size() / 2];
  if (gpuMs) *gpuMs = (r.gpuSeconds + r.denoiseSeconds) * 1e3;
  if (denoiseMs) *denoiseMs = r.denoiseSeconds * 1e3;
  if (rays) *rays = r.rays;
  return tracer->readback(denoising ? denoiser_->output() : tracer->accumulation());
}

Reference StudyRunner::renderReference(const Technique& technique, uint32_t spp, uint32_t seed,
                                       const std::function<void(uint32_t)>& progress) {
  if (spp < 2) throw Error("study: a rendered reference needs at least 2 spp (two halves)");
  if (technique.settings.denoiser.mode != render::DenoiseMode::Off ||
      technique.settings.tracer.radianceClamp > 0.0f)
    throw Error("study: the reference must be unbiased (no denoiser, no clamp)");
  const uint32_t half = (spp + 1) / 2;
  const image::Image a = render(technique, half, seed, nullptr, nullptr, nullptr, progress);
  const image::Image b =
      render(technique, half, seed + 1, nullptr, nullptr, nullptr, [&](uint32_t done) {
        if (progress) progress(half + done);
      });
  Reference ref;
  ref.image = a;
  for (size_t i = 0; i < a.rgba.size(); ++i) ref.image.rgba[i] = 0.5f * (a.rgba[i] + b.rgba[i]);
  ref.source = "rendered";
  ref.spp = 2 * half;
  ref.seed = seed;
  // Each half's error against the converged image has the variance s^2 /
  // half; their difference twice that, the mean's half of one half's: so
  // the mean's relMSE is a quarter of the halves' (against each other).
  ref.noiseRelMse = image::compareImages(a, b, 0.0).relativeMse / 4.0;
  return ref;
}

StudyRow StudyRunner::run(const StudyPoint& point, const Reference& reference,
                          const std::function<void(uint32_t)>& progress) {
  StudyRow row;
  row.point = point;
  lastImage_ = render(point.technique, point.spp, point.seed, &row.gpuMs, &row.denoiseMs, &row.rays,
                      progress);
  row.error = measureError(lastImage_, reference.image);
  row.belowReferenceNoise =
      reference.noiseRelMse >= 0 && row.error.relMse <= 2.0 * reference.noiseRelMse;
  return row;
}

void checkReferenceIndependence(const StudySpec& spec, uint32_t referenceSeed) {
  for (uint32_t half : {referenceSeed, referenceSeed + 1})
    if (half >= spec.firstSeed && half - spec.firstSeed < spec.seeds)
      throw Error(fmt::format(
          "study: the reference's seeds ({} and {}) overlap the study's seeds {}..{}: errors "
          "would be measured against the same random numbers (choose another --reference-seed)",
          referenceSeed, referenceSeed + 1, spec.firstSeed, spec.firstSeed + spec.seeds - 1));
}

}  // namespace penumbra::study
