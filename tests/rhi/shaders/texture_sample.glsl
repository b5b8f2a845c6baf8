// Bindless texture sampling shared by texture_sample.comp and
// texture_sample.rgen (tests/rhi/test_textures.cpp): query i names a texture,
// a sampler and a uv; neighbouring invocations name different ones, so the
// indices are non-uniform within a subgroup.
#extension GL_EXT_nonuniform_qualifier : require
#include "bindings.hlsli"

struct TextureQuery {
  vec2 uv;
  uint textureIndex;
  uint samplerIndex;
};

layout(push_constant, std430) uniform Push { uint gCount; };
layout(set = 0, binding = PENUMBRA_T(0), std430) readonly buffer Queries { TextureQuery gQueries[]; };
layout(set = 0, binding = PENUMBRA_U(0), std430) writeonly buffer Results { vec4 gResults[]; };
layout(set = 0, binding = PENUMBRA_T(12)) uniform texture2D gTextures[];
layout(set = 0, binding = PENUMBRA_S(0)) uniform sampler gSamplers[];

void sampleQuery(uint i) {
  if (i >= gCount) return;
  TextureQuery q = gQueries[i];
  gResults[i] = textureLod(sampler2D(gTextures[nonuniformEXT(q.textureIndex)], gSamplers[nonuniformEXT(q.samplerIndex)]),
                           q.uv, 0.0);
}
