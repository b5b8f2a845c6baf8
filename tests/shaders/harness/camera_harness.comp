#version 460
// The shading core's pinhole camera (shaders/shared/camera.hlsli) for
// tests/apps/viewer/test_picking.cpp: ray i goes through film position
// gFilm[i] of the frame constants gFrame, as the ray generation shaders trace it.
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
#include "camera.hlsli"

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push { uint gCount; };
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Constants { FrameConstants gFrame; };
layout(set = 0, binding = PENUMBRA_T(1), std430) readonly buffer FilmPositions { vec2 gFilm[]; };
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { vec4 gDirections[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  gDirections[i] = vec4(cameraRayDirection(gFrame, gFilm[i]), 0.0);
}
