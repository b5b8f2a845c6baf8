// The Disney principled BSDF (Burley 2012, "Physically Based Shading at
// Disney"; with the transmission extension of Burley 2015, "Extending the
// Disney BRDF to a BSDF with Integrated Subsurface Scattering").
//
// Everything here works in the local shading frame: +z is the geometric
// normal's front (outside) side, wo and wi point away from the surface. The
// reflection lobes are two-sided (mirrored to wo's side); the glass lobe uses
// the side of wo to tell entering (eta = ior) from leaving (eta = 1 / ior),
// except thin glass, which has air on both sides (eta = ior from either face).
//
// Lobes, weighted by metallic m, specTrans t, clearcoat c:
//   diffuse   (1-m)(1-t)   Burley diffuse with retro-reflection, blended towards a
//                          Hanrahan-Krueger-like flat term by `subsurface`; or
//                          Lambert for materials marked so (glTF, the Cornell box);
//             with diffuseTransmission d, a share d of it is Lambertian
//             transmission of diffuseTransmissionColor to the other side
//             (KHR_materials_diffuse_transmission), dimmed by the layers
//             above as the reflection is;
//   sheen     (1-m)(1-t)   sheen * lerp(1, tint, sheenTint) * sheenColor
//                          * SchlickWeight(cos theta_d); or, for the Lambert model
//                          (glTF's), KHR_materials_sheen's layer over diffuse,
//                          specular and glass alike (sheen.hlsli), which dims them
//                          by its albedo and is sampled as a lobe of its own;
//   specular  m + (1-m)(1-t)  anisotropic GGX reflection; Fresnel Schlick from baseColor
//                          (metal) or specular * min(0.08 * lerp(1, tint, specularTint)
//                          * specularColor, 1) (dielectric; specularColor is glTF's
//                          per-channel F0 colour, 1 for Disney materials), grazing
//                          reflectance faded below F0 = 0.02 (fresnelSchlickFaded);
//                          with iridescence i, a share i of either Fresnel is a thin
//                          film's over it (KHR_materials_iridescence, iridescence.hlsli);
//   glass     (1-m) t      rough dielectric reflection + refraction (Walter et al. 2007)
//                          with the exact dielectric Fresnel of `ior`; the thin option
//                          transmits without bending;
//   clearcoat 0.25 c       GTR1 (alpha lerp(0.1, 0.001, clearcoatGloss)), F0 = 0.04,
//                          separable Smith GGX masking with alpha 0.25; or, for
//                          the Lambert model (glTF's), KHR_materials_clearcoat's
//                          coat: weight c, GGX of alpha (1 - clearcoatGloss)^2 with
//                          height-correlated masking, F0 = 0.04, a mirror when smooth.
// Energy: Burley's layers are additive and a white material can reflect more
// than it receives; here the diffuse base is renormalised (Lagarde & de
// Rousiers 2014) and attenuated by the specular layer's Fresnel on the way in
// and out, per channel (a coloured F0 dims the base channel by channel), and
// everything below the clearcoat by the clearcoat's, so the directional
// albedo stays <= 1 (tested).
// GGX masking is Smith's height-correlated form; sampling uses visible normals.
// Lobes with max(alphaX, alphaY) <= kSpecularAlphaThreshold are perfectly
// specular (delta) and are sampled but never evaluated.
#ifndef PENUMBRA_DISNEY_BSDF_HLSLI
#define PENUMBRA_DISNEY_BSDF_HLSLI
#include "effects.h"
#include "fresnel.hlsli"
#include "iridescence.hlsli"
#include "microfacet.hlsli"
#include "sampling.hlsli"
#include "sheen.hlsli"

static const float kSpecularAlphaThreshold = 1e-3;
static const float kMinAlpha = 1e-4;

#define BSDF_LOBE_DIFFUSE 0u
#define BSDF_LOBE_SPECULAR 1u
#define BSDF_LOBE_GLASS 2u
#define BSDF_LOBE_CLEARCOAT 3u
#define BSDF_LOBE_NONE 4u
#define BSDF_LOBE_SHEEN 5u

struct DisneyMaterial {
  float3 baseColor;
  float metallic;
  float roughness;
  float anisotropic;
  float anisotropyStrength;  // glTF KHR_materials_anisotropy: alpha along the tangent grows towards 1
  float specular;
  float specularTint;
  float3 specularColor;  // multiplies the dielectric F0 per channel before its clamp to 1
  float specularF90;     // caps the dielectric layer's grazing reflectance (glTF's specularFactor)
  float sheen;
  float sheenTint;
  float3 sheenColor;  // multiplies the sheen per channel, in [0, 1]
  float sheenRoughness;  // glTF's sheen (charlieSheen) only
  float clearcoat;
  float clearcoatGloss;
  float specTrans;
  float ior;
  float subsurface;
  float diffuseTransmission;        // the diffuse lobe's share sent to the other side
  float3 diffuseTransmissionColor;  // its colour (the reflected share keeps baseColor)
  float iridescence;                // the share of the specular Fresnel that is the film's
  float iridescenceIor;             // the film's index
  float iridescenceThickness;       // nm; 0: no film
  bool thin;
  bool lambertDiffuse;
  bool ggxCoat;  // glTF's coat (full strength, GGX) instead of Disney's
  // glTF's coat's own normal (its normal map, or the vertex normal), unit, in
  // this frame; (0, 0, 1) lays the coat on the base. Read where
  // PT_COAT_NORMALS builds it.
  float3 coatNormal;
  bool charlieSheen;  // glTF's sheen layer instead of Disney's
};

