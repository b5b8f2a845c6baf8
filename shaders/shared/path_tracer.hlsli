// Unidirectional path tracing (Kajiya 1986) with the Disney BSDF: BSDF
// importance sampling (or uniform / cosine direction sampling, for study),
// next-event estimation on emissive triangles and on point/spot lights,
// multiple importance sampling (power or balance heuristic, Veach 1997)
// between NEE and BSDF sampling for area lights, delta lobes without MIS,
// Russian roulette, and optional per-sample radiance clamping.
//
// The entry points define, before including this file:
//   HitRecord traceRay(float3 origin, float3 direction, float tMax, bool shadow);
//     a radiance ray's closest hit (hitT < 0: it missed), or for a shadow
//     ray hitT < 0 exactly when nothing blocks [0, tMax]; the one trace call
//     of the integrator (tracePixel says why)
//   SurfaceHit surfaceFromRecord(float3 origin, float3 direction, HitRecord r);
//     the surface a radiance ray's record describes (surface_from_record.hlsli)
//   FrameConstants frameConstants();  // this launch's constants
//   uint2 launchPixel();  // the pixel this invocation renders
//   void addGuideSample(uint2 pixel, uint samplesBefore, float3 albedo, float4 normalDepth, float3
//   emission);
//     one sample's guides into the guide buffers' running means
//   InstanceData loadInstanceData(uint index);
//   MaterialData loadMaterial(uint index);
//   EmissiveTriangle loadEmissiveTriangle(uint index);
//   PointLight loadPointLight(uint index);
//   and environment.hlsli's loadEnvironment, loadEnvironmentTexel, loadEnvironmentCdf
//   and sheen.hlsli's loadSheenAlbedo
#ifndef PENUMBRA_PATH_TRACER_HLSLI
#define PENUMBRA_PATH_TRACER_HLSLI
#include "camera.hlsli"
#include "environment.hlsli"
#include "lights.hlsli"
#include "material.hlsli"
#include "ray_offset.hlsli"
#include "rng.hlsli"
#include "sampling.hlsli"
#include "spectrum.hlsli"
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

// The shading frame about unit n. An anisotropic material's lobes follow
// the mesh's tangents, so its frame is oriented by the hit's vertex tangent
// where it has one (turned by glTF's anisotropy direction: triangleSurfaceHit). Every other BSDF is the same about any tangent: its
// frame is built from the normal alone, and a pipeline without the GGX
// lobes (specular, glass) carries no tangent code at all.
Frame shadingFrame(SurfaceHit hit, float3 n, DisneyMaterial material) {
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR) || PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
  if (material.anisotropic != 0.0 || material.anisotropyStrength != 0.0) {
    float3 t = resolveShadingTangent(hit.shadingTangent, n);
    if (dot(t, t) >= 0.5) {
      Frame f;
      f.tangent = t;
      f.bitangent = cross(n, t);
      f.normal = n;
      return f;
    }
  }
#endif
  return frameFromNormal(n);
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

// The shadow ray towards a delta light (or a soft sun, its direction drawn
// by `u`) from a path vertex at `position`, carrying the light's
// contribution if nothing blocks it.
ShadowRay pointLightShadowRay(PointLight light, float2 u, DisneyMaterial material, Frame frame, float3 position,
                              float3 ng, float3 direction, float3 wo, float3 throughput, float clampLimit) {
  ShadowRay r = noShadowRay();
  float3 wi;
  float distance;
  float3 incident = pointLightIncident(light, position, u, wi, distance);
  float3 wiLocal = frameToLocal(frame, wi);
  if (maxComponent(incident) <= 0.0 || wiLocal.z == 0.0 ||
      !shadingConsistent(ng, -direction, wi, wo.z, wiLocal.z))
    return r;
  BsdfEval e = disneyEval(material, wo, wiLocal);
  if (maxComponent(e.f) <= 0.0) return r;
  float3 spawn = offsetRayOrigin(position, dot(wi, ng) > 0.0 ? ng : -ng);
  float shadowLength;
  float3 toLight = pointLightShadowSegment(light, spawn, wi, shadowLength);
  if (!(shadowLength > 0.0)) return r;
  r.origin = spawn;
  r.direction = toLight;
  r.tMax = shadowLength;
  r.contribution = clampContribution(throughput * e.f * incident * abs(wiLocal.z), clampLimit);
  return r;
}

