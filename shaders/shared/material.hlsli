// Unpacking MaterialData into the parameter structs of the shading models.
#ifndef PENUMBRA_MATERIAL_HLSLI
#define PENUMBRA_MATERIAL_HLSLI
#include "disney_bsdf.hlsli"

struct PhongMaterial {
  float3 kd;
  float ks;
  float exponent;
  float reflectivity;
  float transparency;
  float ior;
};

PhongMaterial unpackPhong(MaterialData d) {
  PhongMaterial p;
  p.kd = d.baseColor.xyz;
  p.ks = d.phong.x;
  p.exponent = d.phong.y;
  p.reflectivity = d.phong.z;
  p.transparency = d.phong.w;
  p.ior = d.disney2.z;
  return p;
}

// Disney parameters; a Phong material (Whitted scenes rendered by the path
// tracer) maps onto the closest Disney material: kd -> baseColor, mirror
// reflectivity -> metallic with roughness from the Phong exponent
// (alpha = sqrt(2 / (n + 2))), transparency -> specTrans.
DisneyMaterial unpackDisney(MaterialData d) {
  DisneyMaterial m;
  m.baseColor = d.baseColor.xyz;
  m.metallic = d.disney0.x;
  m.roughness = d.disney0.y;
  m.anisotropic = d.disney0.z;
  m.specular = d.disney0.w;
  m.specularTint = d.disney1.x;
  m.sheen = d.disney1.y;
  m.sheenTint = d.disney1.z;
  m.clearcoat = d.disney1.w;
  m.clearcoatGloss = d.disney2.x;
  m.specTrans = d.disney2.y;
  m.ior = d.disney2.z;
  m.subsurface = d.disney2.w;
  m.thin = (d.flags.y & MATERIAL_FLAG_THIN) != 0u;
  m.lambertDiffuse = (d.flags.y & MATERIAL_FLAG_LAMBERT_DIFFUSE) != 0u;
  if (d.flags.x == MATERIAL_MODEL_PHONG) {
    PhongMaterial p = unpackPhong(d);
    m.metallic = p.reflectivity;
    m.baseColor = p.reflectivity > 0.0 ? lerp(p.kd, splat3(1.0), p.reflectivity) : p.kd;
    m.roughness = p.reflectivity > 0.0 ? 0.0 : sqrt(sqrt(2.0 / (p.exponent + 2.0)));
    m.specTrans = p.transparency;
    m.specular = 0.5 * p.ks;
    m.lambertDiffuse = true;
  }
  // A variant without an effect is only used for scenes whose materials all
  // have these parameters at 0; saying so lets the compiler fold the lobes away.
#if !PT_HAS_EFFECT(PT_EFFECT_SPECULAR)
  m.metallic = 0.0;
  m.specular = 0.0;
#endif
#if !PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
  m.specTrans = 0.0;
#endif
#if !PT_HAS_EFFECT(PT_EFFECT_CLEARCOAT)
  m.clearcoat = 0.0;
#endif
#if !PT_HAS_EFFECT(PT_EFFECT_SHEEN)
  m.sheen = 0.0;
#endif
  return m;
}

#endif
