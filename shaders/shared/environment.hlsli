// The environment: radiance arriving from infinitely far away, an
// equirectangular map (EnvironmentData), looked up for rays that leave the
// scene and sampled by next-event estimation in proportion to each texel's
// luminance times sin(theta), its share of the sphere.
//
// The map is piecewise constant (nearest texel): the density the sampler
// draws with is then exactly proportional to what it looks up, wherever the
// map is not black, so the estimator stays unbiased with NEE alone and the
// density can be evaluated in O(1) for MIS.
//
// Directions: the map's top row looks up (+y), its centre column along -z
// (where a default camera looks), u grows towards +x; `rotation` turns the
// map about +y (counter-clockwise seen from above).
//
// The entry point defines, before including this file:
//   EnvironmentData loadEnvironment();
//   float4 loadEnvironmentTexel(uint index);  // rgb radiance, w probability of the texel
//   float loadEnvironmentCdf(uint index);     // rows' CDF, then each row's own
#ifndef PENUMBRA_ENVIRONMENT_HLSLI
#define PENUMBRA_ENVIRONMENT_HLSLI
#include "effects.h"
#include "math.hlsli"

// False at compile time in a variant without PT_EFFECT_ENVIRONMENT, so
// none of the environment's code is in a scene's pipeline that has none.
bool environmentPresent(FrameConstants c) {
#if PT_HAS_EFFECT(PT_EFFECT_ENVIRONMENT)
  return (c.sceneFlags & PT_SCENE_ENVIRONMENT) != 0u;
#else
  return false;
#endif
}

// The map's direction for a world direction: the rotation undone.
float3 environmentToMap(EnvironmentData e, float3 d) {
  float c = e.cosRotation;
  float s = e.sinRotation;
  return float3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

float3 environmentToWorld(EnvironmentData e, float3 m) {
  float c = e.cosRotation;
  float s = e.sinRotation;
  return float3(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
}

// (u, v) in [0, 1)^2 of a unit map direction: u the azimuth from -z towards
// +x, v the polar angle from +y over pi.
float2 environmentUv(float3 m) {
  float u = 0.5 + atan2(m.x, -m.z) * (0.5 * kInvPi);
  float v = acos(clamp(m.y, -1.0, 1.0)) * kInvPi;
  return float2(u - floor(u), v);
}

uint environmentTexelIndex(EnvironmentData e, float2 uv) {
  uint x = min(uint(uv.x * float(e.width)), e.width - 1u);
  uint y = min(uint(uv.y * float(e.height)), e.height - 1u);
  return y * e.width + x;
}

// dw = 2 pi^2 sin(theta) du dv.
float environmentSolidAnglePdf(EnvironmentData e, float texelProbability, float sinTheta) {
  return sinTheta > 0.0 ? texelProbability * float(e.width * e.height) / (2.0 * kPi * kPi * sinTheta) : 0.0;
}

// Radiance arriving along -direction, i.e. seen looking along `direction`.
float3 environmentRadiance(float3 direction) {
  EnvironmentData e = loadEnvironment();
  float2 uv = environmentUv(environmentToMap(e, direction));
  return loadEnvironmentTexel(environmentTexelIndex(e, uv)).xyz * e.intensity;
}

// The solid-angle density with which sampleEnvironment draws `direction`.
float environmentPdf(float3 direction) {
  EnvironmentData e = loadEnvironment();
  float3 m = environmentToMap(e, direction);
  float2 uv = environmentUv(m);
  float sinTheta = sqrt(max(0.0, 1.0 - m.y * m.y));
  return environmentSolidAnglePdf(e, loadEnvironmentTexel(environmentTexelIndex(e, uv)).w, sinTheta);
}

// The first of the `count` cumulative probabilities from `first` that
// exceeds u (the last one is exactly 1, and u < 1).
uint environmentSearch(uint first, uint count, float u) {
  uint lo = 0u;
  uint hi = count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (loadEnvironmentCdf(first + mid) > u)
      hi = mid;
    else
      lo = mid + 1u;
  }
  return lo;
}

struct EnvironmentSample {
  float3 direction;  // world, unit
  float3 radiance;   // arriving along -direction
  float pdf;         // per solid angle; 0: no sample
};

// A row by the rows' CDF, a texel by that row's, a uniform point in the
// texel (the remainders of u0 and u1), and its direction.
EnvironmentSample sampleEnvironment(float u0, float u1) {
  EnvironmentData e = loadEnvironment();
  EnvironmentSample s;
  uint width = e.width;
  uint height = e.height;
  uint row = environmentSearch(0u, height, u0);
  float rowLow = row > 0u ? loadEnvironmentCdf(row - 1u) : 0.0;
  float rowHigh = loadEnvironmentCdf(row);
  uint rowStart = height + row * width;
  uint column = environmentSearch(rowStart, width, u1);
  float columnLow = column > 0u ? loadEnvironmentCdf(rowStart + column - 1u) : 0.0;
  float columnHigh = loadEnvironmentCdf(rowStart + column);
  float fv = rowHigh > rowLow ? saturate((u0 - rowLow) / (rowHigh - rowLow)) : 0.5;
  float fu = columnHigh > columnLow ? saturate((u1 - columnLow) / (columnHigh - columnLow)) : 0.5;
  float u = (float(column) + fu) / float(width);
  float v = (float(row) + fv) / float(height);
  float theta = v * kPi;
  float phi = (u - 0.5) * (2.0 * kPi);
  float sinTheta = sin(theta);
  if (!(sinTheta > 0.0)) {  // u0 so close to 0 or 1 that v is a pole: no direction
    s.direction = float3(0.0, 1.0, 0.0);
    s.radiance = zero3();
    s.pdf = 0.0;
    return s;
  }
  float3 m = float3(sinTheta * sin(phi), cos(theta), -sinTheta * cos(phi));
  s.direction = normalize(environmentToWorld(e, m));
  // Radiance and density of the texel the direction looks up, which is
  // (row, column) but within rounding of its edges, where the division
  // above can land on the neighbour's: so the density is always the one
  // environmentPdf gives MIS for the same direction.
  float3 back = environmentToMap(e, s.direction);
  float4 texel = loadEnvironmentTexel(environmentTexelIndex(e, environmentUv(back)));
  s.radiance = texel.xyz * e.intensity;
  s.pdf = environmentSolidAnglePdf(e, texel.w, sqrt(max(0.0, 1.0 - back.y * back.y)));
  return s;
}

#endif
