#pragma once
// Native Vulkan handles behind RHI objects, for code that must record Vulkan
// commands itself: the viewer's Dear ImGui renderer (imgui_impl_vulkan), which
// draws with a render pass the RHI has no notion of. NVRHI offers the same
// through getNativeObject. Each function throws penumbra::Error when the object
// does not belong to the Vulkan backend.
#include "rhi/rhi.h"
#include "vulkan_functions.h"

namespace penumbra::vk::interop {

struct DeviceHandles {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  // The loader's entry point: everything else is fetched through it.
  PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
};

DeviceHandles deviceHandles(rhi::IDevice& device);
// The command buffer an open command list records into.
VkCommandBuffer commandBuffer(rhi::ICommandList& commandList);
VkImageView imageView(rhi::ITexture& texture);

}  // namespace penumbra::vk::interop
