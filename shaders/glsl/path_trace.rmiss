#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#include "hlsl_prelude.glsl"
#include "surface_hit.hlsli"

layout(location = 0) rayPayloadInEXT SurfaceHit gHit;

void main() { gHit = surfaceMiss(); }
