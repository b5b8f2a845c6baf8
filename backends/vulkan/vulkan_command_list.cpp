#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"
#include "vulkan_backend.h"

namespace penumbra::vk {
namespace {

struct StageAccess {
  VkPipelineStageFlags stages;
  VkAccessFlags access;
};

// `shaderStages`: the device's (VulkanDevice::shaderStages).
StageAccess stageAccess(rhi::ResourceState state, VkPipelineStageFlags shaderStages) {
  using S = rhi::ResourceState;
  switch (state) {
    case S::Undefined:
      return {VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0};
    case S::ShaderResource:
      return {shaderStages, VK_ACCESS_SHADER_READ_BIT};
    case S::UnorderedAccess:
      return {shaderStages, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    case S::ConstantBuffer:
      return {shaderStages, VK_ACCESS_UNIFORM_READ_BIT};
    case S::CopySource:
      return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};
    case S::CopyDest:
      return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT};
    case S::AccelStructBuildInput:
      return {VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, VK_ACCESS_SHADER_READ_BIT};
    case S::AccelStructWrite:
      return {VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
              VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                  VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR};
    case S::AccelStructRead:
      return {shaderStages | VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
              VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR};
    case S::ShaderTable:
      return {VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT};
    case S::HostRead:
      return {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};
    case S::RenderTarget:
      return {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
    case S::VertexInput:
      return {VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
              VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT};
    // The presentation engine's reads are ordered by the present semaphore.
    case S::Present:
      return {VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0};
  }
  return {VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
          VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT};
}

// Shader access uses GENERAL (storage images need it); copies use the
// transfer-optimal layouts.
VkImageLayout imageLayout(rhi::ResourceState state) {
  switch (state) {
    case rhi::ResourceState::Undefined:
      return VK_IMAGE_LAYOUT_UNDEFINED;
    case rhi::ResourceState::CopySource:
      return VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    case rhi::ResourceState::CopyDest:
      return VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    case rhi::ResourceState::RenderTarget:
      return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    case rhi::ResourceState::Present:
      return VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    default:
      return VK_IMAGE_LAYOUT_GENERAL;
  }
}

bool isWriteState(rhi::ResourceState s) {
  return s == rhi::ResourceState::UnorderedAccess || s == rhi::ResourceState::CopyDest ||
         s == rhi::ResourceState::AccelStructWrite || s == rhi::ResourceState::RenderTarget;
}

// Whether moving from `from` to `to` needs a barrier: always after a write
// (write-after-write and read-after-write hazards), and between different read
// states only if they belong to different stages.
bool needsBarrier(rhi::ResourceState from, rhi::ResourceState to) {
  return from != to || isWriteState(from);
}

}  // namespace

VulkanCommandList::VulkanCommandList(VulkanDevice& device, const std::string& debugName)
    : device_(device), debugName_(debugName) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.queueFamilyIndex = device_.queueFamily();
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  check(vkCreateCommandPool(device_.handle(), &poolInfo, nullptr, &pool_), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  check(vkAllocateCommandBuffers(device_.handle(), &alloc, &commandBuffer_),
        "vkAllocateCommandBuffers");
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  check(vkCreateFence(device_.handle(), &fenceInfo, nullptr, &fence_), "vkCreateFence");
  device_.setName(VK_OBJECT_TYPE_COMMAND_BUFFER, uint64_t(commandBuffer_), debugName);
}

VulkanCommandList::~VulkanCommandList() {
  vkWaitForFences(device_.handle(), 1, &fence_, VK_TRUE, UINT64_MAX);
  device_.forgetSubmitted(this);
  vkDestroyFence(device_.handle(), fence_, nullptr);
  vkDestroyCommandPool(device_.handle(), pool_, nullptr);
}

void VulkanCommandList::replaceFenceSignaled() {
  VkFence fresh = VK_NULL_HANDLE;
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  check(vkCreateFence(device_.handle(), &fenceInfo, nullptr, &fresh), "vkCreateFence");
  vkDestroyFence(device_.handle(), fence_, nullptr);
  fence_ = fresh;
}

void VulkanCommandList::open() {
  // A list still executing is waited for before it is recorded again.
  device_.checkDevice(vkWaitForFences(device_.handle(), 1, &fence_, VK_TRUE, UINT64_MAX),
                      "waiting for a command list's last submission (vkWaitForFences)");
  releaseTransientResources();
  // From here on the staging buffers are this recording's: a waitForIdle
  // while it records (a pass rebinding mid-frame) must leave them alone.
  device_.forgetSubmitted(this);
  check(vkResetCommandPool(device_.handle(), pool_, 0), "vkResetCommandPool");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commandBuffer_, &begin), "vkBeginCommandBuffer");
  boundLayout_ = VK_NULL_HANDLE;
}

