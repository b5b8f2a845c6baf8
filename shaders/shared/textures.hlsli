// Material textures (glTF): where a texture is read and how each one changes
// the material. Needs the entry point's loadTextureRef(index) and
// sampleTextureLevel(texture, sampler, uv, level) (bindless arrays).
//
// Which mip level: rays have no screen-space derivatives, so a hit takes a
// ray cone's (Akenine-Moller et al., "Improved Shader and Texture Level of
// Detail Using Ray Cones", JCGT 2021), the camera's at that point
// (camera.hlsli, pixelCone): its width W there, over |cos| of the angle to
// the triangle's normal, is the footprint's length on the surface, and 0.5
// log2 of the triangle's texture-coordinate area over its world area turns
// that into texture-coordinate units. A hit's `footprint` holds log2 of that
// length for TEXCOORD_0 and TEXCOORD_1 (surface_from_record.hlsli); each
// texture adds its own lodOffset (log2 of its texels per coordinate unit),
// so the level is where one texel spans the footprint.
#ifndef PENUMBRA_TEXTURES_HLSLI
#define PENUMBRA_TEXTURES_HLSLI
#include "rng.hlsli"

// The footprint of a read without a cone (alpha tests, emission): level 0
// of every texture.
#define PT_FINEST_FOOTPRINT float2(-1.0e4, -1.0e4)

// The texture coordinates a reference reads: its set (TEXCOORD_0 in uv.xy,
// TEXCOORD_1 in uv.zw) through its KHR_texture_transform.
float2 textureCoordinates(TextureRefData ref, float4 uv) {
  float2 st = ref.texCoordSet == 1u ? uv.zw : uv.xy;
  return ref.column0 * st.x + ref.column1 * st.y + ref.column2;
}

float4 sampleTextureRef(uint refIndex, float4 uv, float2 footprint) {
  TextureRefData ref = loadTextureRef(refIndex);
  float level = max((ref.texCoordSet == 1u ? footprint.y : footprint.x) + ref.lodOffset, 0.0);
  return sampleTextureLevel(ref.textureIndex, ref.samplerIndex, textureCoordinates(ref, uv), level);
}

