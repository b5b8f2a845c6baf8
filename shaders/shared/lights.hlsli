// Next-event estimation on emissive triangles. Needs the entry point's
// loadEmissiveTriangle(index) and, with textures, textures.hlsli.
#ifndef PENUMBRA_LIGHTS_HLSLI
#define PENUMBRA_LIGHTS_HLSLI
#include "effects.h"
#include "sampling.hlsli"

struct LightSample {
  float3 position;
  float3 normal;    // front face of the emitter
  float3 radiance;
  float pdfArea;    // per unit area, including the choice of triangle
};

// Chooses a triangle in proportion to its emitted power (binary search of the
// cumulative probabilities), then a uniform point on it.
LightSample sampleEmissiveTriangles(uint count, float u0, float u1, float u2) {
  uint lo = 0u;
  uint hi = count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (loadEmissiveTriangle(mid).radiance.w > u0)
      hi = mid;
    else
      lo = mid + 1u;
  }
  EmissiveTriangle tri = loadEmissiveTriangle(lo);
  float2 b = sampleUniformTriangle(u1, u2);
  LightSample s;
  s.position = barycentricInterpolate(tri.p0.xyz, tri.p1.xyz, tri.p2.xyz, b);
  s.normal = normalize(cross(tri.p1.xyz - tri.p0.xyz, tri.p2.xyz - tri.p0.xyz));
  s.radiance = tri.radiance.xyz;
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  uint emissionTexture = asuint(tri.p2.w);
  if (emissionTexture != PT_NO_TEXTURE) {
    float2 uv = barycentricInterpolate2(tri.uv01.xy, tri.uv01.zw, tri.uv2.xy, b);
    s.radiance *= sampleTextureRef(emissionTexture, float4(uv, uv)).xyz;
  }
#endif
  s.pdfArea = tri.p0.w / tri.p1.w;
  return s;
}

// Area density with which sampleEmissiveTriangles picks a point on triangle `index`.
float emissiveTrianglePdfArea(uint index) {
  EmissiveTriangle tri = loadEmissiveTriangle(index);
  return tri.p0.w / tri.p1.w;
}

// spot.w holds a spot's cos(outer angle) in [-1, 1], or a marker below it.
bool isDirectionalLight(PointLight light) {
  return light.spot.w < 0.5 * (PT_LIGHT_POINT + PT_LIGHT_DIRECTIONAL);
}
bool isSpotLight(PointLight light) { return light.spot.w > 0.5 * (-1.0 + PT_LIGHT_POINT); }

// Irradiance a delta light gives at `position` on a surface facing it: a
// directional light's own, else intensity / distance^2 times the spot's
// falloff and the range's window (both as KHR_lights_punctual recommends).
// `toLight` returns the unit direction, `distance` the distance to the light.
float3 pointLightIncident(PointLight light, float3 position, out float3 toLight, out float distance) {
  if (isDirectionalLight(light)) {
    toLight = -light.spot.xyz;
    distance = PT_DIRECTIONAL_SHADOW_LENGTH;
    return light.intensity.xyz;
  }
  float3 d = light.position.xyz - position;
  distance = length(d);
  toLight = distance > 0.0 ? d / distance : float3(0.0, 0.0, 1.0);
  if (distance <= 0.0) return zero3();
  float falloff = 1.0;
  float cosOuter = light.spot.w;
  if (isSpotLight(light)) {
    // (cos - cos outer) / (cos inner - cos outer), squared; a hard edge
    // when the cones are equal.
    float cosInner = light.position.w;
    float cosAngle = dot(-toLight, light.spot.xyz);
    float t = cosInner > cosOuter ? saturate((cosAngle - cosOuter) / (cosInner - cosOuter))
                                  : (cosAngle >= cosOuter ? 1.0 : 0.0);
    falloff = t * t;
  }
  float range = light.intensity.w;
  if (range > 0.0) {
    float r = distance / range;
    float window = saturate(1.0 - r * r * r * r);
    falloff *= window * window;
  }
  return light.intensity.xyz * (falloff / (distance * distance));
}

// The segment a shadow ray from `spawn` to the light must find empty.
float3 pointLightShadowSegment(PointLight light, float3 spawn, out float segmentLength) {
  if (isDirectionalLight(light)) {
    segmentLength = PT_DIRECTIONAL_SHADOW_LENGTH;
    return -light.spot.xyz;
  }
  float3 toLight = light.position.xyz - spawn;
  segmentLength = length(toLight);
  return segmentLength > 0.0 ? toLight / segmentLength : float3(0.0, 0.0, 1.0);
}

// Converts an area density at a point seen at `distance` under `cosLight` to
// a solid-angle density at the receiver.
float areaToSolidAnglePdf(float pdfArea, float distance, float cosLight) {
  return cosLight > 0.0 ? pdfArea * distance * distance / cosLight : 0.0;
}

#endif