#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
// What a delta light could give a vertex at `position` (geometric normal
// ng), shadows and the BSDF aside: its irradiance's luminance, times |cos|
// at the surface for a point or spot light (a soft sun's direction varies
// over its disk, so it gets none). Zero only where the light cannot
// contribute, so choosing in proportion leaves out no light that could.
float deltaLightWeight(PointLight light, float3 position, float3 ng) {
  float3 toLight;
  float distance;
  float3 incident = pointLightIncident(light, position, float2(-1.0, 0.0), toLight, distance);
  float w = luminance(incident);
  return isSoftSun(light) ? w : w * abs(dot(ng, toLight));
}

// One of `count` delta lights for a vertex, drawn in proportion to
// deltaLightWeight, with its probability; `count` (none) when no light can
// give anything. A single light is taken without a random number.
uint chooseDeltaLight(uint count, float3 position, float3 ng, inout Rng rng, out float probability) {
  probability = 1.0;
  if (count == 1u) return 0u;
  float total = 0.0;
  for (uint i = 0u; i < count; i += 1u) total += deltaLightWeight(loadPointLight(i), position, ng);
  float target = rngNext(rng) * total;
  uint chosen = count;
  float chosenWeight = 0.0;
  float running = 0.0;
  for (uint i = 0u; i < count; i += 1u) {
    float w = deltaLightWeight(loadPointLight(i), position, ng);
    if (w > 0.0) {
      chosen = i;  // the last light with weight, should rounding leave target past the sum
      chosenWeight = w;
      running += w;
      if (target < running) break;
    }
  }
  probability = total > 0.0 ? chosenWeight / total : 1.0;
  return chosen;
}
#endif

// The next direction at a path vertex by the strategy in `flags` (BSDF
// sampling, or uniform / cosine directions for study), before its BSDF
// value: `bsdf.wi` waits for disneyEval unless the sample is delta or
// none (lobe BSDF_LOBE_NONE). `fromBsdf`: its density is the BSDF's (from
// the evaluation), else `bsdf.pdf` is the strategy's.
struct ScatterDirection {
  BsdfSample bsdf;
  bool fromBsdf;
};

bool scatterNeedsEval(ScatterDirection d) { return d.bsdf.lobe != BSDF_LOBE_NONE && !d.bsdf.isDelta; }

ScatterDirection scatterDirection(FrameConstants c, DisneyMaterial material, float3 wo, inout Rng rng) {
  uint directions = (c.flags >> PT_DIRECTIONS_SHIFT) & 3u;
  float u0 = rngNext(rng);
  float u1 = rngNext(rng);
  float u2 = rngNext(rng);
  ScatterDirection d;
  d.fromBsdf = directions == PT_DIRECTIONS_BSDF || disneyHasDeltaLobe(material);
  if (d.fromBsdf) {
    d.bsdf = disneySampleDirection(material, wo, u0, u1, u2);
    return d;
  }
  d.bsdf = disneyNoSample();
  float3 wiLocal;
  float pdf;
  if (directions == PT_DIRECTIONS_UNIFORM) {
    // The hemisphere of wo, or the whole sphere if the material transmits.
    wiLocal = sampleUniformSphere(u1, u2);
    pdf = 0.25 * kInvPi;
    bool transmits = material.specTrans > 0.0 && material.metallic < 1.0;
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
    transmits = transmits || (material.diffuseTransmission > 0.0 && material.metallic < 1.0 &&
                              material.specTrans < 1.0);
#endif
    if (!transmits) {
      wiLocal.z = wo.z > 0.0 ? abs(wiLocal.z) : -abs(wiLocal.z);
      pdf = 0.5 * kInvPi;
    }
  } else {
    wiLocal = sampleCosineHemisphere(u1, u2);
    wiLocal.z = wo.z > 0.0 ? wiLocal.z : -wiLocal.z;
    pdf = cosineHemispherePdf(abs(wiLocal.z));
  }
  if (pdf > 0.0 && wiLocal.z != 0.0) {
    d.bsdf.wi = wiLocal;
    d.bsdf.pdf = pdf;
    d.bsdf.lobe = BSDF_LOBE_DIFFUSE;
  }
  return d;
}

