#version 460
// The shading core's bendForValidReflection (shaders/shared/surface_hit.hlsli)
// for tests/shaders/test_shading_normal.cpp: case i bends shading normal
// gCases[i].n for geometric normal gCases[i].ng and viewer direction
// gCases[i].wo.
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
#include "surface_hit.hlsli"

struct BendCase {
  vec4 n;
  vec4 ng;
  vec4 wo;
};

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push { uint gCount; };
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Cases { BendCase gCases[]; };
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { vec4 gBent[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  BendCase c = gCases[i];
  gBent[i] = vec4(bendForValidReflection(c.n.xyz, c.ng.xyz, c.wo.xyz), 0.0);
}
