// Spawning secondary rays without self-intersection: offset the origin along
// the geometric normal by a few ULPs in integer space, so the offset scales
// with the magnitude of the position (Wächter & Binder, "A Fast and Robust
// Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6).
#ifndef PENUMBRA_RAY_OFFSET_HLSLI
#define PENUMBRA_RAY_OFFSET_HLSLI

float offsetComponent(float p, float n) {
  const float kOrigin = 1.0 / 32.0;
  const float kFloatScale = 1.0 / 65536.0;
  const float kIntScale = 256.0;
  int ulps = int(kIntScale * n);
  float moved = asfloat(asint(p) + (p < 0.0 ? -ulps : ulps));
  // Near the origin ULPs are tiny, so a fixed float offset is used instead.
  return abs(p) < kOrigin ? p + kFloatScale * n : moved;
}

// `n` is the geometric normal on the side the new ray leaves from.
float3 offsetRayOrigin(float3 p, float3 n) {
  return float3(offsetComponent(p.x, n.x), offsetComponent(p.y, n.y), offsetComponent(p.z, n.z));
}

#endif
