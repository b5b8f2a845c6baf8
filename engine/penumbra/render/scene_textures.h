#pragma once
// A scene's textures on the GPU: one sampled texture with its mip chain per scene::Texture, the
// distinct samplers its texture references use, and the references packed
// for the shaders (PT_T_TEXTURES, PT_S_SAMPLERS, PT_T_TEXTURE_REFS).
#include <glm/glm.hpp>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

struct SceneTextures {
  // Never empty: a scene without textures binds one white texel and one
  // sampler, since the bindless arrays are declared by every pipeline.
  std::vector<rhi::TextureHandle> textures;
  std::vector<rhi::SamplerHandle> samplers;
  std::vector<gpu::TextureRefData> refs;  // parallel to Scene::textureRefs (one zero entry if none)
};

// Creates the textures and records their uploads into the open command list,
// leaving them in ShaderResource state.
SceneTextures uploadSceneTextures(rhi::IDevice& device, rhi::ICommandList& commandList,
                                  const scene::Scene& scene);

// The GPU form of a texture reference whose sampler is samplers[samplerIndex]
// and whose texture is width x height.
gpu::TextureRefData packTextureRef(const scene::TextureRef& ref, uint32_t samplerIndex,
                                   uint32_t width, uint32_t height);

// rhi::SamplerDesc for a glTF sampler.
rhi::SamplerDesc samplerDesc(const scene::TextureSampler& sampler);

// The mean linear colour of a texture (sRGB decoded when it is sRGB): an
// emitter's average radiance factor, for choosing lights by power.
glm::vec3 meanLinearColor(const scene::Texture& texture);

}  // namespace penumbra::render