struct BsdfEval {
  float3 f;   // BSDF value (no cosine)
  float pdf;  // solid-angle density with which disneySample picks wi (non-delta part)
};

struct BsdfSample {
  float3 wi;
  float3 weight;  // f * |cos| / pdf, or the delta lobe's throughput
  float pdf;      // 0 for delta samples
  bool isDelta;
  uint lobe;      // BSDF_LOBE_*; BSDF_LOBE_NONE when no direction was produced
};

struct LobeWeights {
  float diffuse;
  float specularLayer;  // weight of the specular reflection lobe (m + (1-m)(1-t))
  float glass;
  float clearcoat;
  float sheen;         // glTF's sheen layer: its colour's largest channel (0 for Disney's sheen)
  float2 sheenAlbedoO;  // the glTF sheen's albedo E(cos theta_o), its bound (sheenAlbedo); 0
                        // without it
  // Probabilities of choosing each lobe in disneySample.
  float pDiffuse;
  float pSheen;
  float pSpecular;
  float pGlass;
  float pClearcoat;
};

float clearcoatFresnelWeight(float cosTheta) { return 0.04 + 0.96 * pow(saturate(1.0 - cosTheta), 5.0); }

// Burley scaled his coat to a quarter so that `clearcoat` 1 looks right
// over his additive layers; glTF's coat reflects at full strength.
float coatWeight(DisneyMaterial m) {
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_COAT)
  if (m.ggxCoat) return m.clearcoat;
#endif
  return 0.25 * m.clearcoat;
}

#if PT_COAT_NORMALS
// The coat's normal in disneyEval's frame, flipped to wo's side `side`:
// seen from below, the coat's normal is -coatNormal.
float3 coatNormalOn(DisneyMaterial m, float side) {
  return side > 0.0 ? m.coatNormal : float3(-m.coatNormal.x, -m.coatNormal.y, m.coatNormal.z);
}
#endif

// The cosine of v (in disneyEval's flipped frame) to the coat's normal.
float coatCosine(DisneyMaterial m, float side, float3 v) {
#if PT_COAT_NORMALS
  return dot(v, coatNormalOn(m, side));
#else
  return v.z;
#endif
}

// Everything below the clearcoat passes it twice (cosines to the coat's normal).
float coatAttenuation(DisneyMaterial m, float cosO, float cosI) {
  float c = coatWeight(m);
  return (1.0 - c * clearcoatFresnelWeight(cosO)) * (1.0 - c * clearcoatFresnelWeight(cosI));
}

float3 tintColor(float3 baseColor) {
  float lum = luminance(baseColor);
  return lum > 0.0 ? baseColor / lum : splat3(1.0);
}

// Disney's `anisotropic` trades roughness between the two axes; glTF's
// anisotropy strength s only adds it along the tangent (alpha_t =
// lerp(alpha, 1, s^2), KHR_materials_anisotropy), so rough surfaces stay as
// they are. The two compose: glTF's stretch first, then Disney's aspect.
Ggx disneyGgx(DisneyMaterial m) {
  float alpha = m.roughness * m.roughness;
  float aspect = sqrt(1.0 - 0.9 * m.anisotropic);
  float alongTangent = lerp(alpha, 1.0, m.anisotropyStrength * m.anisotropyStrength);
  Ggx g;
  g.alphaX = max(kMinAlpha, alongTangent / aspect);
  g.alphaY = max(kMinAlpha, alpha * aspect);
  return g;
}

// (With a float tolerance: roughness = sqrt(1e-3) squares to 1.0000001e-3.)
bool isSpecularGgx(Ggx g) { return max(g.alphaX, g.alphaY) <= kSpecularAlphaThreshold * 1.0001; }

// Thin glass scatters with a roughness scaled by the ior (Burley 2015, eq. 11).
Ggx thinGlassGgx(DisneyMaterial m) {
  float scaled = saturate((0.65 * m.ior - 0.35) * m.roughness);
  DisneyMaterial s = m;
  s.roughness = scaled;
  return disneyGgx(s);
}

// The glass lobe's distribution: the thin-glass one or the surface's own `g`.
// (HLSL has no conditional operator on structs, so this is a function.)
Ggx glassGgx(DisneyMaterial m, Ggx g) {
  if (m.thin) return thinGlassGgx(m);
  return g;
}

// glTF's KHR_materials_specular is specular = specularFactor and
// specularColor = specularColorFactor * F0(ior) / 0.08: F0 = min(F0(ior) *
// colour, 1) * factor, as the extension defines it. The clamp keeps F0 <= 1,
// where a saturated tint (baseColor / luminance, up to 13.8) went past it.
// Without PT_EFFECT_SPECULAR_COLOR every F0 is grey (no tint, specularColor
// 1: unpackDisney), and one channel's arithmetic stands for the three.
float3 dielectricSpecularF0(DisneyMaterial m) {
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR_COLOR)
  float3 tinted = lerp(splat3(1.0), tintColor(m.baseColor), m.specularTint) * m.specularColor;
  return m.specular * min(0.08 * tinted, splat3(1.0));