void VulkanCommandList::close() {
  check(vkEndCommandBuffer(commandBuffer_), "vkEndCommandBuffer");
}

std::shared_ptr<VulkanBuffer> VulkanCommandList::makeTransientBuffer(uint64_t bytes,
                                                                     rhi::BufferUsage usage,
                                                                     rhi::MemoryLocation memory,
                                                                     uint64_t alignment,
                                                                     const char* name) {
  rhi::BufferDesc desc;
  desc.byteSize = std::max<uint64_t>(bytes, 4);
  desc.usage = usage;
  desc.memory = memory;
  desc.debugName = name;
  auto buffer = std::make_shared<VulkanBuffer>(device_, desc, alignment);
  transient_.push_back(buffer);
  return buffer;
}

void VulkanCommandList::setBufferState(rhi::IBuffer* buffer, rhi::ResourceState state) {
  if (!needsBarrier(buffer->state, state)) return;
  auto from = stageAccess(buffer->state, device_.shaderStages()), to = stageAccess(state, device_.shaderStages());
  // Buffers and acceleration structures share one global memory barrier
  // shape; drivers handle these as cheaply as buffer-range barriers.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = from.access;
  barrier.dstAccessMask = to.access;
  vkCmdPipelineBarrier(commandBuffer_, from.stages, to.stages, 0, 1, &barrier, 0, nullptr, 0,
                       nullptr);
  buffer->state = state;
}

void VulkanCommandList::setAccelStructState(rhi::rt::IAccelStruct* as, rhi::ResourceState state) {
  if (!needsBarrier(as->state, state)) return;
  auto from = stageAccess(as->state, device_.shaderStages()), to = stageAccess(state, device_.shaderStages());
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = from.access;
  barrier.dstAccessMask = to.access;
  vkCmdPipelineBarrier(commandBuffer_, from.stages, to.stages, 0, 1, &barrier, 0, nullptr, 0,
                       nullptr);
  as->state = state;
}

void VulkanCommandList::setTextureState(rhi::ITexture* texture, rhi::ResourceState state) {
  if (!needsBarrier(texture->state, state)) return;
  auto* t = static_cast<VulkanTexture*>(texture);
  auto from = stageAccess(texture->state, device_.shaderStages()), to = stageAccess(state, device_.shaderStages());
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = from.access;
  barrier.dstAccessMask = to.access;
  barrier.oldLayout = imageLayout(texture->state);
  barrier.newLayout = imageLayout(state);
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = t->image();
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
  vkCmdPipelineBarrier(commandBuffer_, from.stages, to.stages, 0, 0, nullptr, 0, nullptr, 1,
                       &barrier);
  texture->state = state;
}

