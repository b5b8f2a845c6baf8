#include "penumbra/rhi/rhi.h"

#include <algorithm>

namespace penumbra::rhi {

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
  uint32_t levels = 1;
  for (uint32_t size = std::max(width, height); size > 1; size >>= 1) ++levels;
  return levels;
}

uint64_t textureByteSize(const TextureDesc& desc) {
  uint64_t bytes = 0;
  for (uint32_t level = 0; level < desc.mipLevels; ++level)
    bytes += uint64_t(std::max(1u, desc.width >> level)) * std::max(1u, desc.height >> level) *
             formatByteSize(desc.format);
  return bytes;
}

uint32_t formatByteSize(Format format) {
  switch (format) {
    case Format::RGBA8_UNORM:
      return 4;
    case Format::RGBA8_SRGB:
      return 4;
    case Format::BGRA8_UNORM:
      return 4;
    case Format::RGBA32_FLOAT:
      return 16;
    case Format::RGB32_FLOAT:
      return 12;
    case Format::R32_UINT:
      return 4;
    case Format::R16_UINT:
      return 2;
    case Format::RG32_FLOAT:
      return 8;
    case Format::Unknown:
      return 0;
  }
  return 0;
}

const char* resourceTypeName(ResourceType type) {
  switch (type) {
    case ResourceType::AccelStruct:
      return "acceleration structure";
    case ResourceType::StorageBuffer:
      return "storage buffer";
    case ResourceType::ConstantBuffer:
      return "constant buffer";
    case ResourceType::StorageTexture:
      return "storage texture";
    case ResourceType::SampledTexture:
      return "sampled texture";
    case ResourceType::Sampler:
      return "sampler";
  }
  return "?";
}

const char* resourceStateName(ResourceState state) {
  switch (state) {
    case ResourceState::Undefined:
      return "Undefined";
    case ResourceState::ShaderResource:
      return "ShaderResource";
    case ResourceState::UnorderedAccess:
      return "UnorderedAccess";
    case ResourceState::ConstantBuffer:
      return "ConstantBuffer";
    case ResourceState::CopySource:
      return "CopySource";
    case ResourceState::CopyDest:
      return "CopyDest";
    case ResourceState::AccelStructBuildInput:
      return "AccelStructBuildInput";
    case ResourceState::AccelStructWrite:
      return "AccelStructWrite";
    case ResourceState::AccelStructRead:
      return "AccelStructRead";
    case ResourceState::ShaderTable:
      return "ShaderTable";
    case ResourceState::HostRead:
      return "HostRead";
    case ResourceState::RenderTarget:
      return "RenderTarget";
    case ResourceState::VertexInput:
      return "VertexInput";
    case ResourceState::Present:
      return "Present";
  }
  return "?";
}

const char* shaderStageName(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Compute:
      return "compute";
    case ShaderStage::RayGeneration:
      return "ray generation";
    case ShaderStage::Miss:
      return "miss";
    case ShaderStage::ClosestHit:
      return "closest hit";
    case ShaderStage::AnyHit:
      return "any hit";
    case ShaderStage::Intersection:
      return "intersection";
    case ShaderStage::Vertex:
      return "vertex";
    case ShaderStage::Pixel:
      return "pixel";
  }
  return "?";
}

const char* windowSystemName(WindowSystem system) {
  switch (system) {
    case WindowSystem::None:
      return "none";
    case WindowSystem::Win32:
      return "Win32";
    case WindowSystem::Xlib:
      return "X11";
    case WindowSystem::Wayland:
      return "Wayland";
  }
  return "?";
}

const char* adapterTypeName(AdapterType type) {
  switch (type) {
    case AdapterType::Discrete:
      return "discrete GPU";
    case AdapterType::Integrated:
      return "integrated GPU";
    case AdapterType::Virtual:
      return "virtual GPU";
    case AdapterType::Cpu:
      return "CPU";
    case AdapterType::Other:
      return "other";
  }
  return "?";
}

}  // namespace penumbra::rhi
