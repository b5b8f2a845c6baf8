#pragma once
// Vulkan entry points, loaded at run time from the system loader
// (libvulkan.so.1) through vkGetInstanceProcAddr. Debian ships no volk, and
// loading at run time lets a machine without a Vulkan loader get a clear
// error instead of failing to start.
//
// Every function is fetched with vkGetInstanceProcAddr, so device-level calls
// go through the loader's trampolines and work for any number of devices.
#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan.h>

#define PENUMBRA_VK_LOADER_FUNCTIONS(X) \
  X(vkCreateInstance)                   \
  X(vkEnumerateInstanceExtensionProperties) \
  X(vkEnumerateInstanceLayerProperties) \
  X(vkEnumerateInstanceVersion)

#define PENUMBRA_VK_INSTANCE_FUNCTIONS(X)      \
  X(vkDestroyInstance)                         \
  X(vkEnumeratePhysicalDevices)                \
  X(vkGetPhysicalDeviceProperties)             \
  X(vkGetPhysicalDeviceProperties2)            \
  X(vkGetPhysicalDeviceFeatures2)              \
  X(vkGetPhysicalDeviceMemoryProperties)       \
  X(vkGetPhysicalDeviceQueueFamilyProperties)  \
  X(vkEnumerateDeviceExtensionProperties)      \
  X(vkCreateDevice)                            \
  X(vkCreateDebugUtilsMessengerEXT)            \
  X(vkDestroyDebugUtilsMessengerEXT)           \
  X(vkSetDebugUtilsObjectNameEXT)              \
  X(vkDestroySurfaceKHR)                       \
  X(vkGetPhysicalDeviceSurfaceSupportKHR)      \
  X(vkGetPhysicalDeviceSurfaceCapabilitiesKHR) \
  X(vkGetPhysicalDeviceSurfaceFormatsKHR)      \
  X(vkGetPhysicalDeviceSurfacePresentModesKHR)

#define PENUMBRA_VK_DEVICE_FUNCTIONS(X)            \
  X(vkDestroyDevice)                               \
  X(vkGetDeviceQueue)                              \
  X(vkDeviceWaitIdle)                              \
  X(vkQueueSubmit)                                 \
  X(vkQueueWaitIdle)                               \
  X(vkCreateBuffer)                                \
  X(vkDestroyBuffer)                               \
  X(vkGetBufferMemoryRequirements)                 \
  X(vkAllocateMemory)                              \
  X(vkFreeMemory)                                  \
  X(vkBindBufferMemory)                            \
  X(vkBindImageMemory)                             \
  X(vkMapMemory)                                   \
  X(vkUnmapMemory)                                 \
  X(vkGetBufferDeviceAddress)                      \
  X(vkCreateImage)                                 \
  X(vkDestroyImage)                                \
  X(vkGetImageMemoryRequirements)                  \
  X(vkCreateImageView)                             \
  X(vkDestroyImageView)                            \
  X(vkCreateShaderModule)                          \
  X(vkDestroyShaderModule)                         \
  X(vkCreateDescriptorSetLayout)                   \
  X(vkDestroyDescriptorSetLayout)                  \
  X(vkCreatePipelineLayout)                        \
  X(vkDestroyPipelineLayout)                       \
  X(vkCreateComputePipelines)                      \
  X(vkDestroyPipeline)                             \
  X(vkCreateDescriptorPool)                        \
  X(vkDestroyDescriptorPool)                       \
  X(vkAllocateDescriptorSets)                      \
  X(vkUpdateDescriptorSets)                        \
  X(vkCreateCommandPool)                           \
  X(vkDestroyCommandPool)                          \
  X(vkResetCommandPool)                            \
  X(vkAllocateCommandBuffers)                      \
  X(vkBeginCommandBuffer)                          \
  X(vkEndCommandBuffer)                            \
  X(vkCreateFence)                                 \
  X(vkDestroyFence)                                \
  X(vkWaitForFences)                               \
  X(vkResetFences)                                 \
  X(vkCreateQueryPool)                             \
  X(vkDestroyQueryPool)                            \
  X(vkGetQueryPoolResults)                         \
  X(vkCmdResetQueryPool)                           \
  X(vkCmdWriteTimestamp)                           \
  X(vkCmdPipelineBarrier)                          \
  X(vkCmdCopyBuffer)                               \
  X(vkCmdCopyImageToBuffer)                        \
  X(vkCmdCopyBufferToImage)                        \
  X(vkCreateSampler)                               \
  X(vkDestroySampler)                              \
  X(vkCmdClearColorImage)                          \
  X(vkCmdFillBuffer)                               \
  X(vkCmdBindPipeline)                             \
  X(vkCmdBindDescriptorSets)                       \
  X(vkCmdPushConstants)                            \
  X(vkCmdDispatch)                                 \
  X(vkCreateGraphicsPipelines)                     \
  X(vkCmdBindVertexBuffers)                        \
  X(vkCmdBindIndexBuffer)                          \
  X(vkCmdSetViewport)                              \
  X(vkCmdSetScissor)                               \
  X(vkCmdDrawIndexed)                              \
  X(vkCmdBeginRenderingKHR)                        \
  X(vkCmdEndRenderingKHR)                          \
  X(vkCreateAccelerationStructureKHR)              \
  X(vkDestroyAccelerationStructureKHR)             \
  X(vkGetAccelerationStructureBuildSizesKHR)       \
  X(vkGetAccelerationStructureDeviceAddressKHR)    \
  X(vkCmdBuildAccelerationStructuresKHR)           \
  X(vkCreateRayTracingPipelinesKHR)                \
  X(vkGetRayTracingShaderGroupHandlesKHR)          \
  X(vkCmdTraceRaysKHR)                             \
  X(vkCmdCopyImage)                                \
  X(vkCmdBlitImage)                                \
  X(vkCreateSemaphore)                             \
  X(vkDestroySemaphore)                            \
  X(vkCreateSwapchainKHR)                          \
  X(vkDestroySwapchainKHR)                         \
  X(vkGetSwapchainImagesKHR)                       \
  X(vkAcquireNextImageKHR)                         \
  X(vkQueuePresentKHR)

namespace penumbra::vk {
#define PENUMBRA_VK_DECLARE(name) extern PFN_##name name;
PENUMBRA_VK_LOADER_FUNCTIONS(PENUMBRA_VK_DECLARE)
PENUMBRA_VK_INSTANCE_FUNCTIONS(PENUMBRA_VK_DECLARE)
PENUMBRA_VK_DEVICE_FUNCTIONS(PENUMBRA_VK_DECLARE)
#undef PENUMBRA_VK_DECLARE

// Opens the loader and fetches the global functions. Throws penumbra::Error
// with a one-line reason when no Vulkan loader is installed.
void loadLoader();
// Fetches every instance- and device-level function through `instance`.
void loadInstanceFunctions(VkInstance instance);
// The loader's vkGetInstanceProcAddr (after loadLoader): window-system
// functions whose prototypes need platform headers, and the viewer's UI
// renderer, load through it.
PFN_vkGetInstanceProcAddr instanceProcAddr();

// Throws penumbra::Error("<what>: <VkResult name>") unless result is VK_SUCCESS.
void check(VkResult result, const char* what);
const char* resultName(VkResult result);
}  // namespace penumbra::vk
