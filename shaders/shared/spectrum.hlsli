// Light of one wavelength in an RGB renderer, for dispersion
// (KHR_materials_dispersion): a path that meets a dispersive volume picks a
// wavelength and carries it from then on; its throughput is multiplied by
// the wavelength's colour weight, whose expectation is 1 in every channel,
// so white light stays white on average and a surface that does not depend
// on the wavelength sees the same expected radiance.
#ifndef PENUMBRA_SPECTRUM_HLSLI
#define PENUMBRA_SPECTRUM_HLSLI
#include "math.hlsli"

// CIE 1931 XYZ to linear Rec. 709 (sRGB primaries, D65 white).
float3 xyzToRec709(float3 xyz) {
  return float3(3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
                -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
                0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z);
}

// Wavelengths, nm: the visible range, outside which the colour
// matching functions are below 0.4 % of their peaks.
static const float kWavelengthMin = 380.0;
static const float kWavelengthMax = 780.0;

float cieLobe(float lambda, float mean, float sigmaBelow, float sigmaAbove) {
  float t = (lambda - mean) / (lambda < mean ? sigmaBelow : sigmaAbove);
  return exp(-0.5 * t * t);
}

// The CIE 1931 2-degree colour matching functions, Wyman, Sloan and
// Shirley's multi-lobe fit (JCGT 2013, "Simple Analytic Approximations to
// the CIE XYZ Color Matching Functions"): its y integrates to 106.92 over the
// range, the table's to 106.86.
float3 cieXyz(float lambda) {
  return float3(
      1.056 * cieLobe(lambda, 599.8, 37.9, 31.0) + 0.362 * cieLobe(lambda, 442.0, 16.0, 26.7) -
          0.065 * cieLobe(lambda, 501.1, 20.4, 26.2),
      0.821 * cieLobe(lambda, 568.8, 46.9, 40.5) + 0.286 * cieLobe(lambda, 530.9, 16.3, 31.1),
      1.217 * cieLobe(lambda, 437.0, 11.8, 36.0) + 0.681 * cieLobe(lambda, 459.0, 26.0, 13.8));
}

// The colour a wavelength stands for: its Rec. 709 colour without the
// negative parts (spectral colours lie outside the gamut), divided per
// channel by that colour's mean over the range, so that its mean over the
// range is exactly (1, 1, 1). The means were integrated numerically from
// cieXyz and xyzToRec709; the tests integrate them independently.
float3 wavelengthColor(float lambda) {
  float3 rgb = max(xyzToRec709(cieXyz(lambda)), zero3());
  return rgb / float3(0.440443, 0.288464, 0.273296);
}

// Wavelengths are drawn from a mixture of three logistic distributions,
// truncated to the range, one at each of the red, green and blue colours'
// peaks (fitted to their sum): a sample's weight then has a standard
// deviation of 1.2-1.3 per channel and is at most 3.8, where uniform
// wavelengths give 1.7-2.1 and 7. The logistic's inverse is closed-form.
static const float3 kWavelengthModes = float3(605.0, 535.0, 450.0);
static const float3 kWavelengthScales = float3(17.0, 20.0, 11.0);

float3 logisticCdf(float lambda) {
  return splat3(1.0) / (splat3(1.0) + exp((kWavelengthModes - splat3(lambda)) / kWavelengthScales));
}

float3 logisticDensity(float lambda) {
  float3 e = exp(-abs(splat3(lambda) - kWavelengthModes) / kWavelengthScales);
  return e / (kWavelengthScales * (splat3(1.0) + e) * (splat3(1.0) + e));
}

struct WavelengthSample {
  float lambda;   // nm
  float3 weight;  // wavelengthColor / (pdf x the range's width): expectation (1, 1, 1)
};

// One uniform number picks the mixture's component and, rescaled, the
// wavelength within it by inverting its truncated CDF.
WavelengthSample sampleWavelength(float u) {
  float scaled = min(3.0 * u, 2.9999998);
  float component = floor(scaled);
  float mode = component == 0.0 ? kWavelengthModes.x
                                : (component == 1.0 ? kWavelengthModes.y : kWavelengthModes.z);
  float scale = component == 0.0 ? kWavelengthScales.x
                                 : (component == 1.0 ? kWavelengthScales.y : kWavelengthScales.z);
  float low = 1.0 / (1.0 + exp((mode - kWavelengthMin) / scale));
  float high = 1.0 / (1.0 + exp((mode - kWavelengthMax) / scale));
  float v = lerp(low, high, scaled - component);
  WavelengthSample s;
  s.lambda = clamp(mode + scale * log(v / (1.0 - v)), kWavelengthMin, kWavelengthMax);
  float3 truncated = logisticCdf(kWavelengthMax) - logisticCdf(kWavelengthMin);
  float pdf = dot(logisticDensity(s.lambda) / truncated, splat3(1.0 / 3.0));
  s.weight = wavelengthColor(s.lambda) / (pdf * (kWavelengthMax - kWavelengthMin));
  return s;
}

// KHR_materials_dispersion: the index at `lambda` nm of a material whose
// index is `ior` at 587.6 nm (the d line) and whose dispersion is 20 / Abbe
// number: Cauchy's two terms through n_d, with n_F - n_C = (n_d - 1) / V_d.
float dispersedIor(float ior, float dispersion, float lambda) {
  float abbeInverse = dispersion / 20.0;
  return max(ior + (ior - 1.0) * abbeInverse * (523655.0 / (lambda * lambda) - 1.5168), 1.0);
}

#endif
