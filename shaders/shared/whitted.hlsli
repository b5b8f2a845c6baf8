// Whitted ray tracing (Whitted 1980) with the Phong model: point, spot and
// directional lights with hard shadows, an ambient term, the environment
// seen by rays that escape (not as a light), perfect mirror reflection, and
// refraction weighted by the dielectric Fresnel term, with total internal
// reflection. Recursion is an explicit stack of pending rays (reflection and
// refraction branch), bounded by the max depth and a minimum weight.
//
// Needs the same entry-point accessors as path_tracer.hlsli.
#ifndef PENUMBRA_WHITTED_HLSLI
#define PENUMBRA_WHITTED_HLSLI
#include "disney_bsdf.hlsli"
#include "environment.hlsli"
#include "fresnel.hlsli"
#include "lights.hlsli"
#include "material.hlsli"
#include "ray_offset.hlsli"
#include "rng.hlsli"
#include "surface_hit.hlsli"

#define WHITTED_STACK_SIZE 16
static const float kWhittedMinWeight = 1e-3;

struct WhittedRay {
  float3 origin;
  float3 direction;
  float3 weight;
  uint depth;
};

WhittedRay whittedRay(float3 origin, float3 direction, float3 weight, uint depth) {
  WhittedRay r;
  r.origin = origin;
  r.direction = direction;
  r.weight = weight;
  r.depth = depth;
  return r;
}

// Phong shading of one light: kd (n.l) + ks (r.v)^n, times the incident light.
float3 phongTerm(PhongMaterial p, float3 n, float3 toLight, float3 toViewer, float3 incident) {
  float nDotL = dot(n, toLight);
  if (nDotL <= 0.0) return zero3();
  float3 r = 2.0 * nDotL * n - toLight;
  float spec = p.ks * pow(max(dot(r, toViewer), 0.0), p.exponent);
  return (p.kd * nDotL + splat3(spec)) * incident;
}

float3 traceWhitted(FrameConstants c, float3 origin, float3 direction) {
  WhittedRay stack[WHITTED_STACK_SIZE];
  int top = 0;
  stack[0] = whittedRay(origin, direction, splat3(1.0), 0u);
  top = 1;
  float3 radiance = zero3();
  while (top > 0) {
    top -= 1;
    WhittedRay ray = stack[top];
    SurfaceHit hit = traceClosest(ray.origin, ray.direction);
    if (hit.hitT < 0.0) {
#if PT_HAS_EFFECT(PT_EFFECT_ENVIRONMENT)
      // Mirror and refraction rays that escape see the environment; camera
      // rays only as a visible background.
      bool seen = ray.depth > 0u || (c.sceneFlags & PT_SCENE_BACKGROUND) != 0u;
      if (environmentPresent(c) && seen) radiance += ray.weight * environmentRadiance(ray.direction);
#endif
      continue;
    }
    InstanceData instance = loadInstanceData(hit.instanceIndex);
    MaterialData data = loadMaterial(instance.materialIndex);
    float occlusion = 1.0;
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
    data = applyMaterialTextures(data, hit.uv, hit.textureFootprint);
    occlusion = materialOcclusion(data, hit.uv, hit.textureFootprint);
    data.baseColor *= hit.color.xyz;  // COLOR_0
#endif
#if PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
    // KHR_materials_unlit (a surface-detail effect): the base colour as seen;
    // nothing reflects or refracts.
    if (data.model == MATERIAL_MODEL_UNLIT) {
      radiance += ray.weight * data.baseColor;
      continue;
    }
#endif
    PhongMaterial p = unpackPhong(data);

    bool frontFace = dot(ray.direction, hit.geometricNormal) < 0.0;
    if (instance.firstEmissiveTriangle != PT_NO_EMISSION && frontFace)
      radiance += ray.weight * data.emission;
    // Shade on the side the ray arrived from: Phong terms and the mirror and
    // refraction directions use the shading normal, rays leave from the
    // geometric surface (ng).
    float3 toViewer = -ray.direction;
    float3 ns = shadingNormalFor(hit, toViewer);
    float3 n = frontFace ? ns : -ns;
    float3 ng = frontFace ? hit.geometricNormal : -hit.geometricNormal;
    float cosIn = -dot(ray.direction, n);
    float3 spawnOut = offsetRayOrigin(hit.position, ng);

    float opaque = max(0.0, 1.0 - p.reflectivity - p.transparency);
    // The occlusion texture darkens only the ambient term: it stands for the
    // ambient light the surroundings block, which point lights do not need.
    float3 local = c.ambient * p.kd * occlusion;
    for (uint l = 0u; l < c.pointLightCount; l += 1u) {
      PointLight light = loadPointLight(l);
      float3 toLight;
      float distance;
      // A soft sun's centre: Whitted's shadows are hard.
      float3 incident = pointLightIncident(light, hit.position, float2(-1.0, 0.0), toLight, distance);
      // Lights behind the geometric surface stay dark whatever the shading normal says.
      if (maxComponent(incident) <= 0.0 || dot(n, toLight) <= 0.0 || dot(ng, toLight) <= 0.0) continue;
      float shadowLength;
      float3 toLightFromSpawn = pointLightShadowSegment(light, spawnOut, toLight, shadowLength);
      if (shadowLength > 0.0 && traceVisibility(spawnOut, toLightFromSpawn, shadowLength))
        local += phongTerm(p, n, toLight, toViewer, incident);
    }
    radiance += ray.weight * opaque * local;

    if (ray.depth >= c.maxDepth) continue;
    float3 mirror = normalize(ray.direction + 2.0 * abs(cosIn) * n);
    // A shading normal can bend the mirror ray into the surface; reflect about ng then.
    if (dot(mirror, ng) <= 0.0) mirror = normalize(reflect(ray.direction, ng));
#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
    if (p.transparency > 0.0) {
      // Entering through the front face goes from air into the material.
      float eta = frontFace ? p.ior : 1.0 / p.ior;
      float fr = fresnelDielectric(abs(cosIn), eta);
      float3 refracted;
      bool transmits = refractDirection(toViewer, n, eta, refracted);
      // Refraction about the shading normal must still enter the surface.
      if (transmits && dot(refracted, ng) >= 0.0) transmits = refractDirection(toViewer, ng, eta, refracted);
      if (!transmits) fr = 1.0;  // total internal reflection
      float3 reflectWeight = ray.weight * (p.transparency * fr);
      float3 refractWeight = ray.weight * (p.transparency * (1.0 - fr)) * p.kd;
      if (transmits && maxComponent(refractWeight) > kWhittedMinWeight && top < WHITTED_STACK_SIZE) {
        stack[top] = whittedRay(offsetRayOrigin(hit.position, -ng), normalize(refracted), refractWeight,
                                ray.depth + 1u);
        top += 1;
      }
      if (maxComponent(reflectWeight) > kWhittedMinWeight && top < WHITTED_STACK_SIZE) {
        stack[top] = whittedRay(spawnOut, mirror, reflectWeight, ray.depth + 1u);
        top += 1;
      }
    }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR)
    if (p.reflectivity > 0.0 && top < WHITTED_STACK_SIZE) {
      float3 w = ray.weight * p.reflectivity;
      if (maxComponent(w) > kWhittedMinWeight) {
        stack[top] = whittedRay(spawnOut, mirror, w, ray.depth + 1u);
        top += 1;
      }
    }
#endif
  }
  return radiance;
}

#endif
