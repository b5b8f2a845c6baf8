// KHR_materials_sheen's sheen layer (the glTF model's; Disney materials keep
// Burley's sheen, disney_bsdf.hlsli): the "Charlie" fibre distribution of
// Estevez and Kulla 2017 with the extension's shadowing fit, laid over the
// base by albedo scaling, f = sheen + base * (1 - max(colour) E), where E is
// the sheen's directional albedo (a table integrated by tools/sheen_albedo).
//
// The extension's shadowing fit is not exact: below a sheen roughness of
// about 0.26 the lobe reflects more than it receives at grazing angles (E
// up to 2.9 at the clamp, r = 0.07). Dividing the lobe by max(1, E(cos_o),
// E(cos_i)) keeps it reciprocal and its albedo <= 1, and leaves it as the
// extension defines it wherever the table's E <= 1 (from r = 0.32 up).
#ifndef PENUMBRA_SHEEN_HLSLI
#define PENUMBRA_SHEEN_HLSLI
#include "effects.h"
#include "math.hlsli"
#include "path_tracer_shared.h"

// Sheen roughness below this acts as it, as Filament and three.js clamp it:
// below it the extension's lobe gains up to 18x at grazing angles (r =
// 0.01), faster than a 16 x 16 table can follow (tools/sheen_albedo).
static const float kMinSheenRoughness = 0.07;

// The extension's visibility grows as 1 / cos at grazing angles (its
// shadowing term stays finite), and so does E without bound; the table
// stops here (tools/sheen_albedo's kMinCosine), and so does the lobe's
// visibility, so that the normalisation below always sees the lobe's E.
static const float kMinSheenCosine = 1e-4;

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

// Node (column j, row i) of the albedo table: E(mu_j, r_i) with
// mu_j = (j / (PT_SHEEN_ALBEDO_SIZE - 1))^4 (column 0 at kMinSheenCosine) and
// r_i = kMinSheenRoughness + (1 - kMinSheenRoughness) i / (PT_SHEEN_ALBEDO_SIZE - 1),
// row-major, read through the includer's accessor
//   float loadSheenAlbedo(uint index);
// (a buffer, PT_T_SHEEN_ALBEDO; render/sheen_albedo_table.h holds the data).
// Not a constant array in the shader: compilers copy such an array for every
// dynamic index, and lavapipe took minutes per pipeline through DXIL.
float sheenAlbedoNode(uint j, uint i) {
  return loadSheenAlbedo(i * PT_SHEEN_ALBEDO_SIZE + j);
}

// E(cos_o, r), bilinear in (cos_o^(1/4), r) between the table's nodes
// (.x), and the largest of the four nodes (.y): bilinear interpolation
// undershoots E near its grazing peak by up to 6 %, the nodes' largest never
// did on a fine grid of angles and roughnesses (tools/sheen_albedo), so the
// lobe's normalisation uses it.
float2 sheenAlbedo(float cosTheta, float sheenRoughness) {
  const float last = float(PT_SHEEN_ALBEDO_SIZE - 1);
  float x = sqrt(sqrt(saturate(cosTheta))) * last;
  float y = saturate((sheenRoughness - kMinSheenRoughness) / (1.0 - kMinSheenRoughness)) * last;
  uint x0 = min(uint(x), PT_SHEEN_ALBEDO_SIZE - 2u);
  uint y0 = min(uint(y), PT_SHEEN_ALBEDO_SIZE - 2u);
  float fx = x - float(x0);
  float fy = y - float(y0);
  float e00 = sheenAlbedoNode(x0, y0);
  float e10 = sheenAlbedoNode(x0 + 1u, y0);
  float e01 = sheenAlbedoNode(x0, y0 + 1u);
  float e11 = sheenAlbedoNode(x0 + 1u, y0 + 1u);
  float e = lerp(lerp(e00, e10, fx), lerp(e01, e11, fx), fy);
  return float2(e, max(max(e00, e10), max(e01, e11)));
}

// The sheen BRDF for colour 1 (no cosine), wo and wi above the surface;
// albedoO and albedoI are sheenAlbedo at wo and wi (callers look each up
// once: four loads each).
float charlieSheen(float sheenRoughness, float3 wo, float3 wi, float2 albedoO, float2 albedoI) {
  float alpha = charlieAlpha(sheenRoughness);
  float3 wh = normalize(wo + wi);
  float cosO = max(wo.z, kMinSheenCosine);
  float cosI = max(wi.z, kMinSheenCosine);
  float visibility =
      1.0 / ((1.0 + charlieLambda(cosO, alpha) + charlieLambda(cosI, alpha)) * (4.0 * cosO * cosI));
  return charlieD(alpha, wh.z) * visibility / max(1.0, max(albedoO.y, albedoI.y));
}

// What of the light reaches the base below a sheen of largest channel
// `strength`, on the way in and out (the extension's min form: symmetric).
float sheenAlbedoScaling(float strength, float2 albedoO, float2 albedoI) {
  return 1.0 - strength * min(1.0, max(albedoO.x, albedoI.x));
}

#endif
