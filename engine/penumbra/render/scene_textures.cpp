#include "penumbra/render/scene_textures.h"

#include <algorithm>
#include <cmath>

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

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

rhi::TextureHandle createTexture(rhi::IDevice& device, rhi::ICommandList& commandList,
                                 uint32_t width, uint32_t height, bool srgb, const uint8_t* rgba8,
                                 const std::string& name) {
  rhi::TextureDesc desc;
  desc.width = width;
  desc.height = height;
  desc.format = srgb ? rhi::Format::RGBA8_SRGB : rhi::Format::RGBA8_UNORM;
  desc.usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::CopyDest;
  desc.debugName = name;
  auto texture = device.createTexture(desc);
  commandList.setTextureState(texture.get(), rhi::ResourceState::CopyDest);
  commandList.writeTexture(texture.get(), rgba8, size_t(width) * height * 4);
  commandList.setTextureState(texture.get(), rhi::ResourceState::ShaderResource);
  return texture;
}

}  // namespace

rhi::SamplerDesc samplerDesc(const scene::TextureSampler& s) {
  rhi::SamplerDesc d;
  d.magFilter = filter(s.magFilter);
  d.minFilter = filter(s.minFilter);
  d.addressU = addressMode(s.wrapU);
  d.addressV = addressMode(s.wrapV);
  return d;
}

gpu::TextureRefData packTextureRef(const scene::TextureRef& ref, uint32_t samplerIndex) {
  gpu::TextureRefData d{};
  d.column0 = {ref.transform0.x, ref.transform0.y};
  d.column1 = {ref.transform1.x, ref.transform1.y};
  d.column2 = {ref.transform2.x, ref.transform2.y};
  d.textureIndex = ref.texture;
  d.samplerIndex = samplerIndex;
  d.texCoordSet = ref.texCoord;
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
    out.refs.push_back(packTextureRef(ref, uint32_t(it - distinct.begin())));
  }
  if (distinct.empty()) distinct.emplace_back();
  for (const auto& s : distinct) {
    rhi::SamplerDesc desc = samplerDesc(s);
    desc.debugName = "scene sampler";
    out.samplers.push_back(device.createSampler(desc));
  }
  if (out.refs.empty()) out.refs.push_back(packTextureRef(scene::TextureRef{}, 0));
  return out;
}

}  // namespace penumbra::render