#else
  return splat3(m.specular * 0.08);
#endif
}

#if PT_HAS_EFFECT(PT_EFFECT_IRIDESCENCE)
bool hasThinFilm(DisneyMaterial m) {
  return m.iridescence > 0.0 && m.iridescenceThickness > 0.0;
}

ThinFilm thinFilmOf(DisneyMaterial m, float cosTheta) {
  return thinFilmAt(m.iridescenceIor, m.iridescenceThickness, cosTheta);
}

// A layer's Fresnel `fresnel` (of normal reflectance f0, grazing f90) with
// the thin film over it, by the share m.iridescence; f90 fades the film out
// with the layer (a dielectric of specular 0 reflects nothing, film or not).
float3 withThinFilm(DisneyMaterial m, ThinFilm film, float3 fresnel, float3 f0, float f90) {
  return lerp(fresnel, f90 * thinFilmReflectance(film, f0), m.iridescence);
}
#endif

// Schlick's Fresnel from f0 at normal incidence to f90 at grazing.
float3 fresnelSchlickTo(float3 f0, float f90, float cosTheta) {
  return f0 + (splat3(f90) - f0) * schlickWeight(cosTheta);
}

// The grazing reflectance faded out below F0 = 0.02 (F90 = saturate(50 F0),
// as in Filament): `specular` = 0 then means no specular reflection at all,
// instead of a mirror at grazing angles, and F0 >= 0.02 (every real
// dielectric) keeps Schlick's F90 = 1.
float fadedF90(float3 f0) {
  return saturate(50.0 * maxComponent(f0));
}

float3 fresnelSchlickFaded(float3 f0, float cosTheta) {
  return fresnelSchlickTo(f0, fadedF90(f0), cosTheta);
}

// The dielectric layer's grazing reflectance: faded as above, and capped by
// specularF90 (glTF's specularFactor x the specular texture's alpha) in the
// variant that holds glTF's specular extension; 1 elsewhere.
float dielectricF90(DisneyMaterial m, float3 f0) {
  float f90 = fadedF90(f0);
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR_COLOR)
  f90 = min(f90, m.specularF90);
#endif
  return f90;
}

// The dielectric layer's Fresnel: Schlick's up to that F90; a thin film over
// the layer takes its share (withThinFilm).
float3 dielectricFresnel(DisneyMaterial m, float3 f0, float cosTheta) {
  float f90 = dielectricF90(m, f0);
  float3 fresnel = fresnelSchlickTo(f0, f90, cosTheta);
#if PT_HAS_EFFECT(PT_EFFECT_IRIDESCENCE)
  if (hasThinFilm(m)) fresnel = withThinFilm(m, thinFilmOf(m, cosTheta), fresnel, f0, f90);
#endif
  return fresnel;
}

// Fresnel of the specular reflection lobe: metal and dielectric layers mixed,
// already multiplied by their lobe weights. One film covers both.
float3 specularFresnel(DisneyMaterial m, float cosThetaD) {
  float metalF90 = fadedF90(m.baseColor);
  float3 metal = fresnelSchlickTo(m.baseColor, metalF90, cosThetaD);
  float3 f0 = dielectricSpecularF0(m);
  float f90 = dielectricF90(m, f0);
  float3 dielectric = fresnelSchlickTo(f0, f90, cosThetaD);
#if PT_HAS_EFFECT(PT_EFFECT_IRIDESCENCE)
  if (hasThinFilm(m)) {
    ThinFilm film = thinFilmOf(m, cosThetaD);
    metal = withThinFilm(m, film, metal, m.baseColor, metalF90);
    dielectric = withThinFilm(m, film, dielectric, f0, f90);
  }
#endif
  return m.metallic * metal + (1.0 - m.metallic) * (1.0 - m.specTrans) * dielectric;
}

float3 sheenColorOf(DisneyMaterial m) {
  // In this order, as Disney's sheen always multiplied it (bit for bit).
  return m.sheen * (lerp(splat3(1.0), tintColor(m.baseColor), m.sheenTint) * m.sheenColor);
}

// glTF's sheen colour, at most 1 per channel: the layer cannot reflect more
// than reaches it (Disney's sheenTint, which a scene file may give the
// `lambert` model, can push a channel of sheenColorOf to 13.8).
float3 gltfSheenColor(DisneyMaterial m) {
  return min(sheenColorOf(m), splat3(1.0));
}