// The scatter completed (`e`: the BSDF at d.bsdf.wi, if it needed one),
// with the throughput update and Russian roulette; false ends the path.
bool scatter(FrameConstants c, ScatterDirection d, BsdfEval e, Frame frame, float3 ng, float3 direction,
             float3 wo, uint depth, inout Rng rng, inout float3 throughput, inout float previousPdf,
             inout bool previousDelta, out float3 wiWorld) {
  uint flags = c.flags;
  wiWorld = direction;
  BsdfSample s = d.bsdf;
  if (scatterNeedsEval(d)) {
    if (d.fromBsdf) {
      s = disneyFinishSample(s, e);
    } else {
      s.weight = e.f * (abs(s.wi.z) / s.pdf);
    }
  }
  if (s.lobe == BSDF_LOBE_NONE || !(maxComponent(s.weight) > 0.0)) return false;
  wiWorld = normalize(frameToWorld(frame, s.wi));
  if (!shadingConsistent(ng, -direction, wiWorld, wo.z, s.wi.z) || dot(wiWorld, ng) == 0.0) return false;
  throughput *= s.weight;
  if (!isFiniteColor(throughput)) return false;
  previousPdf = s.pdf;
  previousDelta = s.isDelta;
  if ((flags & PT_FLAG_RUSSIAN_ROULETTE) != 0u && depth + 1u >= c.rouletteStartDepth) {
    float survive = min(maxComponent(throughput), 0.95);
    if (rngNext(rng) >= survive) return false;
    throughput /= survive;
  }
  return true;
}

// What the denoiser divides a vertex's illumination by: the base colour
// (diffuse, metal, glass tint) plus the dielectric specular layer's normal
// reflectance, so a black glossy surface still has something to filter.
float3 demodulationAlbedo(DisneyMaterial m) {
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
  // A leaf lit from behind shows its transmission colour, not its base.
  float3 diffuse = lerp(m.baseColor, m.diffuseTransmissionColor,
                        (1.0 - m.metallic) * (1.0 - m.specTrans) * m.diffuseTransmission);
#else
  float3 diffuse = m.baseColor;
#endif
  return diffuse + (1.0 - m.metallic) * (1.0 - m.specTrans) * dielectricSpecularF0(m);
}

// One path between two traced rays: only what the next vertex needs, since
// whatever is alive across a trace call is saved and restored around it.
//
// The guides (what the denoiser needs of the path) are those of its first
// non-delta vertex: a mirror or smooth glass passes them on to the surface
// seen through it ("primary surface replacement"), so a reflection is
// filtered with the reflected surface's albedo, normal and depth. While the
// chain of delta vertices is open, its throughput is the path's and its
// length and emission are kept here; the vertex that closes it hands its
// guides over (VertexGuides), and they go to the guide buffers at once. A
// chain that escapes the scene has no surface: zero albedo, normal and
// depth, as a camera ray that misses, and all it carries as its emission.
struct PathState {
  float3 radiance;
  float3 throughput;
  float previousPdf;
  bool previousDelta;  // the camera ray counts as a delta "bounce"
  uint depth;          // of the vertex the next radiance ray finds
  Rng rng;
  bool guidesOpen;       // every vertex so far was delta: the guides are still ahead
  float chainLength;     // unfolded length of the path so far, while open
  float3 chainEmission;  // radiance emitted along the chain, while open; then the guides' emission
  float cosForward;      // the camera ray's cosine to the view axis: path length to view depth
#if PT_HAS_EFFECT(PT_EFFECT_DISPERSION)
  float wavelength;  // nm, once a dispersive volume picked it (spectrum.hlsli); 0 before
#endif
};

