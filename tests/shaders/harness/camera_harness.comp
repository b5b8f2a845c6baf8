#version 460
// The shading core's pinhole camera (shaders/shared/camera.hlsli) for
// tests/apps/viewer/test_picking.cpp: ray i goes through film position
// gFilm[i] of the frame constants gFrame, as the ray generation shaders trace
// it; its origin goes to gRays[2i], its direction to gRays[2i + 1].
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
#include "camera.hlsli"

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push { uint gCount; };
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Constants { FrameConstants gFrame; };
layout(set = 0, binding = PENUMBRA_T(1), std430) readonly buffer FilmPositions { vec2 gFilm[]; };
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { vec4 gRays[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  Rng rng = rngCreate(uvec2(0u, 0u), 0u, 0u, RNG_SAMPLER_RANDOM);  // a pinhole draws none
  vec3 origin, direction;
  cameraRay(gFrame, gFilm[i], rng, origin, direction);
  gRays[2u * i] = vec4(origin, 1.0);
  gRays[2u * i + 1u] = vec4(direction, 0.0);
}
