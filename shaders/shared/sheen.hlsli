// KHR_materials_sheen's sheen layer (the glTF model's; Disney materials keep
// Burley's sheen, disney_bsdf.hlsli): the "Charlie" fibre distribution of
// Estevez and Kulla 2017 with the extension's shadowing fit, laid over the
// base by albedo scaling, f = sheen + base * (1 - max(colour) E), where E is
// the sheen's directional albedo (sheen_albedo_table.hlsli, integrated by
// tools/sheen_albedo).
//
// The extension's shadowing fit is not exact: below a sheen roughness of
// 0.25 the lobe reflects more than it receives at grazing angles (E up to 18
// at r = 0.01). Dividing the lobe by max(1, E(cos_o), E(cos_i)) keeps it
// reciprocal and its albedo <= 1, and leaves it as the extension defines it
// wherever E <= 1 (every roughness from 0.25 up, every angle).
#ifndef PENUMBRA_SHEEN_HLSLI
#define PENUMBRA_SHEEN_HLSLI
#include "effects.h"
#include "math.hlsli"

// Below it the fibres' distribution is too narrow for float (1 / alpha in pow).
static const float kMinSheenRoughness = 0.01;

float charlieAlpha(float sheenRoughness) {
  float r = max(sheenRoughness, kMinSheenRoughness);
  return r * r;
}

float charlieD(float alpha, float cosThetaH) {
  float sin2h = max(0.0, 1.0 - cosThetaH * cosThetaH);
  return (2.0 + 1.0 / alpha) * pow(sin2h, 0.5 / alpha) / (2.0 * kPi);
}

float charlieFit(float x, float alpha) {
  float t = (1.0 - alpha) * (1.0 - alpha);
  float a = lerp(21.5473, 25.3245, t);
  float b = lerp(3.82987, 3.32435, t);
  float c = lerp(0.19823, 0.16801, t);
  float d = lerp(-1.97760, -1.27393, t);
  float e = lerp(-4.32054, -4.85967, t);
  return a / (1.0 + b * pow(x, c)) + d * x + e;
}

float charlieLambda(float cosTheta, float alpha) {
  float c =
      saturate(cosTheta);  // a unit vector's z can round past 1: pow(1 - c, ...) must not see < 0
  return c < 0.5 ? exp(charlieFit(c, alpha))
                 : exp(2.0 * charlieFit(0.5, alpha) - charlieFit(1.0 - c, alpha));
}

// Only variants with the sheen effect hold the table (DXC keeps an unused
// constant array in the module).
#if PT_HAS_EFFECT(PT_EFFECT_SHEEN)
#include "sheen_albedo_table.hlsli"

// Node (column j, row i) of the table (four columns to a float4).
float sheenAlbedoNode(uint j, uint i) {
  float4 v = kSheenAlbedo[(i * PT_SHEEN_ALBEDO_SIZE + j) / 4u];
  uint k = j % 4u;
  return k == 0u ? v.x : (k == 1u ? v.y : (k == 2u ? v.z : v.w));
}

// E(cos_o, r), bilinear in (sqrt(cos_o), r) between the table's nodes.
float sheenAlbedo(float cosTheta, float sheenRoughness) {
  const float last = float(PT_SHEEN_ALBEDO_SIZE - 1);
  float x = sqrt(saturate(cosTheta)) * last;
  float y = saturate(sheenRoughness) * last;
  uint x0 = min(uint(x), PT_SHEEN_ALBEDO_SIZE - 2u);
  uint y0 = min(uint(y), PT_SHEEN_ALBEDO_SIZE - 2u);
  float fx = x - float(x0);
  float fy = y - float(y0);
  float lower = lerp(sheenAlbedoNode(x0, y0), sheenAlbedoNode(x0 + 1u, y0), fx);
  float upper = lerp(sheenAlbedoNode(x0, y0 + 1u), sheenAlbedoNode(x0 + 1u, y0 + 1u), fx);
  return lerp(lower, upper, fy);
}
#endif

// The sheen BRDF for colour 1 (no cosine), wo and wi above the surface;
// albedoO and albedoI are sheenAlbedo at wo and wi. (Callers look each
// albedo up once: every lookup is compiled into its own copy of the table
// search, which lavapipe takes long to compile.)
float charlieSheen(float sheenRoughness, float3 wo, float3 wi, float albedoO, float albedoI) {
  float alpha = charlieAlpha(sheenRoughness);
  float3 wh = normalize(wo + wi);
  float visibility =
      1.0 / ((1.0 + charlieLambda(wo.z, alpha) + charlieLambda(wi.z, alpha)) * (4.0 * wo.z * wi.z));
  return charlieD(alpha, wh.z) * visibility / max(1.0, max(albedoO, albedoI));
}

// What of the light reaches the base below a sheen of largest channel
// `strength`, on the way in and out (the extension's min form: symmetric).
float sheenAlbedoScaling(float strength, float albedoO, float albedoI) {
  return 1.0 - strength * min(1.0, max(albedoO, albedoI));
}

#endif
