#version 460
// Runs the shading core's Disney BSDF (shaders/shared/disney_bsdf.hlsli) on
// many inputs for tests/render/test_disney_bsdf.cpp.
#extension GL_GOOGLE_include_directive : require
#include "prelude.glsl"
#include "path_tracer_shared.h"
layout(set = 0, binding = PENUMBRA_T(2), std430) readonly buffer SheenAlbedo {
  float gSheenAlbedo[];
};
float loadSheenAlbedo(uint index) {
  return gSheenAlbedo[index];
}
#include "material.hlsli"
#include "rng.hlsli"

#define MODE_SAMPLE 0u  // item i: a sample for wo with stream i -> (wi, pdf), (weight, lobe/delta)
#define MODE_EVAL 1u    // item i: gDirections[i] as wi -> (f(wo, wi), pdf), (f(wi, wo), pdf reversed)
#define MODE_SWEEP 2u   // item i: random extreme material and directions -> counts of bad values
#define MODE_FRAME 3u   // item i: an extreme normal -> orthonormality error of its frame

layout(local_size_x = 64) in;
layout(push_constant, std430) uniform Push {
  uint gMode;
  uint gCount;
  uint gSeed;
  uint gPad;
  float4 gWo;
  float4 gCoatNormal;  // DisneyMaterial.coatNormal for MODE_SAMPLE and MODE_EVAL
};
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Materials { MaterialData gMaterial[]; };
layout(set = 0, binding = PENUMBRA_T(1), std430) readonly buffer Directions { float4 gDirections[]; };
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { float4 gResults[]; };

float pick(inout Rng rng) {
  // Extremes as often as random values.
  float u = rngNext(rng);
  float v = rngNext(rng);
  if (u < 0.15) return 0.0;
  if (u < 0.30) return 1.0;
  if (u < 0.40) return 1e-4;
  if (u < 0.50) return 1.0 - 1e-4;
  return v;
}

float3 pickDirection(inout Rng rng) {
  float u = rngNext(rng);
  float a = rngNext(rng);
  float b = rngNext(rng);
  if (u < 0.1) return float3(0.0, 0.0, 1.0);
  if (u < 0.2) return float3(0.0, 0.0, -1.0);
  if (u < 0.3) return normalize(float3(cos(6.2831853 * a), sin(6.2831853 * a), 0.0));  // exactly grazing
  if (u < 0.4) return normalize(float3(cos(6.2831853 * a), sin(6.2831853 * a), 1e-7));
  if (u < 0.5) return normalize(float3(cos(6.2831853 * a), sin(6.2831853 * a), -1e-4));
  float z = 1.0 - 2.0 * a;
  float r = sqrt(max(0.0, 1.0 - z * z));
  return float3(r * cos(6.2831853 * b), r * sin(6.2831853 * b), z);
}

