#include "penumbra/image/image_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "penumbra/util/error.h"

namespace penumbra::image {

ComparisonStats compareImages(const Image& a, const Image& b, double relativeTolerance) {
  if (a.width != b.width || a.height != b.height)
    throw Error(fmt::format("compare: image sizes differ ({}x{} vs {}x{})", a.width, a.height,
                            b.width, b.height));
  ComparisonStats s;
  s.nonFiniteA = countNonFinite(a);
  s.nonFiniteB = countNonFinite(b);
  double sumAbs = 0, sumSq = 0, peak = 0, sumRel = 0;
  double sumDiff[3] = {0, 0, 0}, sumDiffSq[3] = {0, 0, 0}, sumA[3] = {0, 0, 0};
  const size_t pixels = size_t(a.width) * a.height;
  for (size_t i = 0; i < pixels; ++i) {
    bool beyond = false;
    for (int c = 0; c < 3; ++c) {
      const double va = a.rgba[i * 4 + c], vb = b.rgba[i * 4 + c];
      sumDiff[c] += vb - va;
      sumDiffSq[c] += (vb - va) * (vb - va);
      sumA[c] += va;
      const double d = std::abs(va - vb);
      sumAbs += d;
      sumSq += d * d;
      sumRel += d * d / (vb * vb + 1e-2);
      s.maxAbsoluteDifference = std::max(s.maxAbsoluteDifference, d);
      peak = std::max(peak, std::abs(vb));
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
  for (int c = 0; c < 3 && pixels > 1; ++c) {
    const double count = double(pixels);
    const double mean = sumDiff[c] / count;
    const double variance = std::max(0.0, (sumDiffSq[c] - count * mean * mean) / (count - 1.0));
    s.meanDifference[c] = mean;
    s.meanDifferenceStandardError[c] = std::sqrt(variance / count);
    s.meanA[c] = sumA[c] / count;
  }
  return s;
}

bool meanDifferenceIsSystematic(const ComparisonStats& s, double sigmas, double relativeFloor) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(s.meanDifference[c]) >
        sigmas * s.meanDifferenceStandardError[c] + relativeFloor * std::abs(s.meanA[c]))
      return true;
  return false;
}

double maskedRelativeMse(const Image& a, const Image& b, const std::vector<bool>& mask) {
  const size_t pixels = size_t(a.width) * a.height;
  if (a.width != b.width || a.height != b.height || mask.size() != pixels)
    throw Error(fmt::format("maskedRelativeMse: sizes differ ({}x{}, {}x{}, mask of {})", a.width,
                            a.height, b.width, b.height, mask.size()));
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < pixels; ++i) {
    if (!mask[i]) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.rgba[i * 4 + c]) - b.rgba[i * 4 + c];
      sum += d * d / (double(b.rgba[i * 4 + c]) * b.rgba[i * 4 + c] + 1e-2);
    }
    ++count;
  }
  return count ? sum / (3.0 * count) : 0.0;
}

double ssim(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error(fmt::format("ssim: image sizes differ ({}x{} vs {}x{})", a.width, a.height, b.width,
                            b.height));
  const int w = int(a.width), h = int(a.height);
  if (w == 0 || h == 0) return 1.0;
  const auto display = [](const Image& img) {
    std::vector<double> y(img.rgba.size() / 4);
    for (size_t i = 0; i < y.size(); ++i) {
      const double l =
          0.2126 * img.rgba[i * 4] + 0.7152 * img.rgba[i * 4 + 1] + 0.0722 * img.rgba[i * 4 + 2];
      y[i] = std::pow(std::clamp(std::isfinite(l) ? l : 0.0, 0.0, 1.0), 1.0 / 2.2);
    }
    return y;
  };
  const std::vector<double> x = display(a), y = display(b);
  constexpr int kRadius = 5;
  double kernel[2 * kRadius + 1];
  for (int k = -kRadius; k <= kRadius; ++k)
    kernel[k + kRadius] = std::exp(-0.5 * k * k / (1.5 * 1.5));
  constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double sum = 0;
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      double weight = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
      for (int dy = -kRadius; dy <= kRadius; ++dy) {
        const int qy = py + dy;
        if (qy < 0 || qy >= h) continue;
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
          const int qx = px + dx;
          if (qx < 0 || qx >= w) continue;
          const double k = kernel[dx + kRadius] * kernel[dy + kRadius];
          const double vx = x[size_t(qy) * w + qx], vy = y[size_t(qy) * w + qx];
          weight += k;
          mx += k * vx;
          my += k * vy;
          xx += k * vx * vx;
          yy += k * vy * vy;
          xy += k * vx * vy;
        }
      }
      mx /= weight;
      my /= weight;
      const double vx = std::max(0.0, xx / weight - mx * mx),
                   vy = std::max(0.0, yy / weight - my * my);
      const double cov = xy / weight - mx * my;
      sum += (2 * mx * my + c1) * (2 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
    }
  return sum / (double(w) * h);
}

}  // namespace penumbra::image
