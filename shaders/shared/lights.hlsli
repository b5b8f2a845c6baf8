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
    if (loadEmissiveTriangle(mid).cumulativeProbability > u0)
      hi = mid;
    else
      lo = mid + 1u;
  }
  EmissiveTriangle tri = loadEmissiveTriangle(lo);
  float2 b = sampleUniformTriangle(u1, u2);
  LightSample s;
  s.position = barycentricInterpolate(tri.p0, tri.p1, tri.p2, b);
  s.normal = normalize(cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
  s.radiance = tri.radiance;
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  uint emissionTexture = tri.emissionTexture;
  if (emissionTexture != PT_NO_TEXTURE) {
    float2 uv = barycentricInterpolate2(tri.uv0, tri.uv1, tri.uv2, b);
    s.radiance *= sampleTextureRef(emissionTexture, float4(uv, uv), PT_FINEST_FOOTPRINT).xyz;
  }
#endif
  s.pdfArea = tri.probability / tri.area;
  return s;
}

// Area density with which sampleEmissiveTriangles picks a point on triangle `index`.
float emissiveTrianglePdfArea(uint index) {
  EmissiveTriangle tri = loadEmissiveTriangle(index);
  return tri.probability / tri.area;
}

bool isDirectionalLight(PointLight light) { return light.type == PT_LIGHT_DIRECTIONAL; }
bool isSpotLight(PointLight light) { return light.type == PT_LIGHT_SPOT; }

// A soft sun: a directional light whose disk subtends an angular radius
// (cosInner = its cosine, below 1).
bool isSoftSun(PointLight light) { return isDirectionalLight(light) && light.cosInner < 1.0; }

// Irradiance a delta light gives at `position` on a surface facing it: a
// directional light's own, else intensity / distance^2 times the spot's
// falloff and the range's window (both as KHR_lights_punctual recommends).
// `toLight` returns the unit direction, `distance` the distance to the light.
//
// A soft sun's direction is drawn uniformly from its cone by `u` (solid
// angle 2 pi (1 - cos a)); the sun's disk of irradiance E has radiance
// E / (pi sin^2 a), so one direction carries E 2 / (1 + cos a), and over a
// surface the disk lies wholly above, the mean is E cos(theta) as for a
// delta light. u.x < 0 takes the disk's centre with E (Whitted: hard shadows).
float3 pointLightIncident(PointLight light, float3 position, float2 u, out float3 toLight, out float distance) {
  if (isDirectionalLight(light)) {
    toLight = -light.direction;
    distance = PT_DIRECTIONAL_SHADOW_LENGTH;
    float cosRadius = light.cosInner;
    if (cosRadius >= 1.0 || u.x < 0.0) return light.intensity;
    float cosTheta = 1.0 - u.x * (1.0 - cosRadius);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * kPi * u.y;
    Frame f = frameFromNormal(toLight);
    toLight = normalize(f.tangent * (sinTheta * cos(phi)) + f.bitangent * (sinTheta * sin(phi)) + f.normal * cosTheta);
    return light.intensity * (2.0 / (1.0 + cosRadius));
  }
  float3 d = light.position - position;
  distance = length(d);
  toLight = distance > 0.0 ? d / distance : float3(0.0, 0.0, 1.0);
  if (distance <= 0.0) return zero3();
  float falloff = 1.0;
  if (isSpotLight(light)) {
    // (cos - cos outer) / (cos inner - cos outer), squared; a hard edge
    // when the cones are equal.
    float cosOuter = light.cosOuter;
    float cosInner = light.cosInner;
    float cosAngle = dot(-toLight, light.direction);
    float t = cosInner > cosOuter ? saturate((cosAngle - cosOuter) / (cosInner - cosOuter))
                                  : (cosAngle >= cosOuter ? 1.0 : 0.0);
    falloff = t * t;
  }
  float range = light.range;
  if (range > 0.0) {
    float r = distance / range;
    float window = saturate(1.0 - r * r * r * r);
    falloff *= window * window;
  }
  return light.intensity * (falloff / (distance * distance));
}

// The segment a shadow ray from `spawn` to the light must find empty;
// `toLight` is the direction pointLightIncident chose (a soft sun's differs
// from its axis).
float3 pointLightShadowSegment(PointLight light, float3 spawn, float3 toLight, out float segmentLength) {
  if (isDirectionalLight(light)) {
    segmentLength = PT_DIRECTIONAL_SHADOW_LENGTH;
    return toLight;
  }
  float3 d = light.position - spawn;
  segmentLength = length(d);
  return segmentLength > 0.0 ? d / segmentLength : float3(0.0, 0.0, 1.0);
}

// Converts an area density at a point seen at `distance` under `cosLight` to
// a solid-angle density at the receiver.
float areaToSolidAnglePdf(float pdfArea, float distance, float cosLight) {
  return cosLight > 0.0 ? pdfArea * distance * distance / cosLight : 0.0;
}

#endif
