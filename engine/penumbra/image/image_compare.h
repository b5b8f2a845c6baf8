#pragma once
// Per-pixel comparison of two linear images (backend vs backend, device vs
// device, render vs reference).
#include <string>
#include <vector>

#include "penumbra/image/image.h"

namespace penumbra::image {

struct ComparisonStats {
  double meanAbsoluteDifference = 0;  // over RGB channels of all pixels
  double maxAbsoluteDifference = 0;
  // Pixels where some RGB channel differs by more than relativeTolerance *
  // max(|a|, |b|, 1e-3): "beyond the tolerance".
  double fractionBeyondTolerance = 0;
  uint64_t pixelsBeyondTolerance = 0;
  // dB, the peak the largest value of b, the reference (as for relativeMse):
  // a firefly in the image tested lowers the score instead of raising its
  // peak. Infinite if identical.
  double psnr = 0;
  // Relative MSE against b as the reference: mean of (a - b)^2 / (b^2 + 1e-2)
  // over RGB channels (the 1e-2 keeps dark pixels from dominating).
  double relativeMse = 0;
  uint64_t nonFiniteA = 0, nonFiniteB = 0;
  // Per RGB channel: the mean of the per-pixel differences b - a, and its
  // standard error (their standard deviation / sqrt(pixels)). Two renders
  // whose paths part by float rounding differ like independent noise, with
  // a mean difference of a few standard errors at most; a systematic
  // difference (light lost, a surface missing) shows as many more.
  double meanDifference[3] = {0, 0, 0};
  double meanDifferenceStandardError[3] = {0, 0, 0};
  double meanA[3] = {0, 0, 0};
};

// Whether some channel's mean difference exceeds `sigmas` standard errors
// plus `relativeFloor` of that channel's mean in a (the floor keeps rounding
// offsets of images that agree to the last bits from counting).
bool meanDifferenceIsSystematic(const ComparisonStats& s, double sigmas, double relativeFloor);

// Throws penumbra::Error if the sizes differ.
ComparisonStats compareImages(const Image& a, const Image& b, double relativeTolerance);

// ComparisonStats::relativeMse of `a` against the reference `b` over the
// pixels whose `mask` entry (row-major, width x height) is true; 0 for none.
// Throws penumbra::Error if the sizes differ.
double maskedRelativeMse(const Image& a, const Image& b, const std::vector<bool>& mask);

// Structural similarity (Wang et al. 2004) of the two images' display
// luminance: Rec. 709 luminance clamped to [0, 1] and encoded with gamma
// 2.2, an 11x11 Gaussian window (sigma 1.5, renormalised at the borders),
// C1 = 0.01^2, C2 = 0.03^2; the mean of the SSIM map. 1 for equal images.
// Throws penumbra::Error if the sizes differ.
double ssim(const Image& a, const Image& b);

}  // namespace penumbra::image
