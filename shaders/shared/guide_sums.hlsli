// Per-pixel sums of the path guides over one frame's samples (PathGuides in
// path_tracer.hlsli); the ray generation shader turns them into running means
// in the guide buffers (PT_U_GUIDE_* in path_tracer_shared.h).
#ifndef PENUMBRA_GUIDE_SUMS_HLSLI
#define PENUMBRA_GUIDE_SUMS_HLSLI
#include "math.hlsli"

struct GuideSums {
  float3 albedo;
  float4 normalDepth;  // xyz normal, w linear view depth
  float3 emission;
  float2 moments;      // luminance of (radiance - emission), and its square
};

GuideSums noGuideSums() {
  GuideSums s;
  s.albedo = zero3();
  s.normalDepth = float4(0.0, 0.0, 0.0, 0.0);
  s.emission = zero3();
  s.moments = float2(0.0, 0.0);
  return s;
}

// `cosForward`: the camera ray's cosine to the view axis, which turns the
// unfolded path length into linear view depth.
void addGuides(inout GuideSums s, PathGuides g, float3 radiance, float cosForward) {
  s.albedo += g.albedo;
  s.normalDepth += float4(g.normal, g.distance * cosForward);
  s.emission += g.emission;
  float l = luminance(radiance - g.emission);
  s.moments += float2(l, l * l);
}

#endif
