#version 460
// Runs the wavelength sampling and the dispersive index of
// shaders/shared/spectrum.hlsli for tests/shaders/test_spectrum.cpp. Item i
// reads the uniform number gInputs[i]; it writes 5 floats: the wavelength
// drawn, its weight (rgb) and the index at that wavelength of a material of
// index gIor and dispersion gDispersion.
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
#include "spectrum.hlsli"

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push {
  uint gCount;
  float gIor;
  float gDispersion;
};
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Inputs {
  float gInputs[];
};
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results {
  float gResults[];
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  WavelengthSample s = sampleWavelength(gInputs[i]);
  gResults[i * 5u] = s.lambda;
  gResults[i * 5u + 1u] = s.weight.x;
  gResults[i * 5u + 2u] = s.weight.y;
  gResults[i * 5u + 3u] = s.weight.z;
  gResults[i * 5u + 4u] = dispersedIor(gIor, gDispersion, s.lambda);
}