LobeWeights disneyLobeWeights(DisneyMaterial m, float cosThetaO) {
  LobeWeights w;
  w.diffuse = (1.0 - m.metallic) * (1.0 - m.specTrans);
  w.specularLayer = m.metallic + w.diffuse;
  w.glass = (1.0 - m.metallic) * m.specTrans;
  w.clearcoat = coatWeight(m);
  w.sheen = 0.0;
  w.sheenAlbedoO = float2(0.0, 0.0);
  // Sampling estimates: each lobe's rough share of the reflected energy.
  float disneySheen = m.sheen * 0.25;
  float eSheen = 0.0;
  float below = 1.0;  // what glTF's sheen lets through to the lobes below it
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_SHEEN)
  if (m.charlieSheen) {
    w.sheen = maxComponent(gltfSheenColor(m));
    w.sheenAlbedoO = sheenAlbedo(cosThetaO, m.sheenRoughness);
    eSheen = w.sheen * min(1.0, w.sheenAlbedoO.x);
    below = 1.0 - eSheen;
    disneySheen = 0.0;
  }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
  float eDiffuse = w.diffuse *
                   lerp(luminance(m.baseColor) + disneySheen, luminance(m.diffuseTransmissionColor),
                        m.diffuseTransmission) *
                   below;
#else
  float eDiffuse = w.diffuse * (luminance(m.baseColor) + disneySheen) * below;
#endif
  float eSpecular = luminance(specularFresnel(m, cosThetaO)) * below;
  float eGlass = w.glass * below;
  float eClearcoat = w.clearcoat * (0.04 + 0.96 * schlickWeight(cosThetaO));
  float total = eDiffuse + eSheen + eSpecular + eGlass + eClearcoat;
  float inv = total > 0.0 ? 1.0 / total : 0.0;
  w.pDiffuse = eDiffuse * inv;
  w.pSheen = eSheen * inv;
  w.pSpecular = eSpecular * inv;
  w.pGlass = eGlass * inv;
  w.pClearcoat = eClearcoat * inv;
  return w;
}

// The glTF sheen's albedo at cos theta_i (0 without it).
float2 sheenAlbedoI(DisneyMaterial m, LobeWeights w, float cosI) {
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_SHEEN)
  if (w.sheen > 0.0) return sheenAlbedo(cosI, m.sheenRoughness);
#endif
  return float2(0.0, 0.0);
}

// The share of light that passes glTF's sheen layer to the lobes below it
// (1 without one), for wo (w) and a wi of sheen albedo albedoI.
float sheenLayerScaling(LobeWeights w, float2 albedoI) {
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_SHEEN)
  if (w.sheen > 0.0) return sheenAlbedoScaling(w.sheen, w.sheenAlbedoO, albedoI);
#endif
  return 1.0;
}

// Burley's diffuse with the energy renormalisation of Lagarde & de Rousiers
// 2014 ("Moving Frostbite to PBR", listing 1), so a white surface never
// reflects more than it receives; blended with the Hanrahan-Krueger-like flat
// term by `subsurface`, which is scaled the same way.
float3 diffuseTerm(DisneyMaterial m, float3 wo, float3 wi, float cosThetaD) {
  if (m.lambertDiffuse) return m.baseColor * kInvPi;
  float fo = schlickWeight(wo.z);
  float fi = schlickWeight(wi.z);
  float energyBias = 0.5 * m.roughness;
  float energyFactor = lerp(1.0, 1.0 / 1.51, m.roughness);
  float fd90 = energyBias + 2.0 * m.roughness * cosThetaD * cosThetaD;
  float burley = (1.0 + (fd90 - 1.0) * fo) * (1.0 + (fd90 - 1.0) * fi);
  float fss90 = cosThetaD * cosThetaD * m.roughness;
  float fss = lerp(1.0, fss90, fo) * lerp(1.0, fss90, fi);
  float flatTerm = 1.25 * (fss * (1.0 / (wo.z + wi.z) - 0.5) + 0.5);
  return m.baseColor * (kInvPi * energyFactor) * lerp(burley, flatTerm, m.subsurface);
}

// The share of light that passes a Fresnel-weighted layer on the way in and
// on the way out; scales the layers below it so energy is not created where
// Burley's model simply adds them. Reciprocal: symmetric in wo and wi.
float3 layerTransmission(float3 fresnelO, float3 fresnelI) {
  return (splat3(1.0) - fresnelO) * (splat3(1.0) - fresnelI);
}

// Attenuation of the diffuse base by the dielectric specular layer, per
// channel (what a coloured F0 reflects of a channel does not reach the base,
// so each channel's albedo stays <= 1), and of everything below the clearcoat
// by the clearcoat (`coat`: coatAttenuation).
float3 baseAttenuation(DisneyMaterial m, float cosO, float cosI, float coat) {
  float3 f0 = dielectricSpecularF0(m);
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR_COLOR) || PT_HAS_EFFECT(PT_EFFECT_IRIDESCENCE)
  float3 specO = dielectricFresnel(m, f0, cosO);
  float3 specI = dielectricFresnel(m, f0, cosI);
  return layerTransmission(specO, specI) * coat;
#else
  float specO = fresnelSchlickFaded(f0, cosO).x;
  float specI = fresnelSchlickFaded(f0, cosI).x;
  return splat3((1.0 - specO) * (1.0 - specI) * coat);
#endif
}

// Burley's sheen (Disney materials); glTF's is its own layer.
float3 sheenTerm(DisneyMaterial m, float cosThetaD) {
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_SHEEN)
  if (m.charlieSheen) return zero3();
