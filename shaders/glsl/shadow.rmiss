#version 460
#extension GL_EXT_ray_tracing : require

// Shadow rays skip closest-hit shaders: reaching the miss shader means nothing
// blocked the segment.
layout(location = 1) rayPayloadInEXT uint gVisible;

void main() { gVisible = 1u; }
