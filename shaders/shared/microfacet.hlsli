// Anisotropic GGX (Trowbridge-Reitz) microfacet distribution in the local
// shading frame (normal = +z): distribution, Smith masking (height-correlated
// form, Heitz 2014), and sampling of the visible normals (Heitz 2018, "Sampling
// the GGX Distribution of Visible Normals").
#ifndef PENUMBRA_MICROFACET_HLSLI
#define PENUMBRA_MICROFACET_HLSLI
#include "math.hlsli"

struct Ggx {
  float alphaX;
  float alphaY;
};

float ggxD(Ggx g, float3 wm) {
  float x = wm.x / g.alphaX;
  float y = wm.y / g.alphaY;
  float d = x * x + y * y + wm.z * wm.z;
  return 1.0 / (kPi * g.alphaX * g.alphaY * d * d);
}

// Smith's Lambda for direction w.
float ggxLambda(Ggx g, float3 w) {
  float z2 = w.z * w.z;
  if (z2 <= 0.0) return 1e30;
  float a2tan2 = (w.x * w.x * g.alphaX * g.alphaX + w.y * w.y * g.alphaY * g.alphaY) / z2;
  return 0.5 * (-1.0 + sqrt(1.0 + a2tan2));
}

float ggxG1(Ggx g, float3 w) { return 1.0 / (1.0 + ggxLambda(g, w)); }

// Height-correlated masking-shadowing G2(wo, wi).
float ggxG2(Ggx g, float3 wo, float3 wi) {
  return 1.0 / (1.0 + ggxLambda(g, wo) + ggxLambda(g, wi));
}

// Density of visible normals seen from wo (wo.z > 0): G1(wo) max(0, wo.wm) D(wm) / wo.z.
float ggxVisibleNormalPdf(Ggx g, float3 wo, float3 wm) {
  float cosO = dot(wo, wm);
  if (cosO <= 0.0 || wo.z <= 0.0) return 0.0;
  return ggxG1(g, wo) * cosO * ggxD(g, wm) / wo.z;
}

// A visible normal for wo (wo.z > 0).
float3 ggxSampleVisibleNormal(Ggx g, float3 wo, float u0, float u1) {
  float3 vh = normalize(float3(g.alphaX * wo.x, g.alphaY * wo.y, wo.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  float3 t1 = lensq > 1e-12 ? float3(-vh.y, vh.x, 0.0) * rsqrt(lensq) : float3(1.0, 0.0, 0.0);
  float3 t2 = cross(vh, t1);
  float r = sqrt(u0);
  float phi = 2.0 * kPi * u1;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
  float3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(float3(g.alphaX * nh.x, g.alphaY * nh.y, max(1e-6, nh.z)));
}

// GTR1 (Berry) distribution of the clearcoat lobe, isotropic, alpha in (0, 1).
float gtr1D(float alpha, float cosThetaM) {
  float a2 = alpha * alpha;
  float t = 1.0 + (a2 - 1.0) * cosThetaM * cosThetaM;
  return (a2 - 1.0) / (kPi * log(a2) * t);
}

// Samples cos(theta_m) of GTR1 (pdf over the half vector: D(wm) cos(theta_m)).
float gtr1SampleCosTheta(float alpha, float u) {
  float a2 = alpha * alpha;
  return sqrt(max(0.0, (1.0 - pow(a2, 1.0 - u)) / (1.0 - a2)));
}

#endif