#endif
  return sheenColorOf(m) * schlickWeight(cosThetaD);
}

float clearcoatAlpha(DisneyMaterial m) { return lerp(0.1, 0.001, m.clearcoatGloss); }

// glTF's coat: clearcoatGloss g holds 1 - clearcoatRoughness.
Ggx ggxCoatDistribution(DisneyMaterial m) {
  float r = 1.0 - m.clearcoatGloss;
  Ggx g;
  g.alphaX = max(kMinAlpha, r * r);
  g.alphaY = g.alphaX;
  return g;
}

float separableSmithGgx(float cosTheta, float alpha) {
  float a2 = alpha * alpha;
  float c2 = cosTheta * cosTheta;
  return 2.0 * cosTheta / (cosTheta + sqrt(a2 + c2 - a2 * c2));
}

// Refraction of wo about the normal wm (both on the same side), eta =
// transmitted / incident index; false on total internal reflection.
bool refractDirection(float3 wo, float3 wm, float eta, out float3 wt) {
  float cosI = dot(wo, wm);
  float sin2T = max(0.0, 1.0 - cosI * cosI) / (eta * eta);
  wt = float3(0.0, 0.0, 0.0);
  if (sin2T >= 1.0) return false;
  float cosT = sqrt(1.0 - sin2T);
  wt = -wo / eta + (cosI / eta - cosT) * wm;
  return true;
}

float3 reflectDirection(float3 wo, float3 wm) { return 2.0 * dot(wo, wm) * wm - wo; }

// Relative index of refraction (transmitted side over wo's side) for wo on
// `side` (+1 front, -1 back). A thin sheet has the same medium on both sides,
// so light meets an air-to-glass boundary from either face (no total internal
// reflection from the back).
float disneyEta(DisneyMaterial m, float side) { return (side > 0.0 || m.thin) ? m.ior : 1.0 / m.ior; }

#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
// disneyEval's glass lobe for wi on the other side of the surface (wi.z < 0).
void addGlassTransmission(DisneyMaterial m, LobeWeights w, Ggx g, float eta, float side, float3 wo,
                          float3 wi, float2 albedoI, inout BsdfEval r) {
  float3 wiAbs = float3(wi.x, wi.y, -wi.z);
  if (m.thin) {
    // Thin: the transmitted lobe is the reflected one mirrored through the sheet.
    Ggx gg = thinGlassGgx(m);
    if (!isSpecularGgx(gg)) {
      float3 wh = normalize(wo + wiAbs);
      float fr = fresnelDielectric(dot(wo, wh), eta);
      float dg = ggxD(gg, wh) * ggxG2(gg, wo, wiAbs) / (4.0 * wo.z * wiAbs.z);
      r.f +=
          m.baseColor * (w.glass * (1.0 - fr) * dg *
                         coatAttenuation(m, coatCosine(m, side, wo), coatCosine(m, side, wiAbs)) *
                         sheenLayerScaling(w, albedoI));
      r.pdf += w.pGlass * (1.0 - fr) * ggxVisibleNormalPdf(gg, wo, wh) / (4.0 * dot(wo, wh));
    }
  } else if (!isSpecularGgx(g)) {
    // Generalised half vector of refraction (Walter et al. 2007), on wo's side.
    float3 wh = normalize(wo + wi * eta);
    if (wh.z < 0.0) wh = -wh;
    float cosO = dot(wo, wh);
    float cosI = dot(wi, wh);
    if (cosO > 0.0 && cosI < 0.0) {
      float fr = fresnelDielectric(cosO, eta);
      float denom = cosI + cosO / eta;
      float denom2 = denom * denom;
      float dg = ggxD(g, wh) * ggxG2(g, wo, wi);
      // Radiance crossing into a denser medium is compressed by 1 / eta^2.
      float ft = (1.0 - fr) * dg * abs(cosI) * cosO / (wo.z * abs(wi.z) * denom2) / (eta * eta);
      r.f +=
          m.baseColor *
          (w.glass * ft * coatAttenuation(m, coatCosine(m, side, wo), coatCosine(m, side, wiAbs)) *
           sheenLayerScaling(w, albedoI));
      r.pdf += w.pGlass * (1.0 - fr) * ggxVisibleNormalPdf(g, wo, wh) * abs(cosI) / denom2;
    }
  }
}
#endif

#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
// disneyEval's diffuse transmission for wi on the other side (wi.z < 0):
// Lambertian, of diffuseTransmissionColor, through the layers above as the
// reflection passes them (at wi's cosines taken on wo's side).
void addDiffuseTransmission(DisneyMaterial m, LobeWeights w, float side, float3 wo, float3 wi,
                            float2 albedoI, inout BsdfEval r) {
  float3 wiUp = float3(wi.x, wi.y, -wi.z);
  float coat = coatAttenuation(m, coatCosine(m, side, wo), coatCosine(m, side, wiUp));
  r.f += (w.diffuse * m.diffuseTransmission * sheenLayerScaling(w, albedoI) *
          baseAttenuation(m, wo.z, wiUp.z, coat)) *
         (m.diffuseTransmissionColor * kInvPi);
  r.pdf += w.pDiffuse * m.diffuseTransmission * cosineHemispherePdf(wiUp.z);
}
#endif

