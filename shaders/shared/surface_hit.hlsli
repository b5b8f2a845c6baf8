// What a closest-hit shader reports back to the integrator (the radiance
// ray's payload). World space throughout.
#ifndef PENUMBRA_SURFACE_HIT_HLSLI
#define PENUMBRA_SURFACE_HIT_HLSLI
#include "effects.h"

// Rebuilt in the ray generation shader from the trace's HitRecord
// (surface_from_record.hlsli); the payload is the HitRecord, not this.
struct SurfaceHit {
  float3 position;
  float hitT;             // < 0: the ray missed everything
  float3 geometricNormal; // unit, front side by counter-clockwise winding
  uint instanceIndex;
  uint primitiveIndex;
  float3 shadingNormal;   // unit, on geometricNormal's side (geometricNormal without vertex normals)
  float3 shadingTangent;  // unit and orthogonal to shadingNormal, or zero without vertex tangents
  float4 uv;              // xy TEXCOORD_0, zw TEXCOORD_1 (zero without)
  float4 color;           // COLOR_0, linear RGBA: multiplies base colour and alpha (1 without)
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  // log2 of the ray cone's footprint on the surface in TEXCOORD_0 and
  // TEXCOORD_1 units (textures.hlsli); PT_FINEST_FOOTPRINT without a cone.
  float2 textureFootprint;
#endif
#if PT_COAT_NORMALS
  float3 coatNormal;  // glTF's coat: unit, on geometricNormal's side (its normal map applied)
#endif
};

SurfaceHit surfaceMiss() {
  SurfaceHit h;
  h.position = float3(0.0, 0.0, 0.0);
  h.hitT = -1.0;
  h.geometricNormal = float3(0.0, 0.0, 1.0);
  h.instanceIndex = 0u;
  h.primitiveIndex = 0u;
  h.shadingNormal = float3(0.0, 0.0, 1.0);
  h.uv = float4(0.0, 0.0, 0.0, 0.0);
  h.color = float4(1.0, 1.0, 1.0, 1.0);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  h.textureFootprint = float2(-1.0e4, -1.0e4);
#endif
  h.shadingTangent = float3(0.0, 0.0, 0.0);
#if PT_COAT_NORMALS
  h.coatNormal = float3(0.0, 0.0, 1.0);
#endif
  return h;
}

// Interpolates a triangle hit from its object-space corners and the hit's
// barycentrics (b1, b2); the entry point supplies the object-to-world transform.
float3 barycentricInterpolate(float3 p0, float3 p1, float3 p2, float2 b) {
  return p0 * (1.0 - b.x - b.y) + p1 * b.x + p2 * b.y;
}

float2 barycentricInterpolate2(float2 a0, float2 a1, float2 a2, float2 b) {
  return a0 * (1.0 - b.x - b.y) + a1 * b.x + a2 * b.y;
}

float4 barycentricInterpolate4(float4 a0, float4 a1, float4 a2, float2 b) {
  return a0 * (1.0 - b.x - b.y) + a1 * b.x + a2 * b.y;
}

// The interpolated world-space vertex normal as a shading normal: unit and on
// ng's side (vertex normals that disagree with the winding are flipped rather
// than shading the back of the surface), or ng where there is none (zero
// vertex normals) or it is degenerate.
float3 resolveShadingNormal(float3 n, float3 ng) {
  float len = length(n);
  if (!(len > 1e-8) || !(len < 1e30)) return ng;
  n = n / len;
  return dot(n, ng) < 0.0 ? -n : n;
}

// The interpolated world-space vertex tangent made orthogonal to the shading
// normal (Gram-Schmidt), or zero when there is none.
float3 resolveShadingTangent(float3 t, float3 n) {
  float3 o = t - n * dot(n, t);
  float len = length(o);
  return len > 1e-8 && len < 1e30 ? o / len : float3(0.0, 0.0, 0.0);
}

