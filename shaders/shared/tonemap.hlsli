// Display transform for 8-bit outputs: exposure, a tone curve, sRGB encoding
// (IEC 61966-2-1 piecewise curve).
#ifndef PENUMBRA_TONEMAP_HLSLI
#define PENUMBRA_TONEMAP_HLSLI

// Tone curves (render::ToneMapOperator, same values).
#define TONEMAP_CLAMP 0     // none: values above 1 clip
#define TONEMAP_REINHARD 1  // x / (1 + x) per channel (Reinhard et al. 2002, simple operator)
#define TONEMAP_ACES 2      // Hill's fit of the ACES RRT + sRGB ODT (BakingLab, 2016)
#define TONEMAP_PBR_NEUTRAL 3  // Khronos PBR Neutral (2024): base colours shown as authored
#define TONEMAP_AGX 4          // AgX (Sobotka), as glTF viewers use it (Filament, three.js)

float linearToSrgb(float x) {
  x = saturate(x);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

float3 rrtAndOdtFit(float3 v) {
  float3 a = v * (v + 0.0245786) - 0.000090537;
  float3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return a / b;
}

// Hill's sRGB -> ACES AP1 (with the RRT's saturation) and back, written as
// rows because the shading core keeps no matrices.
float3 acesFitted(float3 c) {
  float3 v = float3(dot(float3(0.59719, 0.35458, 0.04823), c),
                    dot(float3(0.07600, 0.90834, 0.01566), c),
                    dot(float3(0.02840, 0.13383, 0.83777), c));
  v = rrtAndOdtFit(v);
  return float3(dot(float3(1.60475, -0.53108, -0.07367), v),
                dot(float3(-0.10208, 1.10813, -0.00605), v),
                dot(float3(-0.00327, -0.07276, 1.07602), v));
}

// Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md):
// colours up to Ks = 0.76 pass unchanged but for a small offset that takes
// back the 4 % specular floor of dielectrics; brighter ones are compressed
// towards 1 and desaturated, so a lit albedo reads as its base colour.
float3 pbrNeutral(float3 c) {
  const float f90 = 0.04;
  const float ks = 0.8 - f90;
  const float kd = 0.15;
  float x = min(c.x, min(c.y, c.z));
  float f = x <= 2.0 * f90 ? x - x * x / (4.0 * f90) : f90;
  c = c - float3(f, f, f);
  float p = max(c.x, max(c.y, c.z));
  if (p <= ks) return c;
  float pn = 1.0 - (1.0 - ks) * (1.0 - ks) / (p + 1.0 - 2.0 * ks);
  float g = 1.0 / (kd * (p - pn) + 1.0);
  return c * (pn / p * g) + float3(pn, pn, pn) * (1.0 - g);
}

// AgX as Filament and three.js ship it (Blender's AgX base, Rec. 2020 working
// space): into Rec. 2020, the AgX inset, log2 encoding between -12.47 and
// +4.03 (-10 to +6.5 EV about middle grey 0.18), Wrensch's polynomial fit of
// the sigmoid, the
// outset, a 2.2 power back to linear, back to Rec. 709, clipped. Matrices
// as rows (the shading core keeps no matrices).
float3 agxContrast(float3 x) {
  float3 x2 = x * x;
  float3 x4 = x2 * x2;
  return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x -
         0.00232;
}

float3 agx(float3 c) {
  const float minEv = -12.47393;
  const float maxEv = 4.026069;
  // Rec. 709 -> Rec. 2020 (ITU-R BT.2087).
  c = float3(dot(float3(0.6274, 0.3293, 0.0433), c), dot(float3(0.0691, 0.9195, 0.0113), c),
             dot(float3(0.0164, 0.0880, 0.8956), c));
  c = float3(dot(float3(0.856627153315983, 0.0951212405381588, 0.0482516061458583), c),
             dot(float3(0.137318972929847, 0.761241990602591, 0.101439036467562), c),
             dot(float3(0.11189821299995, 0.0767994186031903, 0.811302368396859), c));
  c = max(c, float3(1e-10, 1e-10, 1e-10));
  c = saturate((log2(c) - float3(minEv, minEv, minEv)) / (maxEv - minEv));
  c = agxContrast(c);
  c = float3(dot(float3(1.1271005818144368, -0.11060664309660323, -0.016493938717834573), c),
             dot(float3(-0.1413297634984383, 1.157823702216272, -0.016493938717834257), c),
             dot(float3(-0.14132976349843826, -0.11060664309660294, 1.2519364065950405), c));
  c = pow(max(c, float3(0.0, 0.0, 0.0)), float3(2.2, 2.2, 2.2));
  // Rec. 2020 -> Rec. 709.
  c = float3(dot(float3(1.6605, -0.5876, -0.0728), c), dot(float3(-0.1246, 1.1329, -0.0083), c),
             dot(float3(-0.0182, -0.1006, 1.1187), c));
  return saturate(c);
}

float3 applyToneCurve(float3 c, uint toneOperator) {
  if (toneOperator == TONEMAP_REINHARD) return c / (c + float3(1.0, 1.0, 1.0));
  if (toneOperator == TONEMAP_ACES) return acesFitted(c);
  if (toneOperator == TONEMAP_PBR_NEUTRAL) return pbrNeutral(c);
  if (toneOperator == TONEMAP_AGX) return agx(c);
  return c;
}

// sRGB-encoded display values in [0, 1]; NaN maps to 0.
float3 tonemapToDisplay(float3 linearRgb, float exposure, uint toneOperator) {
  float3 c = applyToneCurve(max(linearRgb * exposure, float3(0.0, 0.0, 0.0)), toneOperator);
  return float3(linearToSrgb(c.x), linearToSrgb(c.y), linearToSrgb(c.z));
}

// Packs to R8G8B8A8 (R in the low byte), alpha 1.
uint tonemapToRgba8(float3 linearRgb, float exposure, uint toneOperator) {
  float3 d = tonemapToDisplay(linearRgb, exposure, toneOperator);
  uint r = uint(d.x * 255.0 + 0.5);
  uint g = uint(d.y * 255.0 + 0.5);
  uint b = uint(d.z * 255.0 + 0.5);
  return r | (g << 8u) | (b << 16u) | (255u << 24u);
}

// What the display pass shows of a texel (DisplayChannels in
// engine/penumbra/render/display_pass.h): 0 its colour, 1 signed xyz as 0.5 + 0.5 v
// (normals, motion), 2 its alpha channel as grey (depth).
float3 displayChannels(float4 texel, uint channels) {
  if (channels == 1u) return float3(0.5, 0.5, 0.5) + 0.5 * texel.xyz;
  if (channels == 2u) return float3(texel.w, texel.w, texel.w);
  return texel.xyz;
}

#endif
