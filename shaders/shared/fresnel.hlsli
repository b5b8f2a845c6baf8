// Fresnel reflectance.
#ifndef PENUMBRA_FRESNEL_HLSLI
#define PENUMBRA_FRESNEL_HLSLI
#include "math.hlsli"

float schlickWeight(float cosTheta) {
  float m = saturate(1.0 - cosTheta);
  float m2 = m * m;
  return m2 * m2 * m;
}

float3 fresnelSchlick(float3 f0, float cosTheta) {
  return f0 + (splat3(1.0) - f0) * schlickWeight(cosTheta);
}

// Unpolarised reflectance of a smooth dielectric boundary. `cosThetaI` is the
// cosine on the incident side (sign ignored), `eta` the relative index of
// refraction (transmitted side over incident side). Total internal reflection
// returns 1; eta = 1 returns 0.
float fresnelDielectric(float cosThetaI, float eta) {
  cosThetaI = saturate(abs(cosThetaI));
  float sin2ThetaT = (1.0 - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0) return 1.0;
  float cosThetaT = sqrt(max(0.0, 1.0 - sin2ThetaT));
  float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
  float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
  return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

#endif
