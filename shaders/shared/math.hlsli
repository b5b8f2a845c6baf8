// Constants and small vector helpers of the portable shading core.
#ifndef PENUMBRA_MATH_HLSLI
#define PENUMBRA_MATH_HLSLI

static const float kPi = 3.14159265358979323846;
static const float kInvPi = 0.31830988618379067154;

// The dialect has no splat constructors (float3(x) is not HLSL-portable in
// every front-end), so these spell them out.
float3 splat3(float v) { return float3(v, v, v); }
float3 zero3() { return float3(0.0, 0.0, 0.0); }

float maxComponent(float3 v) { return max(v.x, max(v.y, v.z)); }
float luminance(float3 rgb) { return dot(rgb, float3(0.2126, 0.7152, 0.0722)); }

// Orthonormal frame around a unit normal, without branches that lose
// precision near the poles (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited").
struct Frame {
  float3 tangent;
  float3 bitangent;
  float3 normal;
};

Frame frameFromNormal(float3 n) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  Frame f;
  f.tangent = float3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
  f.bitangent = float3(b, s + n.y * n.y * a, -n.y);
  f.normal = n;
  return f;
}

float3 frameToWorld(Frame f, float3 v) { return v.x * f.tangent + v.y * f.bitangent + v.z * f.normal; }

float3 frameToLocal(Frame f, float3 v) {
  return float3(dot(v, f.tangent), dot(v, f.bitangent), dot(v, f.normal));
}

#endif