// The part of the BSDF that can be evaluated (all non-delta lobes), and the
// density disneySample gives wi.
BsdfEval disneyEval(DisneyMaterial m, float3 woIn, float3 wiIn) {
  BsdfEval r;
  r.f = zero3();
  r.pdf = 0.0;
  float side = woIn.z < 0.0 ? -1.0 : 1.0;
  float3 wo = float3(woIn.x, woIn.y, woIn.z * side);
  float3 wi = float3(wiIn.x, wiIn.y, wiIn.z * side);
  if (wo.z <= 0.0 || wi.z == 0.0) return r;
  float eta = disneyEta(m, side);
  LobeWeights w = disneyLobeWeights(m, wo.z);
  Ggx g = disneyGgx(m);
  float2 albedoI = sheenAlbedoI(m, w, abs(wi.z));

  if (wi.z > 0.0) {
    float3 wh = normalize(wo + wi);
    float cosThetaD = dot(wi, wh);
    float coat = coatAttenuation(m, coatCosine(m, side, wo), coatCosine(m, side, wi));
    float sheenScale = sheenLayerScaling(w, albedoI);
    if (w.diffuse > 0.0) {
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
      // The transmitted share leaves the diffuse reflection and Disney's
      // sheen on it (sampled with it, by cosine, on wo's side).
      float reflected = 1.0 - m.diffuseTransmission;
      r.f += (w.diffuse * reflected * sheenScale * baseAttenuation(m, wo.z, wi.z, coat)) *
             (diffuseTerm(m, wo, wi, cosThetaD)
#else
      r.f += (w.diffuse * sheenScale * baseAttenuation(m, wo.z, wi.z, coat)) *
             (diffuseTerm(m, wo, wi, cosThetaD)
#endif
#if PT_HAS_EFFECT(PT_EFFECT_SHEEN)
              + sheenTerm(m, cosThetaD)
#endif
             );
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
      r.pdf += w.pDiffuse * reflected * cosineHemispherePdf(wi.z);
#else
      r.pdf += w.pDiffuse * cosineHemispherePdf(wi.z);
#endif
    }
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_SHEEN)
    if (w.sheen > 0.0) {
      r.f += gltfSheenColor(m) *
             (charlieSheen(m.sheenRoughness, wo, wi, w.sheenAlbedoO, albedoI) * coat);
      r.pdf += w.pSheen * cosineHemispherePdf(wi.z);
    }
#endif
    float vndf = ggxVisibleNormalPdf(g, wo, wh);
    // wo.wh >= 0 in exact arithmetic; rounding can make it 0 or negative when
    // wo and wi are nearly opposite at the horizon, where no lobe has density.
    float cosOH = dot(wo, wh);
    float jacobian = cosOH > 0.0 ? 1.0 / (4.0 * cosOH) : 0.0;
    // pSpecular is 0 exactly when the layer's F0 is 0, and then F is 0 at every
    // angle: skip the GGX work (Lambertian scenes pay nothing for it).
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR)
    if (w.pSpecular > 0.0 && !isSpecularGgx(g)) {
      float dg = ggxD(g, wh) * ggxG2(g, wo, wi) / (4.0 * wo.z * wi.z);
      r.f += specularFresnel(m, cosThetaD) * (dg * coat * sheenScale);
      r.pdf += w.pSpecular * vndf * jacobian;
    }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
    if (w.glass > 0.0) {
      Ggx gg = glassGgx(m, g);
      if (!isSpecularGgx(gg) && eta != 1.0) {
        float fr = fresnelDielectric(dot(wo, wh), eta);
        float dg = ggxD(gg, wh) * ggxG2(gg, wo, wi) / (4.0 * wo.z * wi.z);
        r.f += splat3(w.glass * fr * dg * coat * sheenScale);
        r.pdf += w.pGlass * fr * ggxVisibleNormalPdf(gg, wo, wh) * jacobian;
      }
    }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_CLEARCOAT)
    if (w.clearcoat > 0.0) {
      float fc = clearcoatFresnelWeight(cosThetaD);
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_COAT)
      if (m.ggxCoat) {
        Ggx gc = ggxCoatDistribution(m);
        if (!isSpecularGgx(gc)) {
#if PT_COAT_NORMALS
          // The lobe about the coat's normal. The integrator multiplies f by
          // the base frame's cosine wi.z, so f carries the coat's cosine over
          // it: the coat's own cosine cancels out of the denominator.
          Frame cf = frameFromNormal(coatNormalOn(m, side));
          float3 woC = frameToLocal(cf, wo);
          float3 wiC = frameToLocal(cf, wi);
          if (woC.z > 0.0 && wiC.z > 0.0) {
            float3 whC = frameToLocal(cf, wh);
            float dg = ggxD(gc, whC) * ggxG2(gc, woC, wiC) / (4.0 * woC.z * wi.z);
            r.f += splat3(w.clearcoat * fc * dg);
            r.pdf += w.pClearcoat * ggxVisibleNormalPdf(gc, woC, whC) * jacobian;
          }
#else
          float dg = ggxD(gc, wh) * ggxG2(gc, wo, wi) / (4.0 * wo.z * wi.z);
          r.f += splat3(w.clearcoat * fc * dg);
          r.pdf += w.pClearcoat * ggxVisibleNormalPdf(gc, wo, wh) * jacobian;
#endif
        }
      } else