PathState startPath(Rng rng, float cosForward) {
  PathState p;
  p.radiance = zero3();
  p.throughput = splat3(1.0);
  p.previousPdf = 0.0;
  p.previousDelta = true;
  p.depth = 0u;
  p.rng = rng;
  p.guidesOpen = true;
  p.chainLength = 0.0;
  p.chainEmission = zero3();
  p.cosForward = cosForward;
#if PT_HAS_EFFECT(PT_EFFECT_DISPERSION)
  p.wavelength = 0.0;
#endif
  return p;
}

// A radiance ray of the path: the one traced, or the bounce that waits while
// its vertex's shadow rays go first.
struct PathRay {
  float3 origin;
  float3 direction;
};

// A vertex's delta-light shadow ray (shadeVertex), waiting behind its area
// light's. Variants without delta lights keep only the flag (always 0).
struct DeltaLightShadow {
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
  ShadowRay ray;
#endif
  uint waiting;  // 1 while `ray` is still to be traced
};

DeltaLightShadow noDeltaLightShadow() {
  DeltaLightShadow v;
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
  v.ray = noShadowRay();
#endif
  v.waiting = 0u;
  return v;
}

// The material of a hit, its textures and vertex colour applied.
MaterialData hitMaterial(InstanceData instance, SurfaceHit hit) {
  MaterialData data = loadMaterial(instance.materialIndex);
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  data = applyMaterialTextures(data, hit.uv, hit.textureFootprint);
  data.baseColor *= hit.color.xyz;
#endif
  return data;
}

// The guides of the vertex that closed the path's delta chain, if it did.
struct VertexGuides {
  bool closed;
  float3 albedo;
  float3 normal;
};

VertexGuides closeGuides(inout PathState p, float3 albedo, float3 normal) {
  p.guidesOpen = false;
  VertexGuides g;
  g.closed = true;
  g.albedo = albedo;
  g.normal = normal;
  return g;
}

// The probability that next-event estimation samples the environment
// rather than an emissive triangle: 1 or 0 when there is only one of them,
// else half (a power estimate would need the scene's extent).
float environmentChoice(FrameConstants c) {
  if (!environmentPresent(c)) return 0.0;  // a constant 0 in variants without the environment
  return c.emissiveTriangleCount > 0u ? 0.5 : 1.0;
}

#if PT_HAS_EFFECT(PT_EFFECT_ENVIRONMENT)
// What a ray that left the scene along `direction` adds: the environment
// through the path's throughput, weighted against next-event estimation
// (which already counted it without MIS); a camera ray sees it only as a
// visible background.
float3 environmentSeen(FrameConstants c, PathState p, float3 direction) {
  uint flags = c.flags;
  bool useNee = (flags & PT_FLAG_NEE) != 0u;
  float weight = 1.0;
  if (p.depth == 0u) {
    weight = (c.sceneFlags & PT_SCENE_BACKGROUND) != 0u ? 1.0 : 0.0;
  } else if (!p.previousDelta && useNee) {
    weight = (flags & PT_FLAG_MIS) != 0u
                 ? misWeight(flags, p.previousPdf, environmentPdf(direction) * environmentChoice(c))
                 : 0.0;
  }
  if (weight <= 0.0) return zero3();
  return clampContribution(p.throughput * environmentRadiance(direction) * weight, c.radianceClamp);
}
#endif

