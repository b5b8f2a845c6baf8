// Unidirectional path tracing (Kajiya 1986) with the Disney BSDF: BSDF
// importance sampling (or uniform / cosine direction sampling, for study),
// next-event estimation on emissive triangles and on point/spot lights,
// multiple importance sampling (power or balance heuristic, Veach 1997)
// between NEE and BSDF sampling for area lights, delta lobes without MIS,
// Russian roulette, and optional per-sample radiance clamping.
//
// The entry points define, before including this file:
//   SurfaceHit traceClosest(float3 origin, float3 direction);
//   bool traceVisibility(float3 origin, float3 direction, float tMax);
//   InstanceData loadInstanceData(uint index);
//   MaterialData loadMaterial(uint index);
//   EmissiveTriangle loadEmissiveTriangle(uint index);
//   PointLight loadPointLight(uint index);
#ifndef PENUMBRA_PATH_TRACER_HLSLI
#define PENUMBRA_PATH_TRACER_HLSLI
#include "lights.hlsli"
#include "material.hlsli"
#include "ray_offset.hlsli"
#include "rng.hlsli"
#include "sampling.hlsli"
#include "surface_hit.hlsli"

float misWeight(uint flags, float pdfA, float pdfB) {
  if ((flags & PT_FLAG_BALANCE_HEURISTIC) != 0u) return pdfA + pdfB > 0.0 ? pdfA / (pdfA + pdfB) : 0.0;
  return powerHeuristic(pdfA, pdfB);
}

// Clamps one sample's contribution to `limit` (its largest channel), keeping
// its hue; limit 0 disables clamping.
float3 clampContribution(float3 contribution, float limit) {
  float peak = maxComponent(contribution);
  return limit > 0.0 && peak > limit ? contribution * (limit / peak) : contribution;
}

float3 sampleUniformSphere(float u0, float u1) {
  float z = 1.0 - 2.0 * u0;
  float r = sqrt(max(0.0, 1.0 - z * z));
  float phi = 2.0 * kPi * u1;
  return float3(r * cos(phi), r * sin(phi), z);
}

bool isFiniteColor(float3 c) { return !any(isnan(c)) && !any(isinf(c)); }

float3 frameToLocal(Frame f, float3 v) {
  return float3(dot(v, f.tangent), dot(v, f.bitangent), dot(v, f.normal));
}

// The shading frame about unit n, oriented by the hit's vertex tangent where
// it has one (anisotropic lobes follow the mesh's tangents).
Frame shadingFrame(SurfaceHit hit, float3 n) {
  float3 t = resolveShadingTangent(hit.shadingTangent, n);
  if (dot(t, t) < 0.5) return frameFromNormal(n);
  Frame f;
  f.tangent = t;
  f.bitangent = cross(n, t);
  f.normal = n;
  return f;
}

// A shadow ray prepared at a path vertex and traced once the vertex is
// done: its contribution counts if nothing blocks the segment.
struct ShadowRay {
  float3 origin;
  float3 direction;
  float tMax;          // 0: no ray
  float3 contribution;
};

ShadowRay noShadowRay() {
  ShadowRay r;
  r.origin = zero3();
  r.direction = float3(0.0, 0.0, 1.0);
  r.tMax = 0.0;
  r.contribution = zero3();
  return r;
}

// The shadow ray towards a point or spot light from a path vertex at
// `position`, carrying the light's contribution if nothing blocks it.
ShadowRay pointLightShadowRay(PointLight light, DisneyMaterial material, Frame frame, float3 position,
                              float3 ng, float3 direction, float3 wo, float3 throughput, float clampLimit) {
  ShadowRay r = noShadowRay();
  float3 wi;
  float distance;
  float3 incident = pointLightIncident(light, position, wi, distance);
  float3 wiLocal = frameToLocal(frame, wi);
  if (maxComponent(incident) <= 0.0 || wiLocal.z == 0.0 ||
      !shadingConsistent(ng, -direction, wi, wo.z, wiLocal.z))
    return r;
  BsdfEval e = disneyEval(material, wo, wiLocal);
  if (maxComponent(e.f) <= 0.0) return r;
  float3 spawn = offsetRayOrigin(position, dot(wi, ng) > 0.0 ? ng : -ng);
  float3 toLight = light.position.xyz - spawn;
  float shadowLength = length(toLight);
  if (!(shadowLength > 0.0)) return r;
  r.origin = spawn;
  r.direction = toLight / shadowLength;
  r.tMax = shadowLength;
  r.contribution = clampContribution(throughput * e.f * incident * abs(wiLocal.z), clampLimit);
  return r;
}