#endif
      {
        float alpha = clearcoatAlpha(m);
        float d = gtr1D(alpha, wh.z);
        float gc = separableSmithGgx(wo.z, 0.25) * separableSmithGgx(wi.z, 0.25);
        r.f += splat3(w.clearcoat * d * fc * gc / (4.0 * wo.z * wi.z));
        r.pdf += w.pClearcoat * d * wh.z * jacobian;
      }
    }
#endif
  }
#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION) || PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
  else {
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
    if (w.diffuse > 0.0 && m.diffuseTransmission > 0.0)
      addDiffuseTransmission(m, w, side, wo, wi, albedoI, r);
#endif
#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
    if (w.glass > 0.0 && eta != 1.0) addGlassTransmission(m, w, g, eta, side, wo, wi, albedoI, r);
#endif
  }
#endif
  return r;
}

BsdfSample disneyNoSample() {
  BsdfSample s;
  s.wi = float3(0.0, 0.0, 1.0);
  s.weight = zero3();
  s.pdf = 0.0;
  s.isDelta = false;
  s.lobe = BSDF_LOBE_NONE;
  return s;
}

// The first half of disneySample: the lobe and direction that three
// uniform numbers choose. A delta lobe's sample is complete (isDelta, its
// weight); otherwise s.wi is set and disneyFinishSample completes it with
// disneyEval(m, woIn, s.wi). The split lets the path tracer evaluate this
// direction and its light sample's at one call site of disneyEval (every
// call site is a copy of it in the compiled kernel).
BsdfSample disneySampleDirection(DisneyMaterial m, float3 woIn, float u0, float u1, float u2) {
  BsdfSample s = disneyNoSample();
  float side = woIn.z < 0.0 ? -1.0 : 1.0;
  float3 wo = float3(woIn.x, woIn.y, woIn.z * side);
  if (wo.z <= 0.0) return s;
  float eta = disneyEta(m, side);
  LobeWeights w = disneyLobeWeights(m, wo.z);
  Ggx g = disneyGgx(m);
  float3 wi = float3(0.0, 0.0, 1.0);

  // The lobes' cumulative probabilities, in the order they are tried.
  float pToSpecular = w.pDiffuse + w.pSheen;
  float pToGlass = pToSpecular + w.pSpecular;
  if (u0 < w.pDiffuse) {
    s.lobe = BSDF_LOBE_DIFFUSE;
    wi = sampleCosineHemisphere(u1, u2);
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
    // Reuse u0: the transmitted share with probability diffuseTransmission.
    if (u0 < w.pDiffuse * m.diffuseTransmission) wi.z = -wi.z;
#endif
  }
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_SHEEN)
  else if (u0 < pToSpecular) {
    s.lobe = BSDF_LOBE_SHEEN;
    wi = sampleCosineHemisphere(u1, u2);
  }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR)
  else if (u0 < pToGlass) {
    s.lobe = BSDF_LOBE_SPECULAR;
    if (isSpecularGgx(g)) {
      s.wi = float3(-wo.x, -wo.y, wo.z * side);
      float3 mirror = float3(-wo.x, -wo.y, wo.z);
      s.weight = specularFresnel(m, wo.z) *
                 (coatAttenuation(m, coatCosine(m, side, wo), coatCosine(m, side, mirror)) *
                  sheenLayerScaling(w, w.sheenAlbedoO) / w.pSpecular);
      s.isDelta = true;
      return s;
    }
    wi = reflectDirection(wo, ggxSampleVisibleNormal(g, wo, u1, u2));
    if (wi.z <= 0.0) return disneyNoSample();
  }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_TRANSMISSION)
  else if (u0 < pToGlass + w.pGlass) {
    s.lobe = BSDF_LOBE_GLASS;
    // Reuse u0 to choose reflection or transmission.
    float uChoice = (u0 - w.pDiffuse - w.pSheen - w.pSpecular) / w.pGlass;
    Ggx gg = glassGgx(m, g);
    if (eta == 1.0) {
      // An index-matched boundary neither reflects nor bends light.
      s.wi = -woIn;
      s.weight = m.baseColor * (w.glass * sheenLayerScaling(w, w.sheenAlbedoO) / w.pGlass);
      s.isDelta = true;
      return s;
    }
    bool specular = isSpecularGgx(gg);
    float3 wm = specular ? float3(0.0, 0.0, 1.0) : ggxSampleVisibleNormal(gg, wo, u1, u2);
    float fr = fresnelDielectric(dot(wo, wm), eta);
    // A direction on the wrong side of the surface for the chosen event has no
    // density in disneyEval, so it is rejected rather than re-interpreted.
    if (uChoice < fr) {
      wi = reflectDirection(wo, wm);
      if (wi.z <= 0.0) return disneyNoSample();
    } else if (m.thin) {
      float3 r = reflectDirection(wo, wm);
      if (r.z <= 0.0) return disneyNoSample();
      wi = float3(r.x, r.y, -r.z);
    } else {
      if (!refractDirection(wo, wm, eta, wi) || wi.z >= 0.0) return disneyNoSample();
    }
    if (specular) {
      bool reflected = uChoice < fr;
      s.wi = float3(wi.x, wi.y, wi.z * side);
      // Chosen with probability pGlass * (fr or 1 - fr), which cancels the Fresnel factor.
      float scale = m.thin ? 1.0 : 1.0 / (eta * eta);
      // A transmitted direction meets the coat as its mirror image on wo's side.
      float3 wiUp = float3(wi.x, wi.y, abs(wi.z));
      float coat = coatAttenuation(m, coatCosine(m, side, wo), coatCosine(m, side, wiUp)) *
                   sheenLayerScaling(w, sheenAlbedoI(m, w, abs(wi.z)));
      s.weight = reflected ? splat3(w.glass * coat / w.pGlass)
                           : m.baseColor * (w.glass * scale * coat / w.pGlass);
      s.isDelta = true;
      return s;
    }
  }
