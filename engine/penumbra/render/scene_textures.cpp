#include "penumbra/render/scene_textures.h"

#include <algorithm>
#include <cmath>

#include "penumbra/render/texture_mips.h"

namespace penumbra::render {
namespace {

rhi::Filter filter(scene::TextureFilter f) {
  return f == scene::TextureFilter::Nearest ? rhi::Filter::Nearest : rhi::Filter::Linear;
}

rhi::AddressMode addressMode(scene::TextureWrap w) {
  switch (w) {
    case scene::TextureWrap::Repeat:
      return rhi::AddressMode::Repeat;
    case scene::TextureWrap::MirroredRepeat:
      return rhi::AddressMode::MirroredRepeat;
    case scene::TextureWrap::ClampToEdge:
      return rhi::AddressMode::ClampToEdge;
  }
  return rhi::AddressMode::Repeat;
}

rhi::MipFilter mipFilter(scene::MipFilter f) {
  switch (f) {
    case scene::MipFilter::None:
      return rhi::MipFilter::None;
    case scene::MipFilter::Nearest:
      return rhi::MipFilter::Nearest;
    case scene::MipFilter::Linear:
      return rhi::MipFilter::Linear;
  }
  return rhi::MipFilter::Linear;
}

// The texture with its whole mip chain (texture_mips.h).
rhi::TextureHandle createTexture(rhi::IDevice& device, rhi::ICommandList& commandList,
                                 uint32_t width, uint32_t height, bool srgb, const uint8_t* rgba8,
                                 const std::string& name) {
  rhi::TextureDesc desc;
  desc.width = width;
  desc.height = height;
  desc.format = srgb ? rhi::Format::RGBA8_SRGB : rhi::Format::RGBA8_UNORM;
  desc.usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::CopyDest;
  desc.mipLevels = rhi::mipLevelCount(width, height);
  desc.debugName = name;
  auto texture = device.createTexture(desc);
  const std::vector<uint8_t> chain = mipChainRgba8(rgba8, width, height, srgb);
  commandList.setTextureState(texture.get(), rhi::ResourceState::CopyDest);
  commandList.writeTexture(texture.get(), chain.data(), chain.size());
  commandList.setTextureState(texture.get(), rhi::ResourceState::ShaderResource);
  return texture;
}

}  // namespace

rhi::SamplerDesc samplerDesc(const scene::TextureSampler& s) {
  rhi::SamplerDesc d;
  d.magFilter = filter(s.magFilter);
  d.minFilter = filter(s.minFilter);
  d.mipFilter = mipFilter(s.mipFilter);
  d.addressU = addressMode(s.wrapU);
  d.addressV = addressMode(s.wrapV);
  return d;
}

gpu::TextureRefData packTextureRef(const scene::TextureRef& ref, uint32_t samplerIndex,
                                   uint32_t width, uint32_t height) {
  gpu::TextureRefData d{};
  d.column0 = {ref.transform0.x, ref.transform0.y};
  d.column1 = {ref.transform1.x, ref.transform1.y};
  d.column2 = {ref.transform2.x, ref.transform2.y};
  d.textureIndex = ref.texture;
  d.samplerIndex = samplerIndex;
  d.texCoordSet = ref.texCoord;
  // A transform that collapses the coordinates (det 0) would ask for an
  // infinite level; 1e-12 of the area is 20 levels down, past any chain.
  const float areaScale =
      std::abs(ref.transform0.x * ref.transform1.y - ref.transform0.y * ref.transform1.x);
  d.lodOffset = 0.5f * std::log2(float(width) * float(height) * std::max(areaScale, 1e-12f));
  return d;
}

glm::vec3 meanLinearColor(const scene::Texture& texture) {
  glm::dvec3 sum(0.0);
  const size_t texels = size_t(texture.width) * texture.height;
  for (size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = texture.rgba8[i * 4 + size_t(c)] / 255.0f;
      sum[c] += texture.srgb ? srgbToLinear(v) : v;
    }
  return texels > 0 ? glm::vec3(sum / double(texels)) : glm::vec3(0.0f);
}

SceneTextures uploadSceneTextures(rhi::IDevice& device, rhi::ICommandList& commandList,
                                  const scene::Scene& scene) {
  SceneTextures out;
  for (const auto& t : scene.textures)
    out.textures.push_back(createTexture(device, commandList, t.width, t.height, t.srgb,
                                         t.rgba8.data(), "texture " + t.name));
  if (out.textures.empty()) {
    const uint8_t white[4] = {255, 255, 255, 255};
    out.textures.push_back(createTexture(device, commandList, 1, 1, false, white, "no texture"));
  }
  std::vector<scene::TextureSampler> distinct;
  for (const auto& ref : scene.textureRefs) {
    auto it = std::find(distinct.begin(), distinct.end(), ref.sampler);
    if (it == distinct.end()) it = distinct.insert(distinct.end(), ref.sampler);
    const scene::Texture& t = scene.textures.at(ref.texture);
    out.refs.push_back(packTextureRef(ref, uint32_t(it - distinct.begin()), t.width, t.height));
  }
  if (distinct.empty()) distinct.emplace_back();
  for (const auto& s : distinct) {
    rhi::SamplerDesc desc = samplerDesc(s);
    desc.debugName = "scene sampler";
    out.samplers.push_back(device.createSampler(desc));
  }
  if (out.refs.empty()) out.refs.push_back(packTextureRef(scene::TextureRef{}, 0, 1, 1));
  return out;
}

}  // namespace penumbra::render