// The next direction at a path vertex by the strategy in `flags` (BSDF
// sampling, or uniform / cosine directions for study), with the throughput
// update and Russian roulette; false ends the path.
bool scatter(FrameConstants c, DisneyMaterial material, Frame frame, float3 ng, float3 direction,
             float3 wo, uint depth, inout Rng rng, inout float3 throughput, inout float previousPdf,
             inout bool previousDelta, out float3 wiWorld) {
  uint flags = c.sampling.w;
  uint directions = (flags >> PT_DIRECTIONS_SHIFT) & 3u;
  wiWorld = direction;
  float u0 = rngNext(rng);
  float u1 = rngNext(rng);
  float u2 = rngNext(rng);
  BsdfSample s;
  if (directions == PT_DIRECTIONS_BSDF || disneyHasDeltaLobe(material)) {
    s = disneySample(material, wo, u0, u1, u2);
  } else {
    s = disneyNoSample();
    float3 wiLocal;
    float pdf;
    if (directions == PT_DIRECTIONS_UNIFORM) {
      // The hemisphere of wo, or the whole sphere if the material transmits.
      wiLocal = sampleUniformSphere(u1, u2);
      pdf = 0.25 * kInvPi;
      if (material.specTrans <= 0.0 || material.metallic >= 1.0) {
        wiLocal.z = wo.z > 0.0 ? abs(wiLocal.z) : -abs(wiLocal.z);
        pdf = 0.5 * kInvPi;
      }
    } else {
      wiLocal = sampleCosineHemisphere(u1, u2);
      wiLocal.z = wo.z > 0.0 ? wiLocal.z : -wiLocal.z;
      pdf = cosineHemispherePdf(abs(wiLocal.z));
    }
    if (pdf > 0.0 && wiLocal.z != 0.0) {
      BsdfEval e = disneyEval(material, wo, wiLocal);
      s.wi = wiLocal;
      s.pdf = pdf;
      s.weight = e.f * (abs(wiLocal.z) / pdf);
      s.lobe = BSDF_LOBE_DIFFUSE;
    }
  }
  if (s.lobe == BSDF_LOBE_NONE || !(maxComponent(s.weight) > 0.0)) return false;
  wiWorld = normalize(frameToWorld(frame, s.wi));
  if (!shadingConsistent(ng, -direction, wiWorld, wo.z, s.wi.z) || dot(wiWorld, ng) == 0.0) return false;
  throughput *= s.weight;
  if (!isFiniteColor(throughput)) return false;
  previousPdf = s.pdf;
  previousDelta = s.isDelta;
  if ((flags & PT_FLAG_RUSSIAN_ROULETTE) != 0u && depth + 1u >= c.sampling.z) {
    float survive = min(maxComponent(throughput), 0.95);
    if (rngNext(rng) >= survive) return false;
    throughput /= survive;
  }
  return true;
}

// What the denoiser needs of one sample's path, at its first non-delta
// vertex: a mirror or smooth glass passes the guides on to the surface seen
// through it ("primary surface replacement"), so a reflection is filtered
// with the reflected surface's albedo, normal and depth.
struct PathGuides {
  float3 albedo;    // demodulationAlbedo() times the throughput of the delta chain before it
  float3 normal;    // world shading normal, on the viewer's side; zero where the path found no surface
  float3 emission;  // the part of the radiance emitted along the chain, up to and including it
  float distance;   // length of the unfolded path from the camera to it; 0: no surface
};