void VulkanCommandList::writeBuffer(rhi::IBuffer* buffer, const void* data, size_t bytes,
                                    uint64_t offset) {
  if (bytes == 0) return;
  auto staging = makeTransientBuffer(bytes, rhi::BufferUsage::CopySource,
                                     rhi::MemoryLocation::Upload, 0, "writeBuffer staging");
  std::memcpy(staging->mappedData(), data, bytes);
  setBufferState(buffer, rhi::ResourceState::CopyDest);
  VkBufferCopy region{0, offset, bytes};
  vkCmdCopyBuffer(commandBuffer_, staging->handle(), static_cast<VulkanBuffer*>(buffer)->handle(),
                  1, &region);
}

void VulkanCommandList::writeTexture(rhi::ITexture* texture, const void* data, size_t bytes) {
  const auto& d = texture->desc();
  auto staging = makeTransientBuffer(bytes, rhi::BufferUsage::CopySource,
                                     rhi::MemoryLocation::Upload, 0, "writeTexture staging");
  std::memcpy(staging->mappedData(), data, bytes);
  setTextureState(texture, rhi::ResourceState::CopyDest);
  // Each level's bytes are a whole number of texels, so every region's
  // offset stays texel-aligned as Vulkan requires.
  std::vector<VkBufferImageCopy> regions(d.mipLevels);
  VkDeviceSize offset = staging->alignedOffset();
  for (uint32_t level = 0; level < d.mipLevels; ++level) {
    const uint32_t w = std::max(1u, d.width >> level), h = std::max(1u, d.height >> level);
    regions[level].bufferOffset = offset;
    regions[level].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    regions[level].imageExtent = {w, h, 1};
    offset += VkDeviceSize(w) * h * rhi::formatByteSize(d.format);
  }
  vkCmdCopyBufferToImage(
      commandBuffer_, staging->handle(), static_cast<VulkanTexture*>(texture)->image(),
      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()), regions.data());
}

void VulkanCommandList::copyBuffer(rhi::IBuffer* dst, uint64_t dstOffset, rhi::IBuffer* src,
                                   uint64_t srcOffset, uint64_t bytes) {
  setBufferState(src, rhi::ResourceState::CopySource);
  setBufferState(dst, rhi::ResourceState::CopyDest);
  VkBufferCopy region{srcOffset, dstOffset, bytes};
  vkCmdCopyBuffer(commandBuffer_, static_cast<VulkanBuffer*>(src)->handle(),
                  static_cast<VulkanBuffer*>(dst)->handle(), 1, &region);
  // Make the copy visible to the CPU once the list has finished.
  if (dst->desc().memory == rhi::MemoryLocation::Readback)
    setBufferState(dst, rhi::ResourceState::HostRead);
}

void VulkanCommandList::copyTextureToBuffer(rhi::ITexture* src, rhi::IBuffer* dst,
                                            uint64_t dstOffset) {
  const auto& d = src->desc();
  setTextureState(src, rhi::ResourceState::CopySource);
  setBufferState(dst, rhi::ResourceState::CopyDest);
  VkBufferImageCopy region{};
  region.bufferOffset = dstOffset;
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {d.width, d.height, 1};
  vkCmdCopyImageToBuffer(commandBuffer_, static_cast<VulkanTexture*>(src)->image(),
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         static_cast<VulkanBuffer*>(dst)->handle(), 1, &region);
  if (dst->desc().memory == rhi::MemoryLocation::Readback)
    setBufferState(dst, rhi::ResourceState::HostRead);
}

