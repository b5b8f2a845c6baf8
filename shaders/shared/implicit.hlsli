// Implicit surfaces (engine/penumbra/scene/implicit_object.h) on the GPU: the world
// ray moved into an object's space, analytic intersections (sphere, plane,
// box) and the SurfaceHit a closest-hit shader reports. Sphere tracing of the
// SDF kinds is in sphere_tracing.hlsli.
//
// Object-space rays carry a unit direction, so the distance `s` along them is
// an object-space length (what SDFs measure); `s * tPerS` is the world ray's
// parameter t, which is what intersection shaders must report for hit
// distances, shadows and MIS to be right under scaled transforms.
//
// Every function returns the hit nearest to the origin within [sMin, sMax],
// so a ray that starts inside a closed shape reports where it leaves it.
// Normals face the front side: outwards, or +y for a plane.
#ifndef PENUMBRA_IMPLICIT_HLSLI
#define PENUMBRA_IMPLICIT_HLSLI
#include "math.hlsli"
#include "surface_hit.hlsli"
#include "payloads_shared.h"

struct ImplicitHit {
  float s;        // < 0: no hit
  float3 normal;  // unit, object space, front side
};

ImplicitHit implicitMiss() {
  ImplicitHit h;
  h.s = -1.0;
  h.normal = float3(0.0, 0.0, 1.0);
  return h;
}

ImplicitHit implicitHitAt(float s, float3 normal) {
  ImplicitHit h;
  h.s = s;
  h.normal = normal;
  return h;
}

struct ObjectRay {
  float3 origin;
  float3 direction;  // unit
  float sMin;
  float sMax;
  float tPerS;       // world t per object-space distance
};

float3 worldToObjectPoint(ImplicitData o, float3 p) {
  return float3(dot(o.worldToObject0.xyz, p) + o.worldToObject0.w,
                dot(o.worldToObject1.xyz, p) + o.worldToObject1.w,
                dot(o.worldToObject2.xyz, p) + o.worldToObject2.w);
}

float3 worldToObjectVector(ImplicitData o, float3 v) {
  return float3(dot(o.worldToObject0.xyz, v), dot(o.worldToObject1.xyz, v),
                dot(o.worldToObject2.xyz, v));
}

// Normals transform with the inverse transpose of object-to-world, i.e. as a
// row vector times world-to-object.
float3 objectToWorldNormal(ImplicitData o, float3 n) {
  return normalize(n.x * o.worldToObject0.xyz + n.y * o.worldToObject1.xyz +
                   n.z * o.worldToObject2.xyz);
}

ObjectRay objectRay(ImplicitData o, float3 worldOrigin, float3 worldDirection, float tMin,
                    float tMax) {
  float3 d = worldToObjectVector(o, worldDirection);
  float len = length(d);
  ObjectRay r;
  r.origin = worldToObjectPoint(o, worldOrigin);
  r.direction = d / len;
  r.sMin = tMin * len;
  r.sMax = tMax * len;
  r.tPerS = 1.0 / len;
  return r;
}

float3 axisVector(uint axis, float sign) {
  if (axis == 0u) return float3(sign, 0.0, 0.0);
  if (axis == 1u) return float3(0.0, sign, 0.0);
  return float3(0.0, 0.0, sign);
}

// Where a ray is inside the box [lo, hi] (slab method): from sEnter to sExit,
// empty when sEnter > sExit. Axes the ray runs parallel to are tested
// directly rather than divided by zero.
struct SlabSpan {
  float sEnter;
  float sExit;
  uint enterAxis;
  uint exitAxis;
};

SlabSpan intersectSlabs(float3 origin, float3 direction, float3 lo, float3 hi) {
  SlabSpan span;
  span.sEnter = -1e38;
  span.sExit = 1e38;
  span.enterAxis = 0u;
  span.exitAxis = 0u;
  for (uint axis = 0u; axis < 3u; axis += 1u) {
    float o = origin[axis];
    float d = direction[axis];
    if (d == 0.0) {
      if (o < lo[axis] || o > hi[axis]) {
        span.sEnter = 1e38;
        span.sExit = -1e38;
        return span;
      }
      continue;
    }
    float s0 = (lo[axis] - o) / d;
    float s1 = (hi[axis] - o) / d;
    float sNear = min(s0, s1);
    float sFar = max(s0, s1);
    if (sNear > span.sEnter) {
      span.sEnter = sNear;
      span.enterAxis = axis;
    }
    if (sFar < span.sExit) {
      span.sExit = sFar;
      span.exitAxis = axis;
    }
  }
  return span;
}

