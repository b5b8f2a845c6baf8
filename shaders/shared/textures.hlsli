// Material textures (glTF): where a texture is read and how each one changes
// the material. Needs the entry point's loadTextureRef(index) and
// sampleTextureLod0(texture, sampler, uv) (bindless arrays, LOD 0: rays carry
// no screen-space derivatives and the scene's textures have no mipmaps).
#ifndef PENUMBRA_TEXTURES_HLSLI
#define PENUMBRA_TEXTURES_HLSLI

// The texture coordinates a reference reads: its set (TEXCOORD_0 in uv.xy,
// TEXCOORD_1 in uv.zw) through its KHR_texture_transform.
float2 textureCoordinates(TextureRefData ref, float4 uv) {
  float2 st = ref.ids.z == 1u ? uv.zw : uv.xy;
  return ref.transform.xy * st.x + ref.transform.zw * st.y + ref.offset.xy;
}

float4 sampleTextureRef(uint refIndex, float4 uv) {
  TextureRefData ref = loadTextureRef(refIndex);
  return sampleTextureLod0(ref.ids.x, ref.ids.y, textureCoordinates(ref, uv));
}

// The material at a surface point: each texture multiplies its factor
// (glTF 2.0 3.9.2): base colour rgb, metallic from blue and roughness from
// green, emission rgb. sRGB textures arrive decoded to linear by the sampler.
MaterialData applyMaterialTextures(MaterialData d, float4 uv) {
  if (d.textures.x != PT_NO_TEXTURE) d.baseColor.xyz *= sampleTextureRef(d.textures.x, uv).xyz;
  if (d.textures.y != PT_NO_TEXTURE) {
    float4 mr = sampleTextureRef(d.textures.y, uv);
    d.disney0.x *= mr.z;
    d.disney0.y *= mr.y;
  }
  if (d.textures.w != PT_NO_TEXTURE) d.emission.xyz *= sampleTextureRef(d.textures.w, uv).xyz;
  return d;
}

// Base-colour alpha at a point, for alphaMode MASK.
float materialAlpha(MaterialData d, float4 uv) {
  float alpha = d.textureParams.z;
  if (d.textures.x != PT_NO_TEXTURE) alpha *= sampleTextureRef(d.textures.x, uv).w;
  return alpha;
}

// The occlusion texture's factor (1 without): 1 + strength * (r - 1).
float materialOcclusion(MaterialData d, float4 uv) {
  if (d.textures2.x == PT_NO_TEXTURE) return 1.0;
  return 1.0 + d.textureParams.y * (sampleTextureRef(d.textures2.x, uv).x - 1.0);
}

// A tangent-space normal map applied to the world-space frame (n: unit vertex
// normal; t and b: tangent and bitangent, bitangent = cross(n, t) * w taken in
// object space so mirroring transforms keep the map's handedness). The map's
// xy are scaled by normalScale (glTF normalTexture.scale). Returns an
// unnormalised normal; a degenerate frame returns n.
float3 applyNormalMap(MaterialData d, float4 uv, float3 n, float3 t, float3 b) {
  if (d.textures.z == PT_NO_TEXTURE) return n;
  float3 m = sampleTextureRef(d.textures.z, uv).xyz * 2.0 - splat3(1.0);
  m.x *= d.textureParams.x;
  m.y *= d.textureParams.x;
  float3 mapped = t * m.x + b * m.y + n * m.z;
  return dot(t, t) > 0.0 && dot(b, b) > 0.0 ? mapped : n;
}

#endif
