#pragma once
// Buffers, textures and acceleration structures.
#include <array>
#include <cstddef>
#include <vector>

#include "penumbra/rhi/types.h"

namespace penumbra::rhi {

struct BufferDesc {
  uint64_t byteSize = 0;
  BufferUsage usage = BufferUsage::None;
  MemoryLocation memory = MemoryLocation::DeviceLocal;
  std::string debugName;
};

// D3D12: ID3D12Resource (committed, buffer dimension).
// Vulkan: VkBuffer + its own VkDeviceMemory, SHADER_DEVICE_ADDRESS usage always on.
class IBuffer {
 public:
  virtual ~IBuffer() = default;
  virtual const BufferDesc& desc() const = 0;
  // D3D12: GetGPUVirtualAddress. Vulkan: vkGetBufferDeviceAddress.
  virtual uint64_t deviceAddress() const = 0;
  // Upload/Readback buffers only; the pointer stays valid for the buffer's life.
  // D3D12: ID3D12Resource::Map. Vulkan: vkMapMemory (persistently mapped).
  virtual void* mappedData() = 0;
  // Current state as recorded by command lists (see ResourceState).
  ResourceState state = ResourceState::Undefined;
};
using BufferHandle = std::shared_ptr<IBuffer>;

struct TextureDesc {
  uint32_t width = 1;
  uint32_t height = 1;
  Format format = Format::RGBA32_FLOAT;
  TextureUsage usage = TextureUsage::Storage;
  // Level i is max(1, width >> i) x max(1, height >> i); at most
  // mipLevelCount(width, height). More than one only for textures that are
  // sampled and written with writeTexture, not storage or render targets.
  uint32_t mipLevels = 1;
  std::string debugName;
};

// The levels of a full mip chain down to 1x1: floor(log2(max(w, h))) + 1.
uint32_t mipLevelCount(uint32_t width, uint32_t height);
// The bytes of every level of `desc`, tightly packed, largest first: what
// writeTexture takes.
uint64_t textureByteSize(const TextureDesc& desc);

// D3D12: ID3D12Resource (TEXTURE2D, desc.mipLevels). Vulkan: VkImage + VkImageView (2D,
// every level).
class ITexture {
 public:
  virtual ~ITexture() = default;
  virtual const TextureDesc& desc() const = 0;
  ResourceState state = ResourceState::Undefined;
};
using TextureHandle = std::shared_ptr<ITexture>;

// Samplers are separate objects (HLSL SamplerState, GLSL `sampler`), combined
// with a texture in the shader, so any texture can be read with any sampler.
// The shader picks the level (SampleLevel: rays have no screen derivatives).
enum class Filter : uint8_t { Nearest, Linear };
// Between mip levels: None reads level 0 only, whatever level is asked;
// Nearest the nearest level; Linear blends the two nearest (trilinear).
enum class MipFilter : uint8_t { None, Nearest, Linear };
enum class AddressMode : uint8_t { Repeat, MirroredRepeat, ClampToEdge };

struct SamplerDesc {
  Filter minFilter = Filter::Linear;
  Filter magFilter = Filter::Linear;
  MipFilter mipFilter = MipFilter::None;
  AddressMode addressU = AddressMode::Repeat;
  AddressMode addressV = AddressMode::Repeat;
  std::string debugName;
};

// D3D12: a sampler descriptor (D3D12_SAMPLER_DESC), written into the
// shader-visible sampler heap by the binding sets that hold it.
// Vulkan: VkSampler (LOD range [0, 0] for MipFilter::None, no anisotropy).
class ISampler {
 public:
  virtual ~ISampler() = default;
  virtual const SamplerDesc& desc() const = 0;
};
using SamplerHandle = std::shared_ptr<ISampler>;

namespace rt {

// Row-major 3x4 object-to-world matrix, as DXR and Vulkan both store it.
using AffineTransform = std::array<float, 12>;
constexpr AffineTransform kIdentityTransform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

enum class GeometryType : uint8_t { Triangles, AABBs };

// D3D12: D3D12_RAYTRACING_GEOMETRY_FLAGS. Vulkan: VkGeometryFlagsKHR.
enum class GeometryFlags : uint8_t { None = 0, Opaque = 1, NoDuplicateAnyHitInvocation = 2 };

struct GeometryTriangles {
  IBuffer* vertexBuffer = nullptr;
  uint64_t vertexOffset = 0;
  Format vertexFormat = Format::RGB32_FLOAT;
  uint32_t vertexStride = 12;
  uint32_t vertexCount = 0;
  IBuffer* indexBuffer = nullptr;  // null: non-indexed triangle list
  uint64_t indexOffset = 0;
  Format indexFormat = Format::R32_UINT;
  uint32_t indexCount = 0;
  // Null: the vertices are the BLAS's space. Otherwise a row-major 3x4 float
  // matrix (AffineTransform, 16-byte aligned) applied to the vertices when
  // the BLAS is built: D3D12 Transform3x4, Vulkan transformData. The buffer
  // needs BufferUsage::AccelStructBuildInput.
  IBuffer* transformBuffer = nullptr;
  uint64_t transformOffset = 0;
};

// Each AABB is 6 floats (min xyz, max xyz): D3D12_RAYTRACING_AABB /
// VkAabbPositionsKHR.
struct GeometryAABBs {
  IBuffer* buffer = nullptr;
  uint64_t offset = 0;
  uint32_t count = 0;
  uint32_t stride = 24;
};

// D3D12: D3D12_RAYTRACING_GEOMETRY_DESC. Vulkan: VkAccelerationStructureGeometryKHR.
struct GeometryDesc {
  GeometryType type = GeometryType::Triangles;
  GeometryFlags flags = GeometryFlags::Opaque;
  GeometryTriangles triangles;
  GeometryAABBs aabbs;
};

// Byte-identical to D3D12_RAYTRACING_INSTANCE_DESC and VkAccelerationStructureInstanceKHR.
struct InstanceDesc {
  AffineTransform transform = kIdentityTransform;
  uint32_t instanceID : 24 = 0;  // InstanceID() / gl_InstanceCustomIndexEXT
  uint32_t instanceMask : 8 = 0xff;
  uint32_t instanceContributionToHitGroupIndex : 24 = 0;  // hit-group offset in the shader table
  uint32_t flags : 8 = 0;                                 // InstanceFlags
  uint64_t bottomLevelAddress = 0;                        // IAccelStruct::deviceAddress()
};
static_assert(sizeof(InstanceDesc) == 64, "InstanceDesc must match the 64-byte API layout");

// D3D12_RAYTRACING_INSTANCE_FLAGS / VkGeometryInstanceFlagBitsKHR (same bits).
enum InstanceFlags : uint32_t {
  InstanceTriangleCullDisable = 1,
  InstanceTriangleFrontCounterClockwise = 2,
  InstanceForceOpaque = 4,
  InstanceForceNonOpaque = 8,
};

enum class BuildFlags : uint8_t { PreferFastTrace = 0, PreferFastBuild = 1 };

struct AccelStructDesc {
  bool isTopLevel = false;
  std::vector<GeometryDesc> bottomLevelGeometries;  // bottom level only
  uint32_t topLevelMaxInstances = 0;                // top level only
  BuildFlags buildFlags = BuildFlags::PreferFastTrace;
  std::string debugName;
};

// D3D12: a buffer in RAYTRACING_ACCELERATION_STRUCTURE state sized by
// GetRaytracingAccelerationStructurePrebuildInfo.
// Vulkan: VkAccelerationStructureKHR over a buffer sized by
// vkGetAccelerationStructureBuildSizesKHR.
class IAccelStruct {
 public:
  virtual ~IAccelStruct() = default;
  virtual const AccelStructDesc& desc() const = 0;
  // The address instances point at (InstanceDesc::bottomLevelAddress).
  virtual uint64_t deviceAddress() const = 0;
  ResourceState state = ResourceState::Undefined;
};
using AccelStructHandle = std::shared_ptr<IAccelStruct>;

}  // namespace rt
}  // namespace penumbra::rhi
