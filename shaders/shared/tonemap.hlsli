// Display transform for 8-bit outputs: exposure, clamp, sRGB encoding
// (IEC 61966-2-1 piecewise curve).
#ifndef PENUMBRA_TONEMAP_HLSLI
#define PENUMBRA_TONEMAP_HLSLI

float linearToSrgb(float x) {
  x = saturate(x);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

// Packs to R8G8B8A8 (R in the low byte), alpha 1; NaN maps to 0.
uint tonemapToRgba8(float3 linearRgb, float exposure) {
  float3 c = linearRgb * exposure;
  uint r = uint(linearToSrgb(c.x) * 255.0 + 0.5);
  uint g = uint(linearToSrgb(c.y) * 255.0 + 0.5);
  uint b = uint(linearToSrgb(c.z) * 255.0 + 0.5);
  return r | (g << 8u) | (b << 16u) | (255u << 24u);
}

#endif
