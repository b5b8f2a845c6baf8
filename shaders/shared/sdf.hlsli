// Signed distance functions of the SDF kinds, in object space (Quilez's
// exact forms for torus, box and rounded box). Every function is
// 1-Lipschitz, which is what lets sphere tracing step by its value; the
// Mandelbulb's estimator is the usual approximation of that.
#ifndef PENUMBRA_SDF_HLSLI
#define PENUMBRA_SDF_HLSLI
#include "math.hlsli"

static const float kMandelbulbBailout = 2.0;

float sdfSphere(float3 p, float radius) { return length(p) - radius; }

float sdfBox(float3 p, float3 halfExtents) {
  float3 q = abs(p) - halfExtents;
  return length(max(q, zero3())) + min(maxComponent(q), 0.0);
}

// The box shrunk by the corner radius, then grown back round.
float sdfRoundedBox(float3 p, float3 halfExtents, float cornerRadius) {
  return sdfBox(p, halfExtents - splat3(cornerRadius)) - cornerRadius;
}

// Around the y axis: distance to the tube's centre circle minus the tube radius.
float sdfTorus(float3 p, float majorRadius, float minorRadius) {
  float2 q = float2(length(float2(p.x, p.z)) - majorRadius, p.y);
  return length(q) - minorRadius;
}

// `shape` as in ImplicitData.shape for the kind.
float sdfPrimitive(uint kind, float4 shape, float3 p) {
  if (kind == IMPLICIT_SPHERE) return sdfSphere(p, shape.x);
  if (kind == IMPLICIT_BOX) return sdfBox(p, shape.xyz);
  if (kind == IMPLICIT_TORUS) return sdfTorus(p, shape.x, shape.y);
  return sdfRoundedBox(p, shape.xyz, shape.w);
}

// Quilez's polynomial smooth minimum. It lies at most k/4 below min(a, b)
// (the host pads a blend's bounds by that per primitive), and its gradient is
// a convex combination of the inputs' gradients, so blending distance bounds
// keeps a 1-Lipschitz bound. k = 0 is the plain union.
float smoothMin(float a, float b, float k) {
  if (k <= 0.0) return min(a, b);
  float h = max(k - abs(a - b), 0.0) / k;
  return min(a, b) - h * h * k * 0.25;
}

float sdfBlend(ImplicitData o, float3 p) {
  float d = sdfPrimitive(o.blendKinds.x, o.blendShapes[0], p - o.blendOffsets[0].xyz);
  for (uint i = 1u; i < o.blendCount; i += 1u) {
    float next = sdfPrimitive(o.blendKinds[i], o.blendShapes[i], p - o.blendOffsets[i].xyz);
    d = smoothMin(d, next, o.blendRadius);
  }
  return d;
}

// Torus, rounded box and blend: the sphere-traced kinds of the "sdf" family.
float sdfObjectDistance(ImplicitData o, float3 p) {
  if (o.kind == IMPLICIT_BLEND) return sdfBlend(o, p);
  return sdfPrimitive(o.kind, o.shape, p);
}

// The Mandelbulb's distance estimator 0.5 r ln(r) / |dz/dc| (Hart et al.
// 1989, as used for the bulb by Quilez and Christensen), iterating
// z <- z^n + p with the triplex power (r, theta, phi) -> (r^n, n theta, n phi).
float sdfMandelbulb(float3 p, float power, uint iterations) {
  float3 z = p;
  float dr = 1.0;
  float r = length(z);
  for (uint i = 0u; i < iterations; i += 1u) {
    r = length(z);
    if (r > kMandelbulbBailout || r == 0.0) break;
    float theta = acos(clamp(z.z / r, -1.0, 1.0)) * power;
    // atan2(0, 0) is undefined in GLSL: on the z axis phi is 0.
    float phi = (z.x != 0.0 || z.y != 0.0) ? atan2(z.y, z.x) * power : 0.0;
    dr = pow(r, power - 1.0) * power * dr + 1.0;
    float zr = pow(r, power);
    z = zr * float3(sin(theta) * cos(phi), sin(phi) * sin(theta), cos(theta)) + p;
  }
  // r = 0 only at points that never leave the origin: inside.
  return r > 0.0 ? 0.5 * log(r) * r / dr : -1.0;
}

#endif
