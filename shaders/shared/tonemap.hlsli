// Display transform for 8-bit outputs: exposure, a tone curve, sRGB encoding
// (IEC 61966-2-1 piecewise curve).
#ifndef PENUMBRA_TONEMAP_HLSLI
#define PENUMBRA_TONEMAP_HLSLI

// Tone curves (render::ToneMapOperator, same values).
#define TONEMAP_CLAMP 0     // none: values above 1 clip
#define TONEMAP_REINHARD 1  // x / (1 + x) per channel (Reinhard et al. 2002, simple operator)
#define TONEMAP_ACES 2      // Hill's fit of the ACES RRT + sRGB ODT (BakingLab, 2016)

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

float3 applyToneCurve(float3 c, uint toneOperator) {
  if (toneOperator == TONEMAP_REINHARD) return c / (c + float3(1.0, 1.0, 1.0));
  if (toneOperator == TONEMAP_ACES) return acesFitted(c);
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
