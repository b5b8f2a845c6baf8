#pragma once
// Plain enums and flags shared by every RHI object. No API headers here:
// engine/ never sees Vulkan or D3D12 types.
#include <cstdint>
#include <memory>
#include <string>

namespace penumbra::rhi {

enum class Format : uint8_t {
  Unknown,
  RGBA8_UNORM,   // D3D12: DXGI_FORMAT_R8G8B8A8_UNORM      Vulkan: VK_FORMAT_R8G8B8A8_UNORM
  BGRA8_UNORM,   // D3D12: DXGI_FORMAT_B8G8R8A8_UNORM      Vulkan: VK_FORMAT_B8G8R8A8_UNORM
                 // (swapchains)
  RGBA32_FLOAT,  // D3D12: DXGI_FORMAT_R32G32B32A32_FLOAT  Vulkan: VK_FORMAT_R32G32B32A32_SFLOAT
  RGB32_FLOAT,   // vertex positions only (AS build input)
  R32_UINT,      // index buffers, counters
  R16_UINT,
  RGBA8_SRGB,  // D3D12: DXGI_FORMAT_R8G8B8A8_UNORM_SRGB Vulkan: VK_FORMAT_R8G8B8A8_SRGB (sampled
               // colour textures; the sampler decodes sRGB to linear before filtering)
  RG32_FLOAT,  // D3D12: DXGI_FORMAT_R32G32_FLOAT        Vulkan: VK_FORMAT_R32G32_SFLOAT (vertex
               // attributes)
};
uint32_t formatByteSize(Format format);

// Where a buffer lives. D3D12: heap type DEFAULT / UPLOAD / READBACK.
// Vulkan: DEVICE_LOCAL / HOST_VISIBLE|HOST_COHERENT / HOST_VISIBLE|HOST_CACHED.
enum class MemoryLocation : uint8_t { DeviceLocal, Upload, Readback };

enum class BufferUsage : uint32_t {
  None = 0,
  StorageBuffer = 1 << 0,          // structured/raw UAV or SRV; Vulkan STORAGE_BUFFER
  ConstantBuffer = 1 << 1,         // CBV; Vulkan UNIFORM_BUFFER
  AccelStructBuildInput = 1 << 2,  // vertex/index/AABB/instance data read by AS builds
  AccelStructStorage = 1 << 3,     // backing memory of an acceleration structure
  ShaderTable = 1 << 4,            // shader binding table records
  CopySource = 1 << 5,
  CopyDest = 1 << 6,
  VertexBuffer = 1 << 7,  // D3D12: IASetVertexBuffers. Vulkan: VERTEX_BUFFER
  IndexBuffer = 1 << 8,   // D3D12: IASetIndexBuffer. Vulkan: INDEX_BUFFER
};
constexpr BufferUsage operator|(BufferUsage a, BufferUsage b) {
  return BufferUsage(uint32_t(a) | uint32_t(b));
}
constexpr bool hasFlag(BufferUsage set, BufferUsage flag) {
  return (uint32_t(set) & uint32_t(flag)) != 0;
}

enum class TextureUsage : uint32_t {
  None = 0,
  Storage = 1 << 0,  // UAV; Vulkan STORAGE image
  Sampled = 1 << 1,  // SRV; Vulkan SAMPLED image
  CopySource = 1 << 2,
  CopyDest = 1 << 3,
  RenderTarget = 1 << 4,  // RTV; Vulkan COLOR_ATTACHMENT
};
constexpr TextureUsage operator|(TextureUsage a, TextureUsage b) {
  return TextureUsage(uint32_t(a) | uint32_t(b));
}
constexpr bool hasFlag(TextureUsage set, TextureUsage flag) {
  return (uint32_t(set) & uint32_t(flag)) != 0;
}

// How a resource is about to be used. Command lists move resources between
// states explicitly (ICommandList::setBufferState and friends).
// D3D12: D3D12_RESOURCE_STATES transitions, UAV barriers for UAV->UAV.
// Vulkan: pipeline barriers with the stage/access masks of each state; image
// layouts GENERAL for shader access, TRANSFER_SRC/DST_OPTIMAL for copies.
enum class ResourceState : uint8_t {
  Undefined,
  ShaderResource,   // read in shaders
  UnorderedAccess,  // read/write in shaders
  ConstantBuffer,
  CopySource,
  CopyDest,
  AccelStructBuildInput,  // vertex/index/instance data read by an AS build
  AccelStructWrite,       // AS being built
  AccelStructRead,        // AS traced against, or read by a TLAS build
  ShaderTable,            // read by DispatchRays / vkCmdTraceRaysKHR
  HostRead,               // mapped and read by the CPU after a copy
  RenderTarget,           // drawn into by raster passes (the viewer's UI); D3D12 RENDER_TARGET,
                          // Vulkan COLOR_ATTACHMENT_OPTIMAL
  VertexInput,            // vertex and index buffers read by draws; D3D12
                          // VERTEX_AND_CONSTANT_BUFFER | INDEX_BUFFER (upload heaps' GENERIC_READ
                // includes both), Vulkan VERTEX_INPUT stage, VERTEX_ATTRIBUTE_READ | INDEX_READ
  Present,  // a back buffer handed to the swapchain; D3D12 PRESENT, Vulkan PRESENT_SRC_KHR
};
const char* resourceStateName(ResourceState state);

enum class ShaderStage : uint8_t {
  Compute,
  RayGeneration,
  Miss,
  ClosestHit,
  AnyHit,
  Intersection,
  Vertex,  // D3D12: vs_6_0. Vulkan: VERTEX
  Pixel,   // D3D12: ps_6_0. Vulkan: FRAGMENT
};
const char* shaderStageName(ShaderStage stage);

}  // namespace penumbra::rhi