// The vertex that `ray` found (its trace returned `record`): its emission
// and guides, its area-light sample (`shadow`, tMax 0 if none), one delta
// light's (`deltaShadow`) and its bounce.
// False: the path ends here (the ray missed, the path is at its maximum
// depth, the vertex is exactly grazing, or the scatter ended it); its
// shadow rays are traced all the same.
bool shadeVertex(FrameConstants c, HitRecord record, PathRay ray, inout PathState p, out VertexGuides guides,
                 out ShadowRay shadow, out DeltaLightShadow deltaShadow, out PathRay bounce) {
  shadow = noShadowRay();
  deltaShadow = noDeltaLightShadow();
  guides.closed = false;
  guides.albedo = zero3();
  guides.normal = zero3();
  bounce = ray;
  SurfaceHit hit = surfaceFromRecord(ray.origin, ray.direction, record);
  float3 direction = ray.direction;
  // Locals are not `const`: GLSL allows const only for constant expressions.
  uint flags = c.flags;
  bool useNee = (flags & PT_FLAG_NEE) != 0u;
  bool useMis = useNee && (flags & PT_FLAG_MIS) != 0u;
  float clampLimit = c.radianceClamp;
  if (hit.hitT < 0.0) {
#if PT_HAS_EFFECT(PT_EFFECT_ENVIRONMENT)
    if (environmentPresent(c)) p.radiance += environmentSeen(c, p, direction);
#endif
    return false;
  }
  float3 radianceBefore = p.radiance;
  InstanceData instance = loadInstanceData(hit.instanceIndex);
  MaterialData data = hitMaterial(instance, hit);
#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION) || PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
  // Beer-Lambert: a ray that meets a surface from behind travelled inside
  // it (closed, non-nested solids) through the medium the material holds.
  if (dot(direction, hit.geometricNormal) > 0.0)
    p.throughput *= exp(-data.absorption * hit.hitT);
#endif

#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  // KHR_materials_unlit: the base colour is what every ray sees, from both
  // sides; the surface reflects and transmits nothing, so the path ends
  // below, as at the maximum depth. Part of the surface-detail effect, and
  // left out of the other variants' code altogether: even this branch cost
  // 1.2 % of the Cornell box's frame with guides on the H100 when every
  // variant had it (docs/results.md).
  bool unlit = data.model == MATERIAL_MODEL_UNLIT;
  if (unlit) p.radiance += clampContribution(p.throughput * data.baseColor, clampLimit);
#endif

#if PT_HAS_EFFECT(PT_EFFECT_AREA_LIGHTS)
  // Emission: one-sided, from the front face (counter-clockwise; outside
  // of an implicit surface).
  float cosLight = -dot(direction, hit.geometricNormal);
  if (instance.firstEmissiveTriangle != PT_NO_EMISSION && cosLight > 0.0) {
    float3 emitted = p.throughput * data.emission;
    // An emitter NEE never samples has light pdf 0: BSDF sampling is the
    // only strategy that finds it, so its MIS weight is 1.
    bool neeSamples = instance.firstEmissiveTriangle != PT_EMISSION_NOT_SAMPLED;
    if (p.depth == 0u || p.previousDelta || !useNee || c.emissiveTriangleCount == 0u || !neeSamples) {
      p.radiance += clampContribution(emitted, clampLimit);
    } else if (useMis) {
      float lightPdf = areaToSolidAnglePdf(
          emissiveTrianglePdfArea(instance.firstEmissiveTriangle + hit.primitiveIndex), hit.hitT, cosLight) *
          (1.0 - environmentChoice(c));
      p.radiance += clampContribution(emitted * misWeight(flags, p.previousPdf, lightPdf), clampLimit);
    }
    // NEE without MIS: this light was already counted by a shadow ray.
  }
#endif
  DisneyMaterial material = unpackDisney(data);
#if PT_HAS_EFFECT(PT_EFFECT_DISPERSION)
  // Dispersion: the first dispersive volume the path meets picks the
  // wavelength it carries from then on, weighting the throughput by that
  // wavelength's colour over its pdf (expectation 1 per channel); every dispersive
  // surface after it refracts with the index at that wavelength. Thin glass
  // does not bend light, so it has none.
  if (data.dispersion > 0.0 && material.specTrans > 0.0 && !material.thin) {
    if (p.wavelength == 0.0) {
      WavelengthSample w = sampleWavelength(rngNext(p.rng));
      p.wavelength = w.lambda;
      p.throughput *= w.weight;
    }
    material.ior = dispersedIor(material.ior, data.dispersion, p.wavelength);
  }
#endif
  // This vertex's guides, should it close the chain.
  float3 guideAlbedo = zero3();
  float3 guideNormal = zero3();
  if (p.guidesOpen) {
    p.chainLength += hit.hitT;
    p.chainEmission += p.radiance - radianceBefore;
    guideAlbedo = p.throughput * demodulationAlbedo(material);
    // Facing the viewer, so both sides of a surface filter alike.
    float3 n = shadingNormalFor(hit, -direction);
    guideNormal = dot(n, direction) > 0.0 ? -n : n;
  }
  // The BSDF sees the shading frame; rays leave from the geometric surface,
  // and every direction must be on the same geometric side as the shading
  // frame says (shadingConsistent), so interpolated normals leak no light.
  float3 ng = hit.geometricNormal;
  Frame frame = shadingFrame(hit, shadingNormalFor(hit, -direction), material);
  float3 wo = frameToLocal(frame, -direction);
#if PT_COAT_NORMALS
  // glTF's coat has a normal of its own, bent for the viewer as the base's
  // is; Disney's coat lies on the base.
  if (material.ggxCoat)
    material.coatNormal = frameToLocal(frame, normalSeenFrom(hit.coatNormal, ng, -direction));
#endif
    // Unlit, at the maximum depth, or exactly grazing (no side to scatter into).
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  if (unlit || p.depth >= c.maxDepth || wo.z == 0.0 || dot(direction, ng) == 0.0) {
#else
  if (p.depth >= c.maxDepth || wo.z == 0.0 || dot(direction, ng) == 0.0) {
#endif
    if (p.guidesOpen) guides = closeGuides(p, guideAlbedo, guideNormal);
    return false;
  }

  // The light sample (an emissive triangle's point, or with probability
  // environmentChoice a direction of the environment) and the bounce's
  // direction are drawn first (in that order), then the BSDF is evaluated
  // for both at one call site.
  bool lightSampled = false;
  bool lightFromEnvironment = false;
  float3 lightWi = float3(0.0, 0.0, 1.0);  // world
  float3 lightWiLocal = float3(0.0, 0.0, 1.0);
  float3 lightRadiance = zero3();
  float lightPdf = 0.0;  // per solid angle, the choice of light included
  LightSample light;
  light.position = zero3();
  light.normal = float3(0.0, 0.0, 1.0);
  light.radiance = zero3();
  light.pdfArea = 0.0;
  bool environmentOn = environmentPresent(c);
  if (useNee && (c.emissiveTriangleCount > 0u || environmentOn)) {
    float u0 = rngNext(p.rng);
    float u1 = rngNext(p.rng);
    float u2 = rngNext(p.rng);
    float choice = environmentChoice(c);
#if PT_HAS_EFFECT(PT_EFFECT_ENVIRONMENT)
    if (u0 < choice) {
      EnvironmentSample es = sampleEnvironment(u1, u2);
      lightFromEnvironment = true;
      lightWi = es.direction;
      lightRadiance = es.radiance;
      lightPdf = es.pdf * choice;
      lightWiLocal = frameToLocal(frame, lightWi);
      lightSampled = lightPdf > 0.0 && lightWiLocal.z != 0.0 &&
                     shadingConsistent(ng, -direction, lightWi, wo.z, lightWiLocal.z);
    }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_AREA_LIGHTS)
#if PT_HAS_EFFECT(PT_EFFECT_ENVIRONMENT)
    else
#endif
    {
      // The rest of u0 picks the triangle (u0 itself without an environment).
      float triangleU = choice > 0.0 ? min((u0 - choice) / (1.0 - choice), 0.99999994) : u0;
      light = sampleEmissiveTriangles(c.emissiveTriangleCount, triangleU, u1, u2);
      float3 toLight = light.position - hit.position;
      float lightDistance = length(toLight);
      lightWi = toLight / max(lightDistance, 1e-30);
      float cosAtLight = -dot(light.normal, lightWi);
      lightWiLocal = frameToLocal(frame, lightWi);
      lightRadiance = light.radiance;
      lightPdf = areaToSolidAnglePdf(light.pdfArea, lightDistance, cosAtLight) * (1.0 - choice);
      lightSampled = cosAtLight > 0.0 && lightDistance > 0.0 && lightWiLocal.z != 0.0 &&
                     shadingConsistent(ng, -direction, lightWi, wo.z, lightWiLocal.z);
    }
#endif
  }
  ScatterDirection scatterDir = scatterDirection(c, material, wo, p.rng);
  BsdfEval lightEval;
  lightEval.f = zero3();
  lightEval.pdf = 0.0;
  BsdfEval scatterEval = lightEval;
  uint lastEval = scatterNeedsEval(scatterDir) ? 2u : 1u;
  for (uint k = lightSampled ? 0u : 1u; k < lastEval; k += 1u) {
    BsdfEval e = disneyEval(material, wo, k == 0u ? lightWiLocal : scatterDir.bsdf.wi);
    if (k == 0u) {
      lightEval = e;
    } else {
      scatterEval = e;
    }
  }
  if (lightSampled && maxComponent(lightEval.f) > 0.0) {
    float3 spawn = offsetRayOrigin(hit.position, dot(lightWi, ng) > 0.0 ? ng : -ng);
    float3 shadowDir = lightWi;
    float shadowLength = PT_DIRECTIONAL_SHADOW_LENGTH;
    if (!lightFromEnvironment) {
      // End the shadow ray just off the light's surface, on the lit side.
      float3 target = offsetRayOrigin(light.position, light.normal);
      shadowDir = target - spawn;
      shadowLength = length(shadowDir);
      shadowDir = shadowDir / max(shadowLength, 1e-30);
    }
    if (shadowLength > 0.0) {
      float weight = useMis ? misWeight(flags, lightPdf, lightEval.pdf) : 1.0;
      shadow.origin = spawn;
      shadow.direction = shadowDir;
      shadow.tMax = shadowLength;
      shadow.contribution = clampContribution(
          p.throughput * lightEval.f * lightRadiance * (abs(lightWiLocal.z) * weight / lightPdf), clampLimit);
    }
  }
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
  float3 throughputHere = p.throughput;  // the scatter below changes it
#endif

  float3 wiWorld;
  bool continues = scatter(c, scatterDir, scatterEval, frame, ng, direction, wo, p.depth, p.rng, p.throughput,
                           p.previousPdf, p.previousDelta, wiWorld);
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
  // One delta light per vertex, its shadow ray built while the surface is
  // still here (after the scatter, so a lone light's random numbers come in
  // the order they always did); with several, one is chosen in proportion
  // to what it could give here (chooseDeltaLight) and its contribution
  // divided by that probability: an unbiased estimate of their sum with one
  // shadow ray.
  if (useNee && c.pointLightCount > 0u) {
    float probability = 1.0;
    uint index = chooseDeltaLight(c.pointLightCount, hit.position, ng, p.rng, probability);
    if (index < c.pointLightCount) {
      PointLight light = loadPointLight(index);
      float2 u = float2(0.0, 0.0);
      if (isSoftSun(light)) {
        u.x = rngNext(p.rng);
        u.y = rngNext(p.rng);
      }
      deltaShadow.ray = pointLightShadowRay(light, u, material, frame, hit.position, ng, direction, wo,
                                            throughputHere / probability, clampLimit);
      deltaShadow.waiting = deltaShadow.ray.tMax > 0.0 ? 1u : 0u;
    }
  }
#endif
  bounce.origin = offsetRayOrigin(hit.position, dot(wiWorld, ng) > 0.0 ? ng : -ng);
  bounce.direction = wiWorld;
  if (p.guidesOpen && !(continues && p.previousDelta)) guides = closeGuides(p, guideAlbedo, guideNormal);
  p.depth += 1u;
  return continues;
}