// The shading normal n (unit, on ng's side) turned towards the geometric
// normal ng (unit, on wo's side) just enough that the mirror reflection of wo
// about it leaves the geometric surface: at least min(0.9 wo.ng, 0.01) above
// its plane (the 0.9 wo.ng keeps ng itself a valid answer for grazing views).
// Every interpolated shading normal goes through it, vertex normals as well
// as normal maps; only where the mirror direction would fall below the
// surface does it change anything. A normal map's bumps tilt
// n so far from ng that the reflection of a grazing view falls below the
// surface; a path that must end there draws a black rim around every bump.
// The same remedy as production renderers' "valid reflection" normal.
//
// n is turned in the plane of ng and n: with x the unit part of n
// orthogonal to ng and n(t) = sin(t) x + cos(t) ng, the reflection's height
// is r(t).ng = 2 (n(t).wo) cos(t) - wo.ng = A cos(2t - phi), with
// A = |(wo.x, wo.ng)| and phi = atan2(wo.x, wo.ng). The heights at least the
// margin m lie in 2t - phi in [-acos(m/A), acos(m/A)]; t = 0 (ng) is among
// them (m <= wo.ng), n's own angle is past them, so the largest, the least
// turn, is t = theta / 2 with theta = phi + acos(m/A). No trigonometry is
// needed: cos and sin of theta follow from those of phi (wo.ng / A,
// wo.x / A) and of acos(m/A) (m/A, sqrt(1 - (m/A)^2)) by the angle sum, and
// n(theta/2) is the direction of (sin theta) x + (1 + cos theta) ng (the
// half-angle identity; theta lies in (-pi/2, pi) because wo.ng > 0 and
// m >= 0). 1 + cos theta is taken as sin^2 / (1 - cos) where cos < 0, so it
// does not cancel near theta = pi.
float3 bendForValidReflection(float3 n, float3 ng, float3 wo) {
  float woZ = dot(wo, ng);
  float margin = min(0.9 * woZ, 0.01);
  float3 r = 2.0 * dot(n, wo) * n - wo;
  if (dot(r, ng) >= margin) return n;
  float3 x = n - dot(n, ng) * ng;
  float lenX = length(x);
  if (!(lenX > 1e-7)) return ng;
  x = x / lenX;
  float woX = dot(wo, x);
  float a = sqrt(woX * woX + woZ * woZ);
  float cosAlpha = clamp(margin / a, 0.0, 1.0);
  float sinAlpha = sqrt(1.0 - cosAlpha * cosAlpha);
  float cosTheta = (woZ * cosAlpha - woX * sinAlpha) / a;
  float sinTheta = (woX * cosAlpha + woZ * sinAlpha) / a;
  float onePlusCos = cosTheta >= 0.0 ? 1.0 + cosTheta : sinTheta * sinTheta / (1.0 - cosTheta);
  return normalize(sinTheta * x + onePlusCos * ng);
}

// The normal to shade with for a viewer in direction `wo` (unit, away from
// the surface): the shading normal n (or the coat's), bent for a valid mirror reflection
// (bendForValidReflection), unless wo lies on the other side of it than of
// the geometric surface; then the shading normal cannot describe what the
// viewer sees and the geometric normal takes over (no black fringes, no
// negative cosines). The result stays on the geometric normal's side.
float3 normalSeenFrom(float3 n, float3 ng, float3 wo) {
  float sideG = dot(wo, ng);
  float sideS = dot(wo, n);
  if (!(sideG * sideS > 0.0)) return ng;
  float facing = sideG > 0.0 ? 1.0 : -1.0;
  return facing * bendForValidReflection(facing * n, facing * ng, wo);
}

float3 shadingNormalFor(SurfaceHit hit, float3 wo) {
  return normalSeenFrom(hit.shadingNormal, hit.geometricNormal, wo);
}

// Whether wi continues on the side of the geometric surface that the shading
// frame says it does (reflection vs transmission agree for both normals).
// Samples that fail would carry light through the surface (light leaks) or
// reflect from inside it; they are discarded.
bool shadingConsistent(float3 ng, float3 wo, float3 wi, float woZ, float wiZ) {
  bool geometricReflection = dot(wo, ng) * dot(wi, ng) > 0.0;
  bool shadingReflection = woZ * wiZ > 0.0;
  return geometricReflection == shadingReflection;
}

#endif