// What the denoiser divides a vertex's illumination by: the base colour
// (diffuse, metal, glass tint) plus the dielectric specular layer's normal
// reflectance, so a black glossy surface still has something to filter.
float3 demodulationAlbedo(DisneyMaterial m) {
  return m.baseColor + (1.0 - m.metallic) * (1.0 - m.specTrans) * dielectricSpecularF0(m);
}

PathGuides noGuides() {
  PathGuides g;
  g.albedo = zero3();
  g.normal = zero3();
  g.emission = zero3();
  g.distance = 0.0;
  return g;
}

// Radiance arriving along (origin, direction), and the path's guides.
//
// Each vertex first prepares its shadow rays (the light sample and the BSDF
// value towards it), then samples the next direction, and traces the shadow
// rays last, so that what is alive across each trace call is the path state
// alone (throughput, radiance, the next ray, the random stream), not the hit,
// material and shading frame: whatever is alive across a trace is saved and
// restored around it. The random numbers are drawn in the same order as
// when the shadow ray was traced before the bounce was sampled.
float3 tracePath(FrameConstants c, float3 origin, float3 direction, inout Rng rng, out PathGuides guides) {
  // Locals are not `const`: GLSL allows const only for constant expressions.
  uint flags = c.sampling.w;
  bool useNee = (flags & PT_FLAG_NEE) != 0u;
  bool useMis = useNee && (flags & PT_FLAG_MIS) != 0u;
  uint maxDepth = c.sampling.y;
  float clampLimit = c.shading.w;

  float3 radiance = zero3();
  float3 throughput = splat3(1.0);
  float previousPdf = 0.0;
  bool previousDelta = true;  // the camera ray counts as a delta "bounce"
  guides = noGuides();
  bool guidesOpen = true;  // every vertex so far was delta: the guides are still ahead
  float3 chainThroughput = splat3(1.0);
  float chainLength = 0.0;

  for (uint depth = 0u;; depth += 1u) {
    SurfaceHit hit = traceClosest(origin, direction);
    if (hit.hitT < 0.0) break;  // no environment light yet
    float3 radianceBefore = radiance;
    InstanceData instance = loadInstanceData(hit.instanceIndex);
    MaterialData data = loadMaterial(instance.materialIndex);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
    data = applyMaterialTextures(data, hit.uv);
#endif

#if PT_HAS_EFFECT(PT_EFFECT_AREA_LIGHTS)
    // Emission: one-sided, from the front face (counter-clockwise; outside
    // of an implicit surface).
    float cosLight = -dot(direction, hit.geometricNormal);
    if (instance.firstEmissiveTriangle != PT_NO_EMISSION && cosLight > 0.0) {
      float3 emitted = throughput * data.emission.xyz;
      // An emitter NEE never samples has light pdf 0: BSDF sampling is the
      // only strategy that finds it, so its MIS weight is 1.
      bool neeSamples = instance.firstEmissiveTriangle != PT_EMISSION_NOT_SAMPLED;
      if (depth == 0u || previousDelta || !useNee || c.lights.x == 0u || !neeSamples) {
        radiance += clampContribution(emitted, clampLimit);
      } else if (useMis) {
        float lightPdf = areaToSolidAnglePdf(
            emissiveTrianglePdfArea(instance.firstEmissiveTriangle + hit.primitiveIndex), hit.hitT,
            cosLight);
        radiance += clampContribution(emitted * misWeight(flags, previousPdf, lightPdf), clampLimit);
      }
      // NEE without MIS: this light was already counted by a shadow ray.
    }
#endif
    DisneyMaterial material = unpackDisney(data);
    if (guidesOpen) {
      // Provisionally this vertex; a delta scatter below passes them on.
      chainLength += hit.hitT;
      guides.emission += radiance - radianceBefore;
      guides.albedo = chainThroughput * demodulationAlbedo(material);
      // Facing the viewer, so both sides of a surface filter alike.
      float3 n = shadingNormalFor(hit, -direction);
      guides.normal = dot(n, direction) > 0.0 ? -n : n;
      guides.distance = chainLength;
    }
    if (depth >= maxDepth) break;

    // The BSDF sees the shading frame; rays leave from the geometric surface,
    // and every direction must be on the same geometric side as the shading
    // frame says (shadingConsistent), so interpolated normals leak no light.
    float3 ng = hit.geometricNormal;
    Frame frame = shadingFrame(hit, shadingNormalFor(hit, -direction));
    float3 wo = frameToLocal(frame, -direction);
    if (wo.z == 0.0 || dot(direction, ng) == 0.0) break;  // exactly grazing: no side to scatter into

    ShadowRay areaShadow = noShadowRay();
#if PT_HAS_EFFECT(PT_EFFECT_AREA_LIGHTS)
    if (useNee && c.lights.x > 0u) {
      float u0 = rngNext(rng);
      float u1 = rngNext(rng);
      float u2 = rngNext(rng);
      LightSample light = sampleEmissiveTriangles(c.lights.x, u0, u1, u2);
      float3 toLight = light.position - hit.position;
      float distance = length(toLight);
      float3 wi = toLight / max(distance, 1e-30);
      float cosAtLight = -dot(light.normal, wi);
      float3 wiLocal = frameToLocal(frame, wi);
      if (cosAtLight > 0.0 && distance > 0.0 && wiLocal.z != 0.0 &&
          shadingConsistent(ng, -direction, wi, wo.z, wiLocal.z)) {
        BsdfEval e = disneyEval(material, wo, wiLocal);
        if (maxComponent(e.f) > 0.0) {
          float3 spawn = offsetRayOrigin(hit.position, dot(wi, ng) > 0.0 ? ng : -ng);
          // End the shadow ray just off the light's surface, on the lit side.
          float3 target = offsetRayOrigin(light.position, light.normal);
          float3 shadowDir = target - spawn;
          float shadowLength = length(shadowDir);
          if (shadowLength > 0.0) {
            float lightPdf = areaToSolidAnglePdf(light.pdfArea, distance, cosAtLight);
            float weight = useMis ? misWeight(flags, lightPdf, e.pdf) : 1.0;
            areaShadow.origin = spawn;
            areaShadow.direction = shadowDir / shadowLength;
            areaShadow.tMax = shadowLength;
            areaShadow.contribution = clampContribution(
                throughput * e.f * light.radiance * (abs(wiLocal.z) * weight / lightPdf), clampLimit);
          }
        }
      }
    }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
    float3 vertexThroughput = throughput;  // the point lights' shadow rays are built after the scatter
#endif

    float3 wiWorld;
    bool continues =
        scatter(c, material, frame, ng, direction, wo, depth, rng, throughput, previousPdf, previousDelta, wiWorld);
    float3 nextOrigin = offsetRayOrigin(hit.position, dot(wiWorld, ng) > 0.0 ? ng : -ng);
    guidesOpen = guidesOpen && continues && previousDelta;
    chainThroughput = throughput;

    // One trace call site for every shadow ray of the vertex: the area
    // light's, then one per point or spot light.
    uint shadowRays = 1u;
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
    if (useNee) shadowRays += c.lights.y;
#endif
    for (uint k = 0u; k < shadowRays; k += 1u) {
      ShadowRay shadow = areaShadow;
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
      if (k > 0u)
        shadow = pointLightShadowRay(loadPointLight(k - 1u), material, frame, hit.position, ng, direction, wo,
                                     vertexThroughput, clampLimit);
#endif
      if (shadow.tMax > 0.0 && traceVisibility(shadow.origin, shadow.direction, shadow.tMax))
        radiance += shadow.contribution;
    }
    if (!continues) break;
    origin = nextOrigin;
    direction = wiWorld;
  }
  return radiance;
}

#endif