// The KHR_materials_* textures, as gltf_materials.cpp maps their factors
// (docs/materials.md): clearcoat by red; the coat's roughness r by green,
// where clearcoatGloss g stands for r = 1 - g (glTF's coat) or
// r^2 = lerp(0.1, 0.001, g) (Disney's); specTrans by
// the transmission's red; sheenColor per channel by the sheen colour
// texture, sheenRoughness by the sheen roughness texture's alpha; specular (glTF's specularFactor)
// and specularF90 by the specular texture's alpha, specularColor per channel by the specular colour
// texture; diffuseTransmission by its texture's alpha, diffuseTransmissionColor by its colour
// texture; iridescence by its texture's red, while the thickness texture's green picks the
// film's thickness between its minimum and maximum (iridescenceThickness.y holds the pick).
void applyExtensionTextures(inout MaterialData d, float4 uv, float2 footprint) {
  if (d.clearcoatTexture != PT_NO_TEXTURE)
    d.clearcoat *= sampleTextureRef(d.clearcoatTexture, uv, footprint).x;
  if (d.clearcoatRoughnessTexture != PT_NO_TEXTURE) {
    float scale = sampleTextureRef(d.clearcoatRoughnessTexture, uv, footprint).y;
    if ((d.flags & MATERIAL_FLAG_GGX_COAT) != 0u) {
      d.clearcoatGloss = 1.0 - (1.0 - d.clearcoatGloss) * scale;
    } else {
      float r = sqrt(lerp(0.1, 0.001, d.clearcoatGloss)) * scale;
      d.clearcoatGloss = saturate((0.1 - r * r) / 0.099);
    }
  }
  if (d.transmissionTexture != PT_NO_TEXTURE)
    d.specTrans *= sampleTextureRef(d.transmissionTexture, uv, footprint).x;
  if (d.sheenColorTexture != PT_NO_TEXTURE)
    d.sheenColor *= sampleTextureRef(d.sheenColorTexture, uv, footprint).xyz;
  if (d.sheenRoughnessTexture != PT_NO_TEXTURE)
    d.sheenRoughness *= sampleTextureRef(d.sheenRoughnessTexture, uv, footprint).w;
  if (d.specularTexture != PT_NO_TEXTURE) {
    float a = sampleTextureRef(d.specularTexture, uv, footprint).w;
    d.specular *= a;
#if PT_HAS_EFFECT(PT_EFFECT_SPECULAR_COLOR)
    d.specularF90 *= a;  // glTF: F90 = specularFactor x the texture's alpha
#endif
  }
  if (d.specularColorTexture != PT_NO_TEXTURE)
    d.specularColor *= sampleTextureRef(d.specularColorTexture, uv, footprint).xyz;
  if (d.anisotropyTexture != PT_NO_TEXTURE)
    d.anisotropyStrength =
        saturate(d.anisotropyStrength * sampleTextureRef(d.anisotropyTexture, uv, footprint).z);
#if PT_HAS_EFFECT(PT_EFFECT_DIFFUSE_TRANSMISSION)
  if (d.diffuseTransmissionTexture != PT_NO_TEXTURE)
    d.diffuseTransmission *= sampleTextureRef(d.diffuseTransmissionTexture, uv, footprint).w;
  if (d.diffuseTransmissionColorTexture != PT_NO_TEXTURE)
    d.diffuseTransmissionColor *=
        sampleTextureRef(d.diffuseTransmissionColorTexture, uv, footprint).xyz;
#endif
#if PT_HAS_EFFECT(PT_EFFECT_IRIDESCENCE)
  if (d.iridescenceTexture != PT_NO_TEXTURE)
    d.iridescence *= sampleTextureRef(d.iridescenceTexture, uv, footprint).x;
  if (d.iridescenceThicknessTexture != PT_NO_TEXTURE)
    d.iridescenceThickness.y =
        lerp(d.iridescenceThickness.x, d.iridescenceThickness.y,
             sampleTextureRef(d.iridescenceThicknessTexture, uv, footprint).y);
#endif
}

// The material at a surface point: each texture multiplies its factor
// (glTF 2.0 3.9.2): base colour rgb, metallic from blue and roughness from
// green, emission rgb. sRGB textures arrive decoded to linear by the sampler.
MaterialData applyMaterialTextures(MaterialData d, float4 uv, float2 footprint) {
  if (d.baseColorTexture != PT_NO_TEXTURE)
    d.baseColor *= sampleTextureRef(d.baseColorTexture, uv, footprint).xyz;
  if (d.metallicRoughnessTexture != PT_NO_TEXTURE) {
    float4 mr = sampleTextureRef(d.metallicRoughnessTexture, uv, footprint);
    d.metallic *= mr.z;
    d.roughness *= mr.y;
  }
  // Emission at level 0: next-event estimation samples emitters by their
  // level-0 texels (lights.hlsli), and MIS needs both strategies to see the
  // same emission.
  if (d.emissionTexture != PT_NO_TEXTURE)
    d.emission *= sampleTextureRef(d.emissionTexture, uv, PT_FINEST_FOOTPRINT).xyz;
  applyExtensionTextures(d, uv, footprint);
  return d;
}

// Base-colour alpha at a point, for alphaMode MASK and BLEND, times the
// vertex colour's alpha.
float materialAlpha(MaterialData d, float4 uv, float vertexAlpha) {
  float alpha = d.alpha * vertexAlpha;
  if (d.baseColorTexture != PT_NO_TEXTURE)
    alpha *= sampleTextureRef(d.baseColorTexture, uv, PT_FINEST_FOOTPRINT).w;
  return alpha;
}

// Whether the alpha any-hit shader keeps a candidate hit: MASK compares alpha
// with the cutoff; BLEND keeps it with probability alpha (`u` uniform in
// [0, 1), drawn per ray and primitive by alphaCoverageRandom), so averaged
// over samples the surface covers alpha of what lies behind it.
bool alphaKeepsHit(MaterialData d, float4 uv, float vertexAlpha, float u) {
  if (d.alphaMode == MATERIAL_ALPHA_MASK) return materialAlpha(d, uv, vertexAlpha) >= d.alphaCutoff;
  if (d.alphaMode == MATERIAL_ALPHA_BLEND) return u < materialAlpha(d, uv, vertexAlpha);
  return true;
}

