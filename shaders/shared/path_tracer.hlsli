// Unidirectional path tracing (Kajiya 1986) for Lambertian surfaces with
// emissive triangles: cosine-weighted BSDF sampling, next-event estimation,
// multiple importance sampling with the power heuristic (Veach 1997), and
// Russian roulette.
//
// The entry points define, before including this file:
//   SurfaceHit traceClosest(float3 origin, float3 direction);
//   bool traceVisibility(float3 origin, float3 direction, float tMax);
//   InstanceData loadInstanceData(uint index);
//   MaterialData loadMaterial(uint index);
//   EmissiveTriangle loadEmissiveTriangle(uint index);
#ifndef PENUMBRA_PATH_TRACER_HLSLI
#define PENUMBRA_PATH_TRACER_HLSLI
#include "lights.hlsli"
#include "ray_offset.hlsli"
#include "rng.hlsli"
#include "sampling.hlsli"
#include "surface_hit.hlsli"

// Radiance arriving along (origin, direction).
float3 tracePath(FrameConstants c, float3 origin, float3 direction, inout Rng rng) {
  // Locals are not `const`: GLSL allows const only for constant expressions.
  uint flags = c.sampling.w;
  bool useNee = (flags & PT_FLAG_NEE) != 0u && c.lights.x > 0u;
  bool useMis = useNee && (flags & PT_FLAG_MIS) != 0u;
  bool useRoulette = (flags & PT_FLAG_RUSSIAN_ROULETTE) != 0u;
  uint maxDepth = c.sampling.y;

  float3 radiance = zero3();
  float3 throughput = splat3(1.0);
  float previousBsdfPdf = 0.0;

  for (uint depth = 0u;; depth += 1u) {
    SurfaceHit hit = traceClosest(origin, direction);
    if (hit.hitT < 0.0) break;  // no environment light yet
    InstanceData instance = loadInstanceData(hit.instanceIndex);
    MaterialData material = loadMaterial(instance.materialIndex);

    // Emission: one-sided, from the counter-clockwise face.
    float cosLight = -dot(direction, hit.geometricNormal);
    if (instance.firstEmissiveTriangle != PT_NO_EMISSION && cosLight > 0.0) {
      float3 emitted = material.emission.xyz;
      if (depth == 0u || !useNee) {
        radiance += throughput * emitted;
      } else if (useMis) {
        float lightPdf = areaToSolidAnglePdf(
            emissiveTrianglePdfArea(instance.firstEmissiveTriangle + hit.primitiveIndex), hit.hitT,
            cosLight);
        radiance += throughput * emitted * powerHeuristic(previousBsdfPdf, lightPdf);
      }
      // NEE without MIS: this light was already counted by the shadow ray.
    }
    if (depth >= maxDepth) break;

    // Surfaces are two-sided: shade on the side the ray came from.
    float3 n = cosLight > 0.0 ? hit.geometricNormal : -hit.geometricNormal;
    float3 albedo = material.albedo.xyz;
    if (maxComponent(albedo) <= 0.0) break;
    float3 spawn = offsetRayOrigin(hit.position, n);

    if (useNee) {
      float u0 = rngNext(rng);
      float u1 = rngNext(rng);
      float u2 = rngNext(rng);
      LightSample light = sampleEmissiveTriangles(c.lights.x, u0, u1, u2);
      float3 toLight = light.position - hit.position;
      float distance = length(toLight);
      float3 wi = toLight / distance;
      float cosSurface = dot(n, wi);
      float cosAtLight = -dot(light.normal, wi);
      if (cosSurface > 0.0 && cosAtLight > 0.0 && distance > 0.0) {
        // End the shadow ray just off the light's surface, on the lit side.
        float3 target = offsetRayOrigin(light.position, light.normal);
        float3 shadowDir = target - spawn;
        float shadowLength = length(shadowDir);
        if (traceVisibility(spawn, shadowDir / shadowLength, shadowLength)) {
          float lightPdf = areaToSolidAnglePdf(light.pdfArea, distance, cosAtLight);
          float weight = useMis ? powerHeuristic(lightPdf, cosineHemispherePdf(cosSurface)) : 1.0;
          // Lambert: f = albedo / pi.
          radiance += throughput * albedo * kInvPi * light.radiance * (cosSurface * weight / lightPdf);
        }
      }
    }

    // BSDF sampling: cosine-weighted, so f * cos / pdf = albedo.
    float3 local = sampleCosineHemisphere(rngNext(rng), rngNext(rng));
    float3 wi = normalize(frameToWorld(frameFromNormal(n), local));
    previousBsdfPdf = cosineHemispherePdf(local.z);
    if (previousBsdfPdf <= 0.0) break;
    throughput *= albedo;

    if (useRoulette && depth + 1u >= c.sampling.z) {
      float survive = min(maxComponent(throughput), 0.95);
      if (rngNext(rng) >= survive) break;
      throughput /= survive;
    }
    origin = spawn;
    direction = wi;
  }
  return radiance;
}

#endif