void VulkanCommandList::copyTexture(rhi::ITexture* dst, rhi::ITexture* src) {
  const auto &d = dst->desc(), &s = src->desc();
  setTextureState(src, rhi::ResourceState::CopySource);
  setTextureState(dst, rhi::ResourceState::CopyDest);
  VkImage from = static_cast<VulkanTexture*>(src)->image();
  VkImage to = static_cast<VulkanTexture*>(dst)->image();
  const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  if (d.format == s.format) {
    VkImageCopy region{};
    region.srcSubresource = region.dstSubresource = layers;
    region.extent = {d.width, d.height, 1};
    vkCmdCopyImage(commandBuffer_, from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    return;
  }
  // A raw copy would keep the bytes and swap red and blue; a 1:1 blit
  // converts between channel orders.
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = layers;
  blit.srcOffsets[1] = {int32_t(s.width), int32_t(s.height), 1};
  blit.dstOffsets[1] = {int32_t(d.width), int32_t(d.height), 1};
  vkCmdBlitImage(commandBuffer_, from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
}

void VulkanCommandList::clearTextureFloat(rhi::ITexture* texture, float r, float g, float b,
                                          float a) {
  setTextureState(texture, rhi::ResourceState::CopyDest);
  VkClearColorValue color{};
  color.float32[0] = r;
  color.float32[1] = g;
  color.float32[2] = b;
  color.float32[3] = a;
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(commandBuffer_, static_cast<VulkanTexture*>(texture)->image(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1, &range);
}

void VulkanCommandList::clearBufferUint(rhi::IBuffer* buffer, uint32_t value) {
  setBufferState(buffer, rhi::ResourceState::CopyDest);
  vkCmdFillBuffer(commandBuffer_, static_cast<VulkanBuffer*>(buffer)->handle(), 0, VK_WHOLE_SIZE,
                  value);
}

void VulkanCommandList::buildBottomLevelAccelStruct(rhi::rt::IAccelStruct* as) {
  auto* vas = static_cast<VulkanAccelStruct*>(as);
  for (const auto& g : vas->desc().bottomLevelGeometries) {
    if (g.type == rhi::rt::GeometryType::Triangles) {
      setBufferState(g.triangles.vertexBuffer, rhi::ResourceState::AccelStructBuildInput);
      if (g.triangles.indexBuffer)
        setBufferState(g.triangles.indexBuffer, rhi::ResourceState::AccelStructBuildInput);
      if (g.triangles.transformBuffer)
        setBufferState(g.triangles.transformBuffer, rhi::ResourceState::AccelStructBuildInput);
    } else {
      setBufferState(g.aabbs.buffer, rhi::ResourceState::AccelStructBuildInput);
    }
  }
  setAccelStructState(as, rhi::ResourceState::AccelStructWrite);
  auto scratch = makeTransientBuffer(vas->scratchBytes(), rhi::BufferUsage::StorageBuffer,
                                     rhi::MemoryLocation::DeviceLocal, device_.scratchAlignment(),
                                     "BLAS scratch");
  AccelStructBuildInputs inputs = vas->buildInputs();
  inputs.info.scratchData.deviceAddress = scratch->deviceAddress();
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = inputs.ranges.data();
  vkCmdBuildAccelerationStructuresKHR(commandBuffer_, 1, &inputs.info, &ranges);
}

void VulkanCommandList::buildTopLevelAccelStruct(rhi::rt::IAccelStruct* as,
                                                 const rhi::rt::InstanceDesc* instances,
                                                 uint32_t count) {
  auto* vas = static_cast<VulkanAccelStruct*>(as);
  // Bottom levels built earlier in this list are read by this build; the
  // instances only hold their addresses, so one global barrier covers them.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
  vkCmdPipelineBarrier(commandBuffer_, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                       VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);

  const uint64_t bytes = uint64_t(count) * sizeof(rhi::rt::InstanceDesc);
  // Instance data must be 16-byte aligned (VkAccelerationStructureGeometryInstancesDataKHR).
  auto instanceBuffer = makeTransientBuffer(bytes, rhi::BufferUsage::AccelStructBuildInput,
                                            rhi::MemoryLocation::Upload, 16, "TLAS instances");
  if (count > 0) std::memcpy(instanceBuffer->mappedData(), instances, bytes);
  auto scratch = makeTransientBuffer(vas->scratchBytes(), rhi::BufferUsage::StorageBuffer,
                                     rhi::MemoryLocation::DeviceLocal, device_.scratchAlignment(),
                                     "TLAS scratch");
  setAccelStructState(as, rhi::ResourceState::AccelStructWrite);
  AccelStructBuildInputs inputs = vas->buildInputs(instanceBuffer->deviceAddress(), count);
  inputs.info.scratchData.deviceAddress = scratch->deviceAddress();
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = inputs.ranges.data();
  vkCmdBuildAccelerationStructuresKHR(commandBuffer_, 1, &inputs.info, &ranges);
}

void VulkanCommandList::transitionBindingSets(const std::vector<rhi::IBindingSet*>& sets) {
  for (auto* s : sets) {
    if (!s) continue;
    auto* set = static_cast<VulkanBindingSet*>(s);
    for (const auto& item : set->desc().items) {
      const auto shaderState = set->isWritable(item.slot) ? rhi::ResourceState::UnorderedAccess
                                                          : rhi::ResourceState::ShaderResource;
      switch (item.type) {
        case rhi::ResourceType::AccelStruct:
          setAccelStructState(item.accelStruct.get(), rhi::ResourceState::AccelStructRead);
          break;
        case rhi::ResourceType::StorageBuffer:
          setBufferState(item.buffer.get(), shaderState);
          break;
        case rhi::ResourceType::ConstantBuffer:
          setBufferState(item.buffer.get(), rhi::ResourceState::ConstantBuffer);
          break;
        case rhi::ResourceType::StorageTexture:
          setTextureState(item.texture.get(), shaderState);
          break;
        case rhi::ResourceType::SampledTexture:
          for (const auto& texture : item.textures)
            setTextureState(texture.get(), rhi::ResourceState::ShaderResource);
          break;
        case rhi::ResourceType::Sampler:
          break;  // no memory behind a sampler
      }
    }
  }
}

void VulkanCommandList::setRayTracingState(const rhi::RayTracingState& state) {
  auto* pipeline = static_cast<VulkanRayTracingPipeline*>(state.pipeline);
  auto* table = static_cast<VulkanShaderTable*>(state.shaderTable);
  transitionBindingSets(state.bindingSets);
  boundRegions_ = table->prepare();
  transient_.push_back(table->buffer());
  vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline->handle());
  std::vector<VkDescriptorSet> sets;
  for (auto* s : state.bindingSets) sets.push_back(static_cast<VulkanBindingSet*>(s)->handle());
  if (!sets.empty())
    vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR,
                            pipeline->layout().handle(), 0, uint32_t(sets.size()), sets.data(), 0,
                            nullptr);
  boundLayout_ = pipeline->layout().handle();
  boundStages_ = pipeline->layout().stages();
}

void VulkanCommandList::setComputeState(const rhi::ComputeState& state) {
  auto* pipeline = static_cast<VulkanComputePipeline*>(state.pipeline);
  transitionBindingSets(state.bindingSets);
  vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline->handle());
  std::vector<VkDescriptorSet> sets;
  for (auto* s : state.bindingSets) sets.push_back(static_cast<VulkanBindingSet*>(s)->handle());
  if (!sets.empty())
    vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE,
                            pipeline->layout().handle(), 0, uint32_t(sets.size()), sets.data(), 0,
                            nullptr);
  boundLayout_ = pipeline->layout().handle();
  boundStages_ = pipeline->layout().stages();
}

