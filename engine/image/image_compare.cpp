#include "image/image_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.h"

namespace penumbra::image {

ComparisonStats compareImages(const Image& a, const Image& b, double relativeTolerance) {
  if (a.width != b.width || a.height != b.height)
    throw Error(fmt::format("compare: image sizes differ ({}x{} vs {}x{})", a.width, a.height,
                            b.width, b.height));
  ComparisonStats s;
  s.nonFiniteA = countNonFinite(a);
  s.nonFiniteB = countNonFinite(b);
  double sumAbs = 0, sumSq = 0, peak = 0, sumRel = 0;
  const size_t pixels = size_t(a.width) * a.height;
  for (size_t i = 0; i < pixels; ++i) {
    bool beyond = false;
    for (int c = 0; c < 3; ++c) {
      const double va = a.rgba[i * 4 + c], vb = b.rgba[i * 4 + c];
      const double d = std::abs(va - vb);
      sumAbs += d;
      sumSq += d * d;
      sumRel += d * d / (vb * vb + 1e-2);
      s.maxAbsoluteDifference = std::max(s.maxAbsoluteDifference, d);
      peak = std::max(peak, std::abs(va));
      if (d > relativeTolerance * std::max({std::abs(va), std::abs(vb), 1e-3})) beyond = true;
    }
    if (beyond) ++s.pixelsBeyondTolerance;
  }
  const double n = double(pixels) * 3.0;
  s.meanAbsoluteDifference = pixels ? sumAbs / n : 0;
  s.fractionBeyondTolerance = pixels ? double(s.pixelsBeyondTolerance) / double(pixels) : 0;
  const double mse = pixels ? sumSq / n : 0;
  s.relativeMse = pixels ? sumRel / n : 0;
  s.psnr = mse > 0 ? 10.0 * std::log10(peak * peak / mse) : std::numeric_limits<double>::infinity();
  return s;
}

}  // namespace penumbra::image
