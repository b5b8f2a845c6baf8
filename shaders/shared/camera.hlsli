// The camera of FrameConstants: a pinhole or a thin lens.
#ifndef PENUMBRA_CAMERA_HLSLI
#define PENUMBRA_CAMERA_HLSLI

#include "effects.h"
#include "rng.hlsli"
#include "sampling.hlsli"

// Where `filmPosition` (pixels, (0,0) the top-left corner of the image) lies
// on the film, along the camera's right and up: at unit distance ahead for a
// perspective camera, in world units about its position for an orthographic one.
float2 filmPoint(FrameConstants c, float2 filmPosition) {
  float halfHeight = c.camera.filmHalfHeight;
  return float2((2.0 * filmPosition.x / float(c.width) - 1.0) * halfHeight * c.camera.aspectRatio,
                (1.0 - 2.0 * filmPosition.y / float(c.height)) * halfHeight);
}

// The perspective ray's direction through `filmPosition`. filmPoint's
// arithmetic spelled out, not called: so the perspective variants' SPIR-V is
// the one they had before orthographic cameras, statement for statement, and
// a perspective scene runs the code it ran then (docs/results.md,
// "Orthographic cameras as an effect bit"; a call changes the SPIR-V's
// shape, and the driver's code for the whole megakernel follows it).
float3 cameraRayDirection(FrameConstants c, float2 filmPosition) {
  float tanHalfFov = c.camera.filmHalfHeight;
  float aspect = c.camera.aspectRatio;
  float sx = (2.0 * filmPosition.x / float(c.width) - 1.0) * tanHalfFov * aspect;
  float sy = (1.0 - 2.0 * filmPosition.y / float(c.height)) * tanHalfFov;
  return normalize(c.camera.forward + sx * c.camera.right + sy * c.camera.up);
}

// The camera's pixel cone at world point p (texture level of detail,
// textures.hlsli): xyz the unit direction the camera sees p along, w the
// cone's width there. A perspective pixel spans 2 tan(fov / 2) / height
// radians at the view's centre; an orthographic one is 2 halfHeight / height
// wide at any distance. Every vertex of a path takes the cone the camera
// would have there (as pbrt-v4 approximates footprints after the first
// hit): nothing rides along the path, and a point seen in a mirror, no
// farther from the camera than the path that reached it, reads textures
// finer than its true footprint, never coarser. Without a camera (zero
// constants: the probe) the width is 0, no cone.
float4 pixelCone(FrameConstants c, float3 p) {
  float pixel = 2.0 * c.camera.filmHalfHeight / max(float(c.height), 1.0);
#if PT_HAS_EFFECT(PT_EFFECT_ORTHOGRAPHIC)
  if ((c.sceneFlags & PT_SCENE_ORTHOGRAPHIC) != 0u) return float4(c.camera.forward, pixel);
#endif
  float3 v = p - c.camera.position;
  float distance = length(v);
  return float4(distance > 0.0 ? v / distance : c.camera.forward, pixel * distance);
}

// Stratified jittered position of sample `index` of `count` in one frame: the
// first m*m samples (m = floor(sqrt(count))) each cover one cell of an m x m
// grid, the rest are uniform.
float2 jitteredPixelSample(uint index, uint count, float u0, float u1) {
  uint m = uint(sqrt(float(count)));
  while ((m + 1u) * (m + 1u) <= count) m += 1u;
  while (m * m > count) m -= 1u;
  if (index < m * m) {
    float cell = 1.0 / float(m);
    return float2((float(index % m) + u0) * cell, (float(index / m) + u1) * cell);
  }
  return float2(u0, u1);
}

// The random stream of the pixel's sample `sampleIndex` (counted over the
// whole accumulation), from the sampler FrameConstants.flags names.
Rng sampleRng(FrameConstants c, uint2 pixel, uint sampleIndex) {
  uint kind = (c.flags & PT_FLAG_SOBOL) != 0u ? RNG_SAMPLER_SOBOL : RNG_SAMPLER_RANDOM;
  return rngCreate(pixel, sampleIndex, c.seed, kind);
}

// Position in the pixel of sample `index` of the `count` this frame takes:
// the Sobol sampler's first two dimensions are stratified already (over the
// whole accumulation, not only this frame); random numbers are jittered.
float2 pixelSample(inout Rng rng, uint index, uint count) {
  float u0 = rngNext(rng);
  float u1 = rngNext(rng);
  if (rng.kind == RNG_SAMPLER_SOBOL) return float2(u0, u1);
  return jitteredPixelSample(index, count, u0, u1);
}

// A uniform point of the regular polygon with `sides` corners on the unit
// circle (an aperture of that many straight blades), one corner on +x: u0
// picks the wedge between two corners and the centre, and what is left of
// it with u1 a uniform point of that triangle.
float2 samplePolygon(uint sides, float u0, float u1) {
  float scaled = u0 * float(sides);
  float wedge = min(floor(scaled), float(sides) - 1.0);
  float2 b = sampleUniformTriangle(saturate(scaled - wedge), u1);
  float step = 2.0 * kPi / float(sides);
  float2 a0 = float2(cos(wedge * step), sin(wedge * step));
  float2 a1 = float2(cos((wedge + 1.0) * step), sin((wedge + 1.0) * step));
  return b.x * a0 + b.y * a1;
}

// The camera ray through `filmPosition`: the pinhole's (from the position
// through the film point; orthographic: from the film point along forward),
// or with a thin lens (camera.apertureRadius > 0) from a point of the
// aperture (a disk, or a polygon of FrameConstants.sceneFlags' blade count)
// towards where the pinhole ray meets the plane in focus, so that plane stays
// sharp and everything nearer or farther blurs by its circle of confusion. A
// pinhole draws no random numbers, so its images do not change with the lens
// code.
void cameraRay(FrameConstants c, float2 filmPosition, inout Rng rng, out float3 origin,
               out float3 direction) {
  origin = c.camera.position;
  direction = cameraRayDirection(c, filmPosition);
  // A variant bit, not only the frame's flag: the branch alone moved the
  // driver's code for the whole megakernel (docs/results.md).
#if PT_HAS_EFFECT(PT_EFFECT_ORTHOGRAPHIC)
  if ((c.sceneFlags & PT_SCENE_ORTHOGRAPHIC) != 0u) {
    float2 film = filmPoint(c, filmPosition);
    origin = c.camera.position + film.x * c.camera.right + film.y * c.camera.up;
    direction = c.camera.forward;
  }
#endif
  float lensRadius = c.camera.apertureRadius;
  if (lensRadius > 0.0) {
    float3 inFocus = origin + direction * (c.camera.focusDistance / dot(direction, c.camera.forward));
    float u0 = rngNext(rng);
    float u1 = rngNext(rng);
    uint blades = (c.sceneFlags >> PT_SCENE_BLADES_SHIFT) & 255u;
    float2 lens = (blades >= 3u ? samplePolygon(blades, u0, u1) : sampleConcentricDisk(u0, u1)) * lensRadius;
    origin += lens.x * c.camera.right + lens.y * c.camera.up;
    direction = normalize(inFocus - origin);
  }
}

#endif
