// Warps of uniform numbers to the distributions the integrators sample, with
// their densities.
#ifndef PENUMBRA_SAMPLING_HLSLI
#define PENUMBRA_SAMPLING_HLSLI
#include "math.hlsli"

// Shirley-Chiu concentric map: uniform square -> uniform unit disk.
float2 sampleConcentricDisk(float u0, float u1) {
  float ox = 2.0 * u0 - 1.0;
  float oy = 2.0 * u1 - 1.0;
  if (ox == 0.0 && oy == 0.0) return float2(0.0, 0.0);
  float r;
  float theta;
  if (abs(ox) > abs(oy)) {
    r = ox;
    theta = (kPi / 4.0) * (oy / ox);
  } else {
    r = oy;
    theta = (kPi / 2.0) - (kPi / 4.0) * (ox / oy);
  }
  return float2(r * cos(theta), r * sin(theta));
}

// Cosine-weighted direction about +z (Malley's method); pdf = cos(theta) / pi.
float3 sampleCosineHemisphere(float u0, float u1) {
  float2 d = sampleConcentricDisk(u0, u1);
  float z = sqrt(max(0.0, 1.0 - d.x * d.x - d.y * d.y));
  return float3(d.x, d.y, z);
}

float cosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0) * kInvPi; }

// Uniform point on a triangle as barycentrics (b1, b2) (Heitz 2019 would
// avoid the sqrt; this form is the classic one of pbrt 3rd ed.).
float2 sampleUniformTriangle(float u0, float u1) {
  float su0 = sqrt(u0);
  return float2(1.0 - su0, u1 * su0);
}

// Veach's power heuristic with beta = 2, for one sample from each strategy.
float powerHeuristic(float pdfA, float pdfB) {
  float a = pdfA * pdfA;
  float b = pdfB * pdfB;
  return a + b > 0.0 ? a / (a + b) : 0.0;
}

#endif
