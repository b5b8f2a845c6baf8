// Buffers, textures and acceleration structures.
#include <fmt/format.h>

#include "penumbra/rhi/fault_injection.h"
#include "penumbra/rhi/geometry_input.h"
#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"
#include "vulkan_backend.h"

namespace penumbra::vk {

VkFormat toVkFormat(rhi::Format format) {
  switch (format) {
    case rhi::Format::RGBA8_UNORM:
      return VK_FORMAT_R8G8B8A8_UNORM;
    case rhi::Format::RGBA8_SRGB:
      return VK_FORMAT_R8G8B8A8_SRGB;
    case rhi::Format::BGRA8_UNORM:
      return VK_FORMAT_B8G8R8A8_UNORM;
    case rhi::Format::RGBA32_FLOAT:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case rhi::Format::RGB32_FLOAT:
      return VK_FORMAT_R32G32B32_SFLOAT;
    case rhi::Format::R32_UINT:
      return VK_FORMAT_R32_UINT;
    case rhi::Format::R16_UINT:
      return VK_FORMAT_R16_UINT;
    case rhi::Format::RG32_FLOAT:
      return VK_FORMAT_R32G32_SFLOAT;
    case rhi::Format::Unknown:
      break;
  }
  throw Error("vulkan: unsupported format");
}

namespace {

// vkAllocateMemory, or the failure an armed fault injection asks for
// (rhi/fault_injection.h).
VkResult allocateMemory(VulkanDevice& device, const VkMemoryAllocateInfo& info, VkDeviceMemory& memory) {
  if (rhi::faults::shouldFail(rhi::faults::Site::Allocation)) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
  return vkAllocateMemory(device.handle(), &info, nullptr, &memory);
}

std::string allocationError(const VulkanDevice& device, uint64_t bytes, const char* kind,
                            const std::string& name, VkResult result) {
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    return fmt::format("vulkan: out of {} memory allocating {:.1f} MiB for {} '{}' on {} ({}): the "
                       "scene or image is too large for this device",
                       result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "device" : "host",
                       double(bytes) / (1024.0 * 1024.0), kind, name, device.adapter().name,
                       resultName(result));
  return fmt::format("vulkan: allocating {} bytes for {} '{}' failed: {}", bytes, kind, name,
                     resultName(result));
}

}  // namespace

// `alignment` > 0 over-allocates so that deviceAddress() is a multiple of it
// (shader tables need shaderGroupBaseAlignment, scratch buffers
// minAccelerationStructureScratchOffsetAlignment); alignedOffset() says where
// that address lies inside the VkBuffer.
VulkanBuffer::VulkanBuffer(VulkanDevice& device, const rhi::BufferDesc& desc, uint64_t alignment)
    : device_(device), desc_(desc) {
  using rhi::BufferUsage;
  VkBufferUsageFlags usage = VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                             VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (hasFlag(desc.usage, BufferUsage::StorageBuffer)) usage |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  if (hasFlag(desc.usage, BufferUsage::ConstantBuffer)) usage |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  if (hasFlag(desc.usage, BufferUsage::AccelStructBuildInput))
    usage |= VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
  if (hasFlag(desc.usage, BufferUsage::AccelStructStorage))
    usage |= VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR;
  if (hasFlag(desc.usage, BufferUsage::ShaderTable))
    usage |= VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR;
  if (hasFlag(desc.usage, BufferUsage::VertexBuffer)) usage |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  if (hasFlag(desc.usage, BufferUsage::IndexBuffer)) usage |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;

  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = desc.byteSize + (alignment > 1 ? alignment : 0);
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkDevice dev = device_.handle();
  check(vkCreateBuffer(dev, &info, nullptr, &buffer_), "vkCreateBuffer");

  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(dev, buffer_, &req);
  VkMemoryPropertyFlags required = 0, preferred = 0;
  switch (desc.memory) {
    case rhi::MemoryLocation::DeviceLocal:
      required = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
      break;
    case rhi::MemoryLocation::Upload:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case rhi::MemoryLocation::Readback:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.pNext = &flags;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = device_.memoryType(req.memoryTypeBits, required, preferred);
  VkResult r = allocateMemory(device_, alloc, memory_);
  if (r != VK_SUCCESS) {
    vkDestroyBuffer(dev, buffer_, nullptr);
    throw Error(allocationError(device_, req.size, "buffer", desc.debugName, r));
  }
  check(vkBindBufferMemory(dev, buffer_, memory_, 0), "vkBindBufferMemory");
  if (desc.memory != rhi::MemoryLocation::DeviceLocal)
    check(vkMapMemory(dev, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");

  VkBufferDeviceAddressInfo addressInfo{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  addressInfo.buffer = buffer_;
  const uint64_t base = vkGetBufferDeviceAddress(dev, &addressInfo);
  address_ = alignment > 1 ? rhi::alignUp(base, alignment) : base;
  alignedOffset_ = address_ - base;
  device_.setName(VK_OBJECT_TYPE_BUFFER, uint64_t(buffer_), desc.debugName);
}

VulkanBuffer::~VulkanBuffer() {
  VkDevice dev = device_.handle();
  if (mapped_) vkUnmapMemory(dev, memory_);
  vkDestroyBuffer(dev, buffer_, nullptr);
  vkFreeMemory(dev, memory_, nullptr);
}

void* VulkanBuffer::mappedData() {
  if (!mapped_)
    throw Error(
        fmt::format("vulkan: buffer '{}' is device-local and cannot be mapped", desc_.debugName));
  return static_cast<uint8_t*>(mapped_) + alignedOffset_;
}

VulkanTexture::VulkanTexture(VulkanDevice& device, const rhi::TextureDesc& desc)
    : device_(device), desc_(desc) {
  using rhi::TextureUsage;
  VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (hasFlag(desc.usage, TextureUsage::Storage)) usage |= VK_IMAGE_USAGE_STORAGE_BIT;
  if (hasFlag(desc.usage, TextureUsage::Sampled)) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (hasFlag(desc.usage, TextureUsage::RenderTarget)) usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;

  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = toVkFormat(desc.format);
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = desc.mipLevels;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkDevice dev = device_.handle();
  check(vkCreateImage(dev, &info, nullptr, &image_), "vkCreateImage");

  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(dev, image_, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      device_.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
  if (VkResult r = allocateMemory(device_, alloc, memory_); r != VK_SUCCESS) {
    vkDestroyImage(dev, image_, nullptr);
    throw Error(allocationError(device_, req.size, "texture", desc.debugName, r));
  }
  check(vkBindImageMemory(dev, image_, memory_, 0), "vkBindImageMemory");
  createView();
}

VulkanTexture::VulkanTexture(VulkanDevice& device, const rhi::TextureDesc& desc,
                             VkImage externalImage)
    : device_(device), desc_(desc), image_(externalImage), ownsImage_(false) {
  createView();
}

void VulkanTexture::createView() {
  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image_;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = toVkFormat(desc_.format);
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, desc_.mipLevels, 0, 1};
  check(vkCreateImageView(device_.handle(), &viewInfo, nullptr, &view_), "vkCreateImageView");
  if (ownsImage_) device_.setName(VK_OBJECT_TYPE_IMAGE, uint64_t(image_), desc_.debugName);
  device_.setName(VK_OBJECT_TYPE_IMAGE_VIEW, uint64_t(view_), desc_.debugName);
}

VulkanTexture::~VulkanTexture() {
  VkDevice dev = device_.handle();
  vkDestroyImageView(dev, view_, nullptr);
  if (!ownsImage_) return;  // the swapchain destroys its images
  vkDestroyImage(dev, image_, nullptr);
  vkFreeMemory(dev, memory_, nullptr);
}

namespace {
VkFilter toVkFilter(rhi::Filter filter) {
  return filter == rhi::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

VkSamplerAddressMode toVkAddressMode(rhi::AddressMode mode) {
  switch (mode) {
    case rhi::AddressMode::Repeat:
      return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case rhi::AddressMode::MirroredRepeat:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case rhi::AddressMode::ClampToEdge:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}
}  // namespace

// Vulkan: vkCreateSampler. MipFilter::None is mipmapMode NEAREST with the
// LOD range [0, 0]; anisotropy stays off (it is a feature the device would
// have to enable, and rays pick one isotropic level).
VulkanSampler::VulkanSampler(VulkanDevice& device, const rhi::SamplerDesc& desc)
    : device_(device), desc_(desc) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = toVkFilter(desc.magFilter);
  info.minFilter = toVkFilter(desc.minFilter);
  info.mipmapMode = desc.mipFilter == rhi::MipFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                             : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = toVkAddressMode(desc.addressU);
  info.addressModeV = toVkAddressMode(desc.addressV);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.anisotropyEnable = VK_FALSE;
  info.maxAnisotropy = 1.0f;
  info.minLod = 0.0f;
  info.maxLod = desc.mipFilter == rhi::MipFilter::None ? 0.0f : VK_LOD_CLAMP_NONE;
  info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  check(vkCreateSampler(device_.handle(), &info, nullptr, &sampler_), "vkCreateSampler");
  device_.setName(VK_OBJECT_TYPE_SAMPLER, uint64_t(sampler_), desc.debugName);
}

VulkanSampler::~VulkanSampler() {
  vkDestroySampler(device_.handle(), sampler_, nullptr);
}

VulkanAccelStruct::VulkanAccelStruct(VulkanDevice& device, const rhi::rt::AccelStructDesc& desc)
    : device_(device), desc_(desc) {
  AccelStructBuildInputs inputs = buildInputs(0, desc.topLevelMaxInstances);
  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  vkGetAccelerationStructureBuildSizesKHR(device_.handle(),
                                          VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                          &inputs.info, inputs.maxPrimitiveCounts.data(), &sizes);
  scratchBytes_ = sizes.buildScratchSize;

  rhi::BufferDesc storageDesc;
  storageDesc.byteSize = sizes.accelerationStructureSize;
  storageDesc.usage = rhi::BufferUsage::AccelStructStorage;
  storageDesc.debugName = desc.debugName + " storage";
  storage_ = std::make_unique<VulkanBuffer>(device_, storageDesc);

  VkAccelerationStructureCreateInfoKHR create{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  create.buffer = storage_->handle();
  create.size = sizes.accelerationStructureSize;
  create.type = desc.isTopLevel ? VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR
                                : VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  check(vkCreateAccelerationStructureKHR(device_.handle(), &create, nullptr, &handle_),
        "vkCreateAccelerationStructureKHR");
  VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  addressInfo.accelerationStructure = handle_;
  address_ = vkGetAccelerationStructureDeviceAddressKHR(device_.handle(), &addressInfo);
  device_.setName(VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR, uint64_t(handle_), desc.debugName);
}

VulkanAccelStruct::~VulkanAccelStruct() {
  vkDestroyAccelerationStructureKHR(device_.handle(), handle_, nullptr);
}

AccelStructBuildInputs VulkanAccelStruct::buildInputs(uint64_t instanceAddress,
                                                      uint32_t instanceCount) const {
  AccelStructBuildInputs in;
  if (desc_.isTopLevel) {
    VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    g.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    g.geometry.instances.sType =
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    g.geometry.instances.arrayOfPointers = VK_FALSE;
    g.geometry.instances.data.deviceAddress = instanceAddress;
    in.geometries.push_back(g);
    in.ranges.push_back({instanceCount, 0, 0, 0});
    in.maxPrimitiveCounts.push_back(desc_.topLevelMaxInstances);
  } else {
    for (const auto& geometry : desc_.bottomLevelGeometries) {
      const rhi::rt::GeometryInput input = rhi::rt::geometryInput(geometry);
      VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
      if (input.opaque) g.flags |= VK_GEOMETRY_OPAQUE_BIT_KHR;
      if (input.noDuplicateAnyHitInvocation)
        g.flags |= VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;
      if (input.triangles) {
        g.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        auto& tri = g.geometry.triangles;
        tri.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
        tri.vertexFormat = toVkFormat(input.vertexFormat);
        tri.vertexData.deviceAddress = input.vertexAddress;
        tri.vertexStride = input.vertexStride;
        tri.maxVertex = input.vertexCount > 0 ? input.vertexCount - 1 : 0;
        tri.transformData.deviceAddress = input.transformAddress;
        tri.indexType = !input.indexed                               ? VK_INDEX_TYPE_NONE_KHR
                        : input.indexFormat == rhi::Format::R16_UINT ? VK_INDEX_TYPE_UINT16
                                                                     : VK_INDEX_TYPE_UINT32;
        tri.indexData.deviceAddress = input.indexAddress;
      } else {
        g.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
        g.geometry.aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
        g.geometry.aabbs.data.deviceAddress = input.aabbAddress;
        g.geometry.aabbs.stride = input.aabbStride;
      }
      in.geometries.push_back(g);
      in.ranges.push_back({input.primitiveCount, 0, 0, 0});
      in.maxPrimitiveCounts.push_back(input.primitiveCount);
    }
  }
  in.info.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR;
  in.info.type = desc_.isTopLevel ? VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR
                                  : VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  in.info.flags = desc_.buildFlags == rhi::rt::BuildFlags::PreferFastBuild
                      ? VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR
                      : VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  in.info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  in.info.dstAccelerationStructure = handle_;
  in.info.geometryCount = uint32_t(in.geometries.size());
  in.info.pGeometries = in.geometries.data();
  return in;
}

}  // namespace penumbra::vk