#endif
#if PT_HAS_EFFECT(PT_EFFECT_CLEARCOAT)
  else if (w.pClearcoat > 0.0) {
    s.lobe = BSDF_LOBE_CLEARCOAT;
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_COAT)
    if (m.ggxCoat) {
      Ggx gc = ggxCoatDistribution(m);
#if PT_COAT_NORMALS
      // Sampled about the coat's normal, then taken back to this frame.
      Frame cf = frameFromNormal(coatNormalOn(m, side));
      float3 woC = frameToLocal(cf, wo);
      if (woC.z <= 0.0) return disneyNoSample();
      float3 wiC = isSpecularGgx(gc)
                       ? float3(-woC.x, -woC.y, woC.z)
                       : reflectDirection(woC, ggxSampleVisibleNormal(gc, woC, u1, u2));
      if (wiC.z <= 0.0) return disneyNoSample();
      wi = frameToWorld(cf, wiC);
      if (isSpecularGgx(gc)) {
        if (wi.z <= 0.0) return disneyNoSample();
        s.wi = float3(wi.x, wi.y, wi.z * side);
        s.weight = splat3(w.clearcoat * clearcoatFresnelWeight(woC.z) / w.pClearcoat);
        s.isDelta = true;
        return s;
      }
#else
      if (isSpecularGgx(gc)) {
        s.wi = float3(-wo.x, -wo.y, wo.z * side);
        s.weight = splat3(w.clearcoat * clearcoatFresnelWeight(wo.z) / w.pClearcoat);
        s.isDelta = true;
        return s;
      }
      wi = reflectDirection(wo, ggxSampleVisibleNormal(gc, wo, u1, u2));
#endif
    } else
#endif
    {
      float cosThetaM = gtr1SampleCosTheta(clearcoatAlpha(m), u1);
      float sinThetaM = sqrt(max(0.0, 1.0 - cosThetaM * cosThetaM));
      float phi = 2.0 * kPi * u2;
      wi = reflectDirection(wo, float3(sinThetaM * cos(phi), sinThetaM * sin(phi), cosThetaM));
    }
    if (wi.z <= 0.0) return disneyNoSample();
  }
#endif
  else {
    return s;
  }

  if (wi.z == 0.0) return disneyNoSample();
  s.wi = float3(wi.x, wi.y, wi.z * side);
  return s;
}

// A non-delta sample of disneySampleDirection completed with `e`, the
// BSDF's value and density at its direction.
BsdfSample disneyFinishSample(BsdfSample s, BsdfEval e) {
  if (e.pdf <= 0.0 || !(e.pdf < 1e30)) return disneyNoSample();
  s.pdf = e.pdf;
  s.weight = e.f * (abs(s.wi.z) / e.pdf);
  return s;
}

// Samples wi for wo with three uniform numbers.
BsdfSample disneySample(DisneyMaterial m, float3 woIn, float u0, float u1, float u2) {
  BsdfSample s = disneySampleDirection(m, woIn, u0, u1, u2);
  if (s.lobe == BSDF_LOBE_NONE || s.isDelta) return s;
  return disneyFinishSample(s, disneyEval(m, woIn, s.wi));
}

// Whether the material has a perfectly specular lobe that sampling can pick.
bool disneyHasDeltaLobe(DisneyMaterial m) {
  LobeWeights w = disneyLobeWeights(m, 1.0);
  Ggx g = disneyGgx(m);
  Ggx gg = glassGgx(m, g);
  bool coatMirror = false;
#if PT_HAS_EFFECT(PT_EFFECT_GLTF_COAT)
  coatMirror = w.pClearcoat > 0.0 && m.ggxCoat && isSpecularGgx(ggxCoatDistribution(m));
#endif
  return (w.pSpecular > 0.0 && isSpecularGgx(g)) ||
         (w.pGlass > 0.0 && (isSpecularGgx(gg) || m.ior == 1.0)) || coatMirror;
}

#endif