void VulkanCommandList::setGraphicsState(const rhi::GraphicsState& state) {
  auto* pipeline = static_cast<VulkanGraphicsPipeline*>(state.pipeline);
  transitionBindingSets(state.bindingSets);
  setBufferState(state.vertexBuffer, rhi::ResourceState::VertexInput);
  setBufferState(state.indexBuffer, rhi::ResourceState::VertexInput);
  vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->handle());
  std::vector<VkDescriptorSet> sets;
  for (auto* s : state.bindingSets) sets.push_back(static_cast<VulkanBindingSet*>(s)->handle());
  if (!sets.empty())
    vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS,
                            pipeline->layout().handle(), 0, uint32_t(sets.size()), sets.data(), 0,
                            nullptr);
  VkBuffer vertexBuffer = static_cast<VulkanBuffer*>(state.vertexBuffer)->handle();
  VkDeviceSize vertexOffset = state.vertexOffset;
  vkCmdBindVertexBuffers(commandBuffer_, 0, 1, &vertexBuffer, &vertexOffset);
  vkCmdBindIndexBuffer(commandBuffer_, static_cast<VulkanBuffer*>(state.indexBuffer)->handle(),
                       state.indexOffset,
                       state.indexFormat == rhi::Format::R32_UINT ? VK_INDEX_TYPE_UINT32
                                                                  : VK_INDEX_TYPE_UINT16);
  boundLayout_ = pipeline->layout().handle();
  boundStages_ = pipeline->layout().stages();
}

