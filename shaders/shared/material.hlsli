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
  p.kd = d.baseColor;
  p.ks = d.ks;
  p.exponent = d.phongExponent;
  p.reflectivity = d.reflectivity;
  p.transparency = d.transparency;
  p.ior = d.ior;
  return p;
}

// Disney parameters; a Phong material (Whitted scenes rendered by the path
// tracer) maps onto the closest Disney material: kd -> baseColor, mirror
// reflectivity -> metallic with roughness from the Phong exponent
// (alpha = sqrt(2 / (n + 2))), transparency -> specTrans.
DisneyMaterial unpackDisney(MaterialData d) {
  DisneyMaterial m;
  m.baseColor = d.baseColor;
  m.metallic = d.metallic;
  m.roughness = d.roughness;
  m.anisotropic = d.anisotropic;
  m.anisotropyStrength = d.anisotropyStrength;
  m.specular = d.specular;
  m.specularTint = d.specularTint;
  m.specularColor = d.specularColor;
  m.specularF90 = d.specularF90;
  m.sheen = d.sheen;
  m.sheenTint = d.sheenTint;
  m.sheenColor = d.sheenColor;
  m.sheenRoughness = d.sheenRoughness;
  m.clearcoat = d.clearcoat;
  m.clearcoatGloss = d.clearcoatGloss;
  m.specTrans = d.specTrans;
  m.ior = d.ior;
  m.subsurface = d.subsurface;
  m.diffuseTransmission = d.diffuseTransmission;
  m.diffuseTransmissionColor = d.diffuseTransmissionColor;
  m.iridescence = d.iridescence;
  m.iridescenceIor = d.iridescenceIor;
  m.iridescenceThickness =
      d.iridescenceThickness.y;  // the texture's pick (textures.hlsli), else the maximum
  m.thin = (d.flags & MATERIAL_FLAG_THIN) != 0u;
  m.lambertDiffuse = (d.flags & MATERIAL_FLAG_LAMBERT_DIFFUSE) != 0u;
  m.ggxCoat = (d.flags & MATERIAL_FLAG_GGX_COAT) != 0u;
  m.charlieSheen = (d.flags & MATERIAL_FLAG_CHARLIE_SHEEN) != 0u;
  m.coatNormal = float3(0.0, 0.0, 1.0);  // the path tracer sets glTF's in its shading frame
  if (d.model == MATERIAL_MODEL_PHONG) {
    PhongMaterial p = unpackPhong(d);
    m.metallic = p.reflectivity;
    m.baseColor = p.reflectivity > 0.0 ? lerp(p.kd, splat3(1.0), p.reflectivity) : p.kd;
    m.roughness = p.reflectivity > 0.0 ? 0.0 : sqrt(sqrt(2.0 / (p.exponent + 2.0)));
    m.specTrans = p.transparency;
    m.specular = 0.5 * p.ks;
    m.specularColor = splat3(1.0);
    m.specularF90 = 1.0;
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
#if !PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
  m.diffuseTransmission = 0.0;
#endif
#if !PT_HAS_EFFECT(PT_EFFECT_IRIDESCENCE)
  m.iridescence = 0.0;
#endif
#if !PT_HAS_EFFECT(PT_EFFECT_TEXTURES)
  m.anisotropyStrength = 0.0;
#endif
#if !PT_HAS_EFFECT(PT_EFFECT_SPECULAR_COLOR)
  m.specularTint = 0.0;
  m.specularColor = splat3(1.0);
  m.specularF90 = 1.0;
#endif
  return m;
}

#endif
