#version 460
// Runs the environment's lookup and sampling (shaders/shared/environment.hlsli)
// for tests/shaders/test_environment_sampling.cpp. Item i reads gInputs[i]:
// with gMode 0 the uniform pair xy, sampled; with gMode 1 the direction xyz,
// looked up. It writes 8 floats: the direction, the density, the radiance
// and environmentPdf(direction) (the density evaluated again, for MIS).
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
#include "math.hlsli"

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push {
  uint gMode;
  uint gCount;
};
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Info { EnvironmentData gEnvironment; };
layout(set = 0, binding = PENUMBRA_T(1), std430) readonly buffer Texels { float4 gTexels[]; };
layout(set = 0, binding = PENUMBRA_T(2), std430) readonly buffer Cdf { float gCdf[]; };
layout(set = 0, binding = PENUMBRA_T(3), std430) readonly buffer Inputs { float4 gInputs[]; };
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { float gResults[]; };

EnvironmentData loadEnvironment() { return gEnvironment; }
float4 loadEnvironmentTexel(uint index) { return gTexels[index]; }
float loadEnvironmentCdf(uint index) { return gCdf[index]; }
#include "environment.hlsli"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  float4 item = gInputs[i];
  float3 direction;
  float pdf;
  float3 radiance;
  if (gMode == 0u) {
    EnvironmentSample s = sampleEnvironment(item.x, item.y);
    direction = s.direction;
    pdf = s.pdf;
    radiance = s.radiance;
  } else {
    direction = normalize(item.xyz);
    pdf = environmentPdf(direction);
    radiance = environmentRadiance(direction);
  }
  uint o = i * 8u;
  gResults[o + 0u] = direction.x;
  gResults[o + 1u] = direction.y;
  gResults[o + 2u] = direction.z;
  gResults[o + 3u] = pdf;
  gResults[o + 4u] = radiance.x;
  gResults[o + 5u] = radiance.y;
  gResults[o + 6u] = radiance.z;
  gResults[o + 7u] = environmentPdf(direction);
}