// The vertex's delta-light shadow ray, if it has one still to trace
// (its signature the same in every variant, so that those without delta
// lights compile to what they did before the ray was built at the vertex).
bool nextDeltaLightShadowRay(FrameConstants c, inout DeltaLightShadow v, inout Rng rng, out ShadowRay shadow) {
  shadow = noShadowRay();
#if PT_HAS_EFFECT(PT_EFFECT_DELTA_LIGHTS)
  if (v.waiting == 0u) return false;
  shadow = v.ray;
  v.waiting = 0u;
  return true;
#endif
  return false;
}

// Sample `s` of this frame at launchPixel(): its random stream (numbered
// over the whole accumulation), its camera ray and its fresh path.
PathState startSample(FrameConstants c, uint s, out float3 origin, out float3 direction) {
  Rng rng = sampleRng(c, launchPixel(), c.firstSample + c.samplesBefore + s);
  float2 jitter = pixelSample(rng, s, c.samplesThisFrame);
  cameraRay(c, float2(launchPixel()) + jitter, rng, origin, direction);
  return startPath(rng, dot(direction, c.camera.forward));
}

// The sum of this frame's path samples (FrameConstants.samplesThisFrame of them,
// continuing the pixel's sample sequence) through launchPixel(), and the
// first two moments of their filtered luminance; with PT_OUTPUT_GUIDES,
// their guides go to the guide buffers as they close.
//
// One loop traces one ray per iteration, from one call site: a camera ray,
// a shadow ray or a bounce, whichever the path needs next, and a path that
// ends starts the pixel's next sample in the same iteration. Neighbouring
// threads of a warp trace together at that one call site whatever kind of
// ray each needs, where separate call sites for bounce and shadow rays each
// ran with only the threads that needed that kind (about half of them for
// shadow rays), and every trace call costs the whole warp. Each vertex first
// prepares its first shadow ray and samples its bounce, then traces them, so
// what is alive across the trace is the path state, one radiance ray (the
// one traced, or the bounce waiting behind a shadow ray) and the shadow
// ray's contribution, not the hit and its material; the pixel is read again
// when a sample starts rather than kept, and so are the frame constants
// after each trace. Random numbers are drawn in the same order as by a path
// traced alone.
float3 tracePixel(out float2 moments) {
  FrameConstants c = frameConstants();
  float3 sum = zero3();
  moments = float2(0.0, 0.0);
  uint s = 0u;
  PathRay ray;
  PathState p = startSample(c, s, ray.origin, ray.direction);
  ShadowRay shadow = noShadowRay();  // to trace next, before `ray`, if tMax > 0
  DeltaLightShadow deltaShadow = noDeltaLightShadow();  // traced after `shadow`
  bool continues = true;  // after the shadow rays, `ray` is traced
  for (;;) {
    bool tracingShadow = shadow.tMax > 0.0;
    HitRecord record = traceRay(tracingShadow ? shadow.origin : ray.origin,
                                tracingShadow ? shadow.direction : ray.direction,
                                tracingShadow ? shadow.tMax : 1e30, tracingShadow);
    c = frameConstants();
    uint before = c.samplesBefore;  // samples of the running means before this frame
    if (tracingShadow) {
      if (record.hitT < 0.0) p.radiance += shadow.contribution;
      shadow = noShadowRay();
    } else {
      VertexGuides guides;
      continues = shadeVertex(c, record, ray, p, guides, shadow, deltaShadow, ray);
#if PT_HAS_EFFECT(PT_OUTPUT_GUIDES)
      if (guides.closed)
        addGuideSample(launchPixel(), before + s, guides.albedo,
                       float4(guides.normal, p.chainLength * p.cosForward), p.chainEmission);
#endif
    }
    if (shadow.tMax > 0.0 || nextDeltaLightShadowRay(c, deltaShadow, p.rng, shadow)) continue;
    if (continues) continue;
    // The path ends: on to the pixel's next sample.
#if PT_HAS_EFFECT(PT_OUTPUT_GUIDES)
    // A chain that never closed escaped the scene through delta vertices:
    // what it carries (the environment, emitters passed on the way) is
    // emission seen by the camera, kept out of the filter like an
    // emitter's, and it has no surface.
    if (p.guidesOpen) addGuideSample(launchPixel(), before + s, zero3(), float4(0.0, 0.0, 0.0, 0.0), p.radiance);
#endif
    sum += p.radiance;
    float l = p.guidesOpen ? 0.0 : luminance(p.radiance - p.chainEmission);
    moments += float2(l, l * l);
    s += 1u;
    if (s >= c.samplesThisFrame) break;
    p = startSample(c, s, ray.origin, ray.direction);
    continues = true;
  }
  return sum;
}

#endif
