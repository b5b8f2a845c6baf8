#pragma once
// KHR_materials_dispersion's reference for render tests, written from the
// formulas, not from the shading core: the index is the extension's Cauchy
// law, each wavelength's colour the CIE 1931 curves (Wyman, Sloan and
// Shirley's published multi-lobe fit) in linear Rec. 709 without negative
// parts, normalised per channel to mean 1 over 380-780 nm by integrating here.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::test {

// One lobe of the fit: a Gaussian, with its own width on either side of its mean.
inline double cieLobe(double lambda, double mean, double below, double above) {
  const double t = (lambda - mean) / (lambda < mean ? below : above);
  return std::exp(-0.5 * t * t);
}

inline glm::dvec3 spectralRgb(double lambda) {
  const double x = 1.056 * cieLobe(lambda, 599.8, 37.9, 31.0) +
                   0.362 * cieLobe(lambda, 442.0, 16.0, 26.7) -
                   0.065 * cieLobe(lambda, 501.1, 20.4, 26.2);
  const double y =
      0.821 * cieLobe(lambda, 568.8, 46.9, 40.5) + 0.286 * cieLobe(lambda, 530.9, 16.3, 31.1);
  const double z =
      1.217 * cieLobe(lambda, 437.0, 11.8, 36.0) + 0.681 * cieLobe(lambda, 459.0, 26.0, 13.8);
  const glm::dvec3 rgb(3.2404542 * x - 1.5371385 * y - 0.4985314 * z,
                       -0.9692660 * x + 1.8760108 * y + 0.0415560 * z,
                       0.0556434 * x - 0.2040259 * y + 1.0572252 * z);
  return glm::max(rgb, glm::dvec3(0.0));
}

// spectralRgb's mean over 380-780 nm (midpoint rule).
inline glm::dvec3 spectralRgbMean(int steps = 40000) {
  glm::dvec3 mean(0.0);
  for (int i = 0; i < steps; ++i)
    mean += spectralRgb(380.0 + 400.0 * (i + 0.5) / steps) / double(steps);
  return mean;
}

// Wavelength grid (midpoints) and each wavelength's colour weight: its
// colour over the range's mean colour, so the weights' mean is 1.
struct Spectrum {
  std::vector<double> lambda;
  std::vector<glm::dvec3> weight;
};
inline Spectrum spectrum(int steps) {
  Spectrum s;
  const glm::dvec3 mean = spectralRgbMean();
  for (int i = 0; i < steps; ++i) {
    s.lambda.push_back(380.0 + 400.0 * (i + 0.5) / steps);
    s.weight.push_back(spectralRgb(s.lambda.back()) / mean);
  }
  return s;
}

// n(lambda) = max(n_d + (n_d - 1) / V_d (523655 / lambda^2 - 1.5168), 1),
// V_d = 20 / dispersion (the extension's text).
inline double cauchyIor(double nd, double dispersion, double lambda) {
  return std::max(nd + (nd - 1.0) * dispersion / 20.0 * (523655.0 / (lambda * lambda) - 1.5168),
                  1.0);
}

// The density the path tracer draws wavelengths from, as spectrum.hlsli
// states it (a mixture of three logistic distributions, modes 605, 535 and
// 450 nm, scales 17, 20 and 11, truncated to 380-780 nm): not physics, but
// what a sample's weight w(l) / (400 pdf(l)) and so its variance follow from.
inline double wavelengthPdf(double lambda) {
  const double modes[3] = {605.0, 535.0, 450.0}, scales[3] = {17.0, 20.0, 11.0};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    auto cdf = [&](double x) { return 1.0 / (1.0 + std::exp((modes[i] - x) / scales[i])); };
    const double e = std::exp(-std::abs(lambda - modes[i]) / scales[i]);
    sum += e / (scales[i] * (1.0 + e) * (1.0 + e)) / (cdf(780.0) - cdf(380.0));
  }
  return sum / 3.0;
}

}  // namespace penumbra::test
