#pragma once
// Renders a study's points on one device and measures each against the
// reference: GPU time (timestamps), rays, and the error metrics.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "penumbra/image/image.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"
#include "penumbra/study/study_plan.h"

namespace penumbra::study {

// The error of an image against a reference, over all pixels and RGB
// channels (image_compare.h's conventions: the 1e-2 keeps dark pixels from
// dominating the relative measures).
struct ErrorMetrics {
  double relMse = 0;  // mean (a - r)^2 / (r^2 + 1e-2)
  double mape = 0;    // mean |a - r| / (|r| + 1e-2)
  double ssim = 1;    // image::ssim, of display luminance
  double bias = 0;    // (mean luminance of a - of r) / mean luminance of r
};
ErrorMetrics measureError(const image::Image& image, const image::Image& reference);

struct Reference {
  image::Image image;
  std::string source;  // the file it came from, or "rendered"
  uint32_t spp = 0;    // 0 for a user's file
  uint32_t seed = 0;   // of its first half, when rendered
  // The reference's own relMSE against the converged image, estimated from
  // its two independent halves; negative when unknown (a user's file). An
  // error no larger than about this is not distinguishable from it.
  double noiseRelMse = -1.0;
};

struct StudyRow {
  StudyPoint point;
  double gpuMs = 0;      // path tracing plus denoising, GPU timestamps
  double denoiseMs = 0;  // of which the denoiser's passes
  uint64_t rays = 0;
  ErrorMetrics error;
  // relMSE no more than twice the reference's own: the error may be the
  // reference's rather than the point's.
  bool belowReferenceNoise = false;
};

// Holds a path tracer per pipeline kind (specialized, full) and a denoiser,
// so that the sweep compiles each pipeline once.
class StudyRunner {
 public:
  StudyRunner(rhi::IDevice& device, const scene::Scene& scene, uint32_t width, uint32_t height);
  ~StudyRunner();
  // The reference: `spp` samples of `technique` in two independent halves
  // (seeds `seed` and seed + 1; spp rounded up to even), averaged; their
  // difference estimates its noise.
  Reference renderReference(const Technique& technique, uint32_t spp, uint32_t seed,
                            const std::function<void(uint32_t)>& progress = {});
  // One point, measured against `reference` (same size as the study). Its
  // timed frames follow untimed ones of the same settings (at least 100 ms
  // of GPU time), so the GPU runs at its working clocks when they start,
  // and its time is the median of setTimingRepeats renders.
  StudyRow run(const StudyPoint& point, const Reference& reference,
               const std::function<void(uint32_t)>& progress = {});
  // How many times each point's timed render runs (its median time counts);
  // 3 unless set. At least 1.
  void setTimingRepeats(uint32_t repeats) { timingRepeats_ = std::max(repeats, 1u); }
  // The image of the last run (its denoised image where it had a denoiser).
  const image::Image& lastImage() const { return lastImage_; }

 private:
  image::Image render(const Technique& technique, uint32_t spp, uint32_t seed, double* gpuMs,
                      double* denoiseMs, uint64_t* rays,
                      const std::function<void(uint32_t)>& progress);
  rhi::IDevice& device_;
  const scene::Scene& scene_;
  uint32_t width_, height_;
  std::map<bool, std::unique_ptr<render::PathTracer>> tracers_;  // by allEffects
  std::unique_ptr<render::Denoiser> denoiser_;
  image::Image lastImage_;
  uint32_t timingRepeats_ = 3;
};

// The seeds a study's points use must differ from a rendered reference's
// (its two halves'), or the errors would be measured against the same
// random numbers. Throws penumbra::Error naming the clash.
void checkReferenceIndependence(const StudySpec& spec, uint32_t referenceSeed);

}  // namespace penumbra::study
