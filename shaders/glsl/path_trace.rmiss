#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#include "hlsl_prelude.glsl"
#include "hit_record.hlsli"

layout(location = 0) rayPayloadInEXT HitRecord gHit;

void main() { gHit = hitRecordMiss(); }