// A uniform number for BLEND's coverage decision, the same whenever the same
// ray meets the same primitive (an any-hit shader may run twice for one
// candidate) and independent between samples: a hash of the pixel, the
// samples accumulated before this frame, the seed, the ray and the primitive.
float alphaCoverageRandom(uint2 pixel, uint samplesBefore, uint seed, float3 origin, float3 direction,
                          uint instance, uint primitive) {
  uint h = pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(samplesBefore + pcgHash(seed))));
  h = pcgHash(h ^ asuint(origin.x));
  h = pcgHash(h ^ asuint(origin.y));
  h = pcgHash(h ^ asuint(origin.z));
  h = pcgHash(h ^ asuint(direction.x));
  h = pcgHash(h ^ asuint(direction.y));
  h = pcgHash(h ^ asuint(direction.z));
  h = pcgHash(h ^ instance);
  h = pcgHash(h ^ primitive);
  return float(h >> 8u) * (1.0 / 16777216.0);
}

// The occlusion texture's factor (1 without): 1 + strength * (r - 1).
float materialOcclusion(MaterialData d, float4 uv, float2 footprint) {
  if (d.occlusionTexture == PT_NO_TEXTURE) return 1.0;
  return 1.0 + d.occlusionStrength * (sampleTextureRef(d.occlusionTexture, uv, footprint).x - 1.0);
}

// A tangent-space normal map applied to the world-space frame (n: unit vertex
// normal; t and b: tangent and bitangent, bitangent = cross(n, t) * w taken in
// object space so mirroring transforms keep the map's handedness). The map's
// xy are scaled by normalScale (glTF normalTexture.scale). Returns an
// unnormalised normal; a degenerate frame returns n. glTF's coat normal map
// (clearcoatNormalTexture) is read the same way.
float3 mapNormal(uint map, float scale, float4 uv, float2 footprint, float3 n, float3 t, float3 b) {
  if (map == PT_NO_TEXTURE) return n;
  float3 m = sampleTextureRef(map, uv, footprint).xyz * 2.0 - splat3(1.0);
  m.x *= scale;
  m.y *= scale;
  float3 mapped = t * m.x + b * m.y + n * m.z;
  return dot(t, t) > 0.0 && dot(b, b) > 0.0 ? mapped : n;
}

float3 applyNormalMap(MaterialData d, float4 uv, float2 footprint, float3 n, float3 t, float3 b) {
  return mapNormal(d.normalTexture, d.normalScale, uv, footprint, n, t, b);
}

// The tangent glTF anisotropy stretches the lobes along
// (KHR_materials_anisotropy): the direction texture's rg (in [-1, 1], the
// tangent-space x and y; (1, 0) without a texture) turned by the material's
// rotation, then taken into the unit frame (t, b), as the extension's TBN
// does: a node's non-uniform scale stretches t and b unequally, which would
// otherwise bend the angle. Unnormalised result; (t, b) with a zero axis
// leaves t. (An 8-bit texel is never exactly zero: 128 is 1/255.)
float3 anisotropyTangent(MaterialData d, float4 uv, float2 footprint, float3 t, float3 b) {
  float lt = dot(t, t);
  float lb = dot(b, b);
  if (!(lt > 0.0) || !(lb > 0.0)) return t;
  t *= rsqrt(lt);
  b *= rsqrt(lb);
  float2 direction = float2(1.0, 0.0);
  if (d.anisotropyTexture != PT_NO_TEXTURE) {
    float2 texel = sampleTextureRef(d.anisotropyTexture, uv, footprint).xy * 2.0 - float2(1.0, 1.0);
    if (dot(texel, texel) > 1e-12) direction = texel;
  }
  float2 r = d.anisotropyDirection;
  float2 turned = float2(r.x * direction.x - r.y * direction.y, r.y * direction.x + r.x * direction.y);
  return t * turned.x + b * turned.y;
}

#endif
