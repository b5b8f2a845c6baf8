#version 460
// Samples bindless texture and sampler arrays from a compute shader
// (texture_sample.glsl).
#extension GL_GOOGLE_include_directive : require
#include "texture_sample.glsl"

layout(local_size_x = 64) in;

void main() { sampleQuery(gl_GlobalInvocationID.x); }