void VulkanCommandList::beginRendering(rhi::ITexture* target, const float* clearColor) {
  auto* t = static_cast<VulkanTexture*>(target);
  setTextureState(target, rhi::ResourceState::RenderTarget);
  VkRenderingAttachmentInfoKHR color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  color.imageView = t->view();
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = clearColor ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  if (clearColor)
    for (int i = 0; i < 4; ++i) color.clearValue.color.float32[i] = clearColor[i];
  const auto& d = target->desc();
  VkRenderingInfoKHR info{VK_STRUCTURE_TYPE_RENDERING_INFO_KHR};
  info.renderArea = {{0, 0}, {d.width, d.height}};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &color;
  vkCmdBeginRenderingKHR(commandBuffer_, &info);
  setViewport({0, 0, float(d.width), float(d.height)});
  setScissor({0, 0, d.width, d.height});
}

void VulkanCommandList::endRendering() {
  vkCmdEndRenderingKHR(commandBuffer_);
}

void VulkanCommandList::setViewport(const rhi::Viewport& viewport) {
  // Negative height (Vulkan 1.1): clip-space +y points up, as on D3D12.
  VkViewport v{viewport.x, viewport.y + viewport.height, viewport.width, -viewport.height, 0.0f, 1.0f};
  vkCmdSetViewport(commandBuffer_, 0, 1, &v);
}

void VulkanCommandList::setScissor(const rhi::ScissorRect& rect) {
  VkRect2D r{{rect.x, rect.y}, {rect.width, rect.height}};
  vkCmdSetScissor(commandBuffer_, 0, 1, &r);
}

void VulkanCommandList::drawIndexed(uint32_t indexCount, uint32_t firstIndex, int32_t vertexOffset) {
  vkCmdDrawIndexed(commandBuffer_, indexCount, 1, firstIndex, vertexOffset, 0);
}

void VulkanCommandList::setPushConstants(const void* data, size_t bytes) {
  vkCmdPushConstants(commandBuffer_, boundLayout_, boundStages_, 0, uint32_t(bytes), data);
}

void VulkanCommandList::dispatchRays(uint32_t width, uint32_t height, uint32_t depth) {
  vkCmdTraceRaysKHR(commandBuffer_, &boundRegions_.rayGen, &boundRegions_.miss, &boundRegions_.hit,
                    &boundRegions_.callable, width, height, depth);
}

void VulkanCommandList::dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
  vkCmdDispatch(commandBuffer_, groupsX, groupsY, groupsZ);
}

void VulkanCommandList::beginTimerQuery(rhi::ITimerQuery* query) {
  auto* q = static_cast<VulkanTimerQuery*>(query);
  vkCmdResetQueryPool(commandBuffer_, q->pool(), 0, 2);
  vkCmdWriteTimestamp(commandBuffer_, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, q->pool(), 0);
}

void VulkanCommandList::endTimerQuery(rhi::ITimerQuery* query) {
  auto* q = static_cast<VulkanTimerQuery*>(query);
  vkCmdWriteTimestamp(commandBuffer_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, q->pool(), 1);
}

}  // namespace penumbra::vk