// Haines et al., "Precision Improvements for Ray/Sphere Intersection" (Ray
// Tracing Gems ch. 7): the discriminant as r^2 - |f - (f.d) d|^2 (the
// squared distance of the ray's closest approach) instead of b^2 - c, which
// cancels when the sphere is small against its distance; the nearer root as
// c / q so it does not cancel either. Hit points are the closest approach
// -+ the half chord, so normals stay accurate for tiny, distant spheres.
ImplicitHit intersectSphere(float3 origin, float3 direction, float radius, float sMin, float sMax) {
  float b = dot(origin, direction);
  float3 closest = origin - b * direction;  // centre -> closest approach
  float r2 = radius * radius;
  float discriminant = r2 - dot(closest, closest);
  if (discriminant < 0.0) return implicitMiss();
  float halfChord = sqrt(discriminant);
  float c = dot(origin, origin) - r2;
  float q = b >= 0.0 ? -b - halfChord : -b + halfChord;
  float sNear = 0.0;
  float sFar = 0.0;
  if (q != 0.0) {
    sNear = min(c / q, q);
    sFar = max(c / q, q);
  }
  if (sNear >= sMin && sNear <= sMax)
    return implicitHitAt(sNear, normalize(closest - halfChord * direction));
  if (sFar >= sMin && sFar <= sMax)
    return implicitHitAt(sFar, normalize(closest + halfChord * direction));
  return implicitMiss();
}

// The plane y = 0 within |x| <= halfExtents.x, |z| <= halfExtents.y. A ray
// in the plane's direction never crosses it, so it misses.
ImplicitHit intersectPlane(float3 origin, float3 direction, float2 halfExtents, float sMin,
                           float sMax) {
  if (direction.y == 0.0) return implicitMiss();
  float s = -origin.y / direction.y;
  if (!(s >= sMin && s <= sMax)) return implicitMiss();
  float3 p = origin + s * direction;
  if (abs(p.x) > halfExtents.x || abs(p.z) > halfExtents.y) return implicitMiss();
  return implicitHitAt(s, float3(0.0, 1.0, 0.0));
}

// The box |x| <= halfExtents: the entry face, or the exit face for a ray
// that starts inside; the normal is the face's outward axis.
ImplicitHit intersectBox(float3 origin, float3 direction, float3 halfExtents, float sMin,
                         float sMax) {
  SlabSpan span = intersectSlabs(origin, direction, -halfExtents, halfExtents);
  if (span.sEnter > span.sExit) return implicitMiss();
  if (span.sEnter >= sMin && span.sEnter <= sMax) {
    float outward = direction[span.enterAxis] > 0.0 ? -1.0 : 1.0;
    return implicitHitAt(span.sEnter, axisVector(span.enterAxis, outward));
  }
  if (span.sExit >= sMin && span.sExit <= sMax) {
    float outward = direction[span.exitAxis] > 0.0 ? 1.0 : -1.0;
    return implicitHitAt(span.sExit, axisVector(span.exitAxis, outward));
  }
  return implicitMiss();
}

// The closest-hit shaders' report: world position from the world ray (the
// hit distance is already world t), the normal brought to world space.
SurfaceHit implicitSurfaceHit(ImplicitData o, float3 worldOrigin, float3 worldDirection, float hitT,
                              float3 objectNormal) {
  SurfaceHit h;
  h.position = worldOrigin + hitT * worldDirection;
  h.hitT = hitT;
  h.geometricNormal = objectToWorldNormal(o, objectNormal);
  h.instanceIndex = o.instanceIndex;
  h.primitiveIndex = 0u;
  // No vertex attributes: the surface shades with its true normal.
  h.shadingNormal = h.geometricNormal;
  h.uv = float4(0.0, 0.0, 0.0, 0.0);
  h.color = float4(1.0, 1.0, 1.0, 1.0);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  h.textureFootprint = float2(-1.0e4, -1.0e4);  // no texture coordinates
#endif
  h.shadingTangent = float3(0.0, 0.0, 0.0);
#if PT_COAT_NORMALS
  h.coatNormal = h.geometricNormal;
#endif
  return h;
}

#endif