bool bad(float x) { return isnan(x) || isinf(x) || x < 0.0; }
bool bad3(float3 v) { return bad(v.x) || bad(v.y) || bad(v.z); }

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= gCount) return;
  if (gMode == MODE_SAMPLE) {
    DisneyMaterial m = unpackDisney(gMaterial[0]);
    m.coatNormal = gCoatNormal.xyz;
    Rng rng = rngCreate(uint2(i, 0u), 0u, gSeed, RNG_SAMPLER_RANDOM);
    uint k = pcgHash(gSeed);
    float u0 = float(pcgHash(pcgHash(3u * i + 0u) ^ k) >> 8u) * (1.0 / 16777216.0);
    float u1 = float(pcgHash(pcgHash(3u * i + 1u) ^ k) >> 8u) * (1.0 / 16777216.0);
    float u2 = float(pcgHash(pcgHash(3u * i + 2u) ^ k) >> 8u) * (1.0 / 16777216.0);
    BsdfSample s = disneySample(m, gWo.xyz, u0, u1, u2);
    gResults[2u * i] = float4(s.wi, s.pdf);
    gResults[2u * i + 1u] = float4(s.weight, float(s.lobe) + (s.isDelta ? 16.0 : 0.0));
  } else if (gMode == MODE_EVAL) {
    DisneyMaterial m = unpackDisney(gMaterial[0]);
    m.coatNormal = gCoatNormal.xyz;
    float3 wi = gDirections[i].xyz;
    BsdfEval forward = disneyEval(m, gWo.xyz, wi);
    BsdfEval backward = disneyEval(m, wi, gWo.xyz);
    gResults[2u * i] = float4(forward.f, forward.pdf);
    gResults[2u * i + 1u] = float4(backward.f, backward.pdf);
  } else if (gMode == MODE_SWEEP) {
    Rng rng = rngCreate(uint2(i, 1u), 0u, gSeed, RNG_SAMPLER_RANDOM);
    MaterialData d;
    d.baseColor = float3(pick(rng), pick(rng), pick(rng));
    d.emission = float3(0.0, 0.0, 0.0);
    d.metallic = pick(rng);
    d.roughness = pick(rng);
    d.anisotropic = pick(rng);
    d.anisotropyStrength = pick(rng);
    d.specular = pick(rng);
    d.specularTint = pick(rng);
    d.sheen = pick(rng);
    d.sheenTint = pick(rng);
    d.clearcoat = pick(rng);
    float iorPick = rngNext(rng);
    float ior = iorPick < 0.2 ? 1.0 : (iorPick < 0.3 ? 1.0001 : (iorPick < 0.4 ? 4.0 : 1.0 + 2.0 * rngNext(rng)));
    d.clearcoatGloss = pick(rng);
    d.specTrans = pick(rng);
    d.ior = ior;
    d.subsurface = pick(rng);
    d.ks = 0.0;
    d.phongExponent = 0.0;
    d.reflectivity = 0.0;
    d.transparency = 0.0;
    uint flags = (rngNext(rng) < 0.3 ? MATERIAL_FLAG_THIN : 0u) |
                 (rngNext(rng) < 0.3 ? MATERIAL_FLAG_LAMBERT_DIFFUSE : 0u) |
                 (rngNext(rng) < 0.3 ? MATERIAL_FLAG_GGX_COAT : 0u) |
                 (rngNext(rng) < 0.3 ? MATERIAL_FLAG_CHARLIE_SHEEN : 0u);
    d.model = MATERIAL_MODEL_DISNEY;
    d.flags = flags;
    // F0 colours from 0 to past the clamp at 1 (0.08 x 20 = 1.6).
    d.specularColor = 20.0 * float3(pick(rng), pick(rng), pick(rng));
    d.specularF90 = pick(rng);
    d.sheenColor = float3(pick(rng), pick(rng), pick(rng));
    d.sheenRoughness = pick(rng);
    d.diffuseTransmission = pick(rng);
    d.diffuseTransmissionColor = float3(pick(rng), pick(rng), pick(rng));
    // Films from none to thicker than interference shows (1e5 nm), of any index.
    d.iridescence = pick(rng);
    d.iridescenceIor = 1.0 + 3.0 * pick(rng);
    d.iridescenceThickness = float2(0.0, 1e5 * pick(rng) * pick(rng));
    DisneyMaterial m = unpackDisney(d);
    // Half the time a coat normal of its own, any direction (the path
    // tracer keeps it on the geometric side, not always the shading one).
    if (rngNext(rng) < 0.5) m.coatNormal = pickDirection(rng);
    float3 wo = pickDirection(rng);
    float3 wi = pickDirection(rng);
    BsdfEval e = disneyEval(m, wo, wi);
    BsdfSample s = disneySample(m, wo, rngNext(rng), rngNext(rng), rngNext(rng));
    float badEval = (bad3(e.f) || bad(e.pdf)) ? 1.0 : 0.0;
    float badSample = (bad3(s.weight) || bad(s.pdf) || any(isnan(s.wi)) || any(isinf(s.wi))) ? 1.0 : 0.0;
    // A sample that produced a direction must be a unit vector.
    float badDirection = (s.lobe != BSDF_LOBE_NONE && abs(length(s.wi) - 1.0) > 1e-3) ? 1.0 : 0.0;
    gResults[i] = float4(badEval, badSample, badDirection, 0.0);
  } else {
    Rng rng = rngCreate(uint2(i, 2u), 0u, gSeed, RNG_SAMPLER_RANDOM);
    float3 n = pickDirection(rng);
    float tiny = rngNext(rng) < 0.5 ? 1e-20 : 0.0;
    n = normalize(n + float3(tiny, -tiny, 0.0));
    Frame f = frameFromNormal(n);
    float err = max(abs(dot(f.tangent, f.bitangent)), max(abs(dot(f.tangent, f.normal)), abs(dot(f.bitangent, f.normal))));
    err = max(err, max(abs(length(f.tangent) - 1.0), abs(length(f.bitangent) - 1.0)));
    // Right-handed: t x b = n.
    err = max(err, length(cross(f.tangent, f.bitangent) - n));
    gResults[i] = float4(isnan(err) ? 1e30 : err, 0.0, 0.0, 0.0);
  }
}
