#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "penumbra/rhi/fault_injection.h"
#include "penumbra/util/error.h"
#include "vulkan_backend.h"
#include "vulkan_surface.h"
#include "vulkan_swapchain.h"

namespace penumbra::vk {

namespace {
bool hasDeviceExtension(VkPhysicalDevice physical, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data());
  for (const auto& e : exts)
    if (std::string_view(e.extensionName) == name) return true;
  return false;
}
// The queue family the device uses: ray tracing runs on any queue with
// compute; the universal queue is preferred, which presentation (the
// viewer) will want too.
uint32_t chooseQueueFamily(VkPhysicalDevice physicalDevice, const std::string& adapterName,
                           VkQueueFamilyProperties& chosen) {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
  int family = -1;
  for (uint32_t i = 0; i < familyCount; ++i) {
    const auto flags = families[i].queueFlags;
    if ((flags & VK_QUEUE_COMPUTE_BIT) && (family < 0 || (flags & VK_QUEUE_GRAPHICS_BIT))) {
      if (family < 0 || !(families[family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) family = int(i);
    }
  }
  if (family < 0) throw Error(fmt::format("vulkan: {} has no compute queue", adapterName));
  chosen = families[size_t(family)];
  return uint32_t(family);
}

// One queue does everything (ray tracing, the UI, presentation), so the
// chosen family must also present to this window.
void requirePresentation(VkInstance instance, VkPhysicalDevice physicalDevice, uint32_t family,
                         const rhi::NativeWindow& window, const std::string& adapterName) {
  VulkanSurface probe(instance, window);
  VkBool32 supported = VK_FALSE;
  check(vkGetPhysicalDeviceSurfaceSupportKHR(physicalDevice, family, probe.handle(), &supported),
        "vkGetPhysicalDeviceSurfaceSupportKHR");
  if (!supported)
    throw Error(fmt::format("vulkan: the queue family {} of {} cannot present to this {} window",
                            family, adapterName, rhi::windowSystemName(window.system)));
}

// Bindless texture arrays (rhi::BindingLayoutItem::arraySize == 0) index
// runtime-sized arrays of sampled images and samplers with nonuniformEXT,
// and bind only the elements a binding set fills.
void requireBindlessFeatures(VkPhysicalDevice physicalDevice, const std::string& adapterName) {
  VkPhysicalDeviceVulkan12Features supported12{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  supported.pNext = &supported12;
  vkGetPhysicalDeviceFeatures2(physicalDevice, &supported);
  std::string missing;
  for (auto [have, name] :
       {std::pair{supported12.runtimeDescriptorArray, "runtimeDescriptorArray"},
        std::pair{supported12.shaderSampledImageArrayNonUniformIndexing,
                  "shaderSampledImageArrayNonUniformIndexing"},
        std::pair{supported12.descriptorBindingPartiallyBound, "descriptorBindingPartiallyBound"}})
    if (!have) missing += (missing.empty() ? "" : ", ") + std::string(name);
  if (!missing.empty())
    throw Error(
        fmt::format("vulkan: {} lacks the descriptor-indexing features bindless textures need: {}",
                    adapterName, missing));
}
}  // namespace

VulkanDevice::VulkanDevice(std::shared_ptr<VulkanInstance> instance,
                           VkPhysicalDevice physicalDevice, rhi::AdapterInfo adapter,
                           const rhi::NativeWindow& presentWindow)
    : instance_(std::move(instance)),
      physicalDevice_(physicalDevice),
      adapter_(std::move(adapter)) {
  validationBaseline_ = instance_->validationMessages();
  VkQueueFamilyProperties familyProperties{};
  const uint32_t family = chooseQueueFamily(physicalDevice_, adapter_.name, familyProperties);
  queueFamily_ = family;
  shaderStages_ = VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  if (familyProperties.queueFlags & VK_QUEUE_GRAPHICS_BIT)
    shaderStages_ |= VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  timestampValidBits_ = familyProperties.timestampValidBits;

  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(physicalDevice_, &props);
  timestampPeriodNs_ = props.limits.timestampPeriod;
  limits_ = props.limits;
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);

  VkPhysicalDeviceAccelerationStructurePropertiesKHR asProps{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props2.pNext = &asProps;
  vkGetPhysicalDeviceProperties2(physicalDevice_, &props2);
  scratchAlignment_ = std::max<uint64_t>(asProps.minAccelerationStructureScratchOffsetAlignment, 1);

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  std::vector<const char*> extensions = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                         VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                         VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
  if (presentWindow.system != rhi::WindowSystem::None) {
    // One queue does everything (ray tracing, the UI, presentation), so the
    // queue chosen above must also present to this window.
    if (!hasDeviceExtension(physicalDevice_, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
      throw Error(fmt::format("vulkan: {} cannot present (no VK_KHR_swapchain)", adapter_.name));
    requirePresentation(instance_->handle(), physicalDevice_, queueFamily_, presentWindow,
                        adapter_.name);
    extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    canPresent_ = true;
  }

  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rtFeatures{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  rtFeatures.rayTracingPipeline = VK_TRUE;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR asFeatures{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  asFeatures.accelerationStructure = VK_TRUE;
  // Bindless texture arrays (rhi::BindingLayoutItem::arraySize == 0) index
  // runtime-sized arrays of sampled images and samplers with nonuniformEXT,
  // and bind only the elements a binding set fills.
  requireBindlessFeatures(physicalDevice_, adapter_.name);
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  v12.bufferDeviceAddress = VK_TRUE;
  v12.runtimeDescriptorArray = VK_TRUE;
  v12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
  v12.descriptorBindingPartiallyBound = VK_TRUE;
  rtFeatures.pNext = &asFeatures;
  asFeatures.pNext = &v12;
  // The raster subset draws with dynamic rendering (core in Vulkan 1.3; the
  // instance asks for 1.2, so through the extension). Optional: without it,
  // only createGraphicsPipeline fails.
  VkPhysicalDeviceDynamicRenderingFeaturesKHR dynamicRendering{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
  if ((familyProperties.queueFlags & VK_QUEUE_GRAPHICS_BIT) &&
      hasDeviceExtension(physicalDevice_, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME)) {
    VkPhysicalDeviceDynamicRenderingFeaturesKHR supportedDynamic{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
    VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    query.pNext = &supportedDynamic;
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &query);
    if (supportedDynamic.dynamicRendering) {
      dynamicRendering.dynamicRendering = VK_TRUE;
      v12.pNext = &dynamicRendering;
      extensions.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);
      dynamicRendering_ = true;
    }
  }
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &rtFeatures;

  VkDeviceCreateInfo create{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  create.pNext = &features;
  create.queueCreateInfoCount = 1;
  create.pQueueCreateInfos = &queueInfo;
  create.enabledExtensionCount = uint32_t(extensions.size());
  create.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physicalDevice_, &create, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  setName(VK_OBJECT_TYPE_DEVICE, uint64_t(device_), adapter_.name);
  setName(VK_OBJECT_TYPE_QUEUE, uint64_t(queue_), "main queue");
}

VulkanDevice::~VulkanDevice() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyDevice(device_, nullptr);
  }
}

void VulkanDevice::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
  if (!instance_->hasDebugUtils() || name.empty() || !vkSetDebugUtilsObjectNameEXT) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  vkSetDebugUtilsObjectNameEXT(device_, &info);
}

uint32_t VulkanDevice::memoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                  VkMemoryPropertyFlags preferred) const {
  for (VkMemoryPropertyFlags wanted : {required | preferred, required}) {
    for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i) {
      if ((typeBits & (1u << i)) &&
          (memoryProperties_.memoryTypes[i].propertyFlags & wanted) == wanted)
        return i;
    }
  }
  throw Error(fmt::format("vulkan: {} has no memory type with properties 0x{:x}", adapter_.name,
                          required));
}

rhi::BufferHandle VulkanDevice::createBuffer(const rhi::BufferDesc& desc) {
  return std::make_shared<VulkanBuffer>(*this, desc);
}

rhi::TextureHandle VulkanDevice::createTexture(const rhi::TextureDesc& desc) {
  return std::make_shared<VulkanTexture>(*this, desc);
}

rhi::SamplerHandle VulkanDevice::createSampler(const rhi::SamplerDesc& desc) {
  return std::make_shared<VulkanSampler>(*this, desc);
}

uint32_t VulkanDevice::bindlessCapacity(rhi::ResourceType type) const {
  uint32_t limit = rhi::kMaxBindlessDescriptors;
  switch (type) {
    case rhi::ResourceType::SampledTexture:
      limit = std::min({limit, limits_.maxPerStageDescriptorSampledImages, limits_.maxDescriptorSetSampledImages});
      break;
    case rhi::ResourceType::Sampler:
      limit = std::min({limit, limits_.maxPerStageDescriptorSamplers, limits_.maxDescriptorSetSamplers});
      break;
    case rhi::ResourceType::StorageBuffer:
      limit = std::min({limit, limits_.maxPerStageDescriptorStorageBuffers,
                        limits_.maxDescriptorSetStorageBuffers});
      break;
    case rhi::ResourceType::ConstantBuffer:
      limit = std::min({limit, limits_.maxPerStageDescriptorUniformBuffers,
                        limits_.maxDescriptorSetUniformBuffers});
      break;
    case rhi::ResourceType::StorageTexture:
      limit = std::min({limit, limits_.maxPerStageDescriptorStorageImages,
                        limits_.maxDescriptorSetStorageImages});
      break;
    case rhi::ResourceType::AccelStruct: break;
  }
  return std::min(limit, limits_.maxPerStageResources);
}

rhi::rt::AccelStructHandle VulkanDevice::createAccelStruct(const rhi::rt::AccelStructDesc& desc) {
  return std::make_shared<VulkanAccelStruct>(*this, desc);
}

rhi::RayTracingPipelineHandle VulkanDevice::createRayTracingPipeline(
    const rhi::RayTracingPipelineDesc& desc) {
  return std::make_shared<VulkanRayTracingPipeline>(*this, desc);
}

rhi::ComputePipelineHandle VulkanDevice::createComputePipeline(const rhi::ComputePipelineDesc& desc) {
  return std::make_shared<VulkanComputePipeline>(*this, desc);
}

rhi::GraphicsPipelineHandle VulkanDevice::createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) {
  if (!dynamicRendering_)
    throw Error(fmt::format("vulkan: {} cannot draw: its queue has no graphics or it lacks "
                            "VK_KHR_dynamic_rendering",
                            adapter_.name));
  return std::make_shared<VulkanGraphicsPipeline>(*this, desc);
}

rhi::BindingSetHandle VulkanDevice::createBindingSet(const rhi::BindingSetDesc& desc,
                                                     const rhi::IPipeline& pipeline) {
  const VulkanPipelineLayout* layout = nullptr;
  if (auto* rt = dynamic_cast<const VulkanRayTracingPipeline*>(&pipeline))
    layout = &rt->layout();
  else if (auto* cs = dynamic_cast<const VulkanComputePipeline*>(&pipeline))
    layout = &cs->layout();
  else if (auto* gp = dynamic_cast<const VulkanGraphicsPipeline*>(&pipeline))
    layout = &gp->layout();
  else
    throw Error("vulkan: createBindingSet needs a pipeline of this device's backend");
  return std::make_shared<VulkanBindingSet>(*this, desc, *layout);
}

rhi::TimerQueryHandle VulkanDevice::createTimerQuery() {
  if (timestampValidBits_ == 0)
    throw Error(fmt::format("vulkan: {} does not support timestamps on its queue", adapter_.name));
  return std::make_shared<VulkanTimerQuery>(*this);
}

rhi::CommandListHandle VulkanDevice::createCommandList(const std::string& debugName) {
  return std::make_shared<VulkanCommandList>(*this, debugName);
}

rhi::SwapchainHandle VulkanDevice::createSwapchain(const rhi::SwapchainDesc& desc) {
  if (!canPresent_)
    throw Error("vulkan: createSwapchain on a device created without presentWindow");
  return std::make_shared<VulkanSwapchain>(*this, desc);
}

void VulkanDevice::submit(rhi::ICommandList* commandList) {
  submit(commandList, VK_NULL_HANDLE, VK_NULL_HANDLE);
}

void VulkanDevice::submit(rhi::ICommandList* commandList, VkSemaphore wait, VkSemaphore signal) {
  auto* list = static_cast<VulkanCommandList*>(commandList);
  VkCommandBuffer cb = list->handle();
  VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  info.commandBufferCount = 1;
  info.pCommandBuffers = &cb;
  // The whole list waits for the acquired image: its first command may
  // already be the back buffer's layout transition.
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
  if (wait) {
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &wait;
    info.pWaitDstStageMask = &waitStage;
  }
  if (signal) {
    info.signalSemaphoreCount = 1;
    info.pSignalSemaphores = &signal;
  }
  VkFence fence = list->fence();
  check(vkResetFences(device_, 1, &fence), "vkResetFences");
  const VkResult submitted = rhi::faults::shouldFail(rhi::faults::Site::Submit)
                                 ? VK_ERROR_DEVICE_LOST
                                 : vkQueueSubmit(queue_, 1, &info, fence);
  // Nothing will signal the fence of a submission that did not happen; the
  // list's next open() and its destructor wait on it.
  if (submitted != VK_SUCCESS) list->replaceFenceSignaled();
  checkDevice(submitted, fmt::format("submitting command list '{}'", list->debugName()).c_str());
  // A viewer resubmits the same few lists every frame; list them once.
  if (std::find(inFlight_.begin(), inFlight_.end(), list) == inFlight_.end()) inFlight_.push_back(list);
}

void VulkanDevice::checkDevice(VkResult result, const char* what) const {
  if (result == VK_ERROR_DEVICE_LOST)
    throw Error(fmt::format("vulkan: the device {} was lost {} (VK_ERROR_DEVICE_LOST): the GPU hung "
                            "or was reset, or its driver failed; nothing more can run on it",
                            adapter_.name, what));
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw Error(fmt::format("vulkan: out of {} memory {} on {} ({})",
                            result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "device" : "host", what,
                            adapter_.name, resultName(result)));
  check(result, what);
}

void VulkanDevice::waitForIdle() {
  checkDevice(vkQueueWaitIdle(queue_), "waiting for the GPU to finish (vkQueueWaitIdle)");
  for (auto* list : inFlight_) list->releaseTransientResources();
  inFlight_.clear();
}

void VulkanDevice::forgetSubmitted(VulkanCommandList* list) {
  inFlight_.erase(std::remove(inFlight_.begin(), inFlight_.end(), list), inFlight_.end());
}

double VulkanDevice::timerQuerySeconds(rhi::ITimerQuery* query) {
  auto* q = static_cast<VulkanTimerQuery*>(query);
  uint64_t ticks[2] = {};
  check(vkGetQueryPoolResults(device_, q->pool(), 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults");
  const uint64_t mask = timestampValidBits_ >= 64 ? ~0ull : ((1ull << timestampValidBits_) - 1);
  const uint64_t delta = ((ticks[1] & mask) - (ticks[0] & mask)) & mask;
  return double(delta) * timestampPeriodNs_ * 1e-9;
}

VulkanTimerQuery::VulkanTimerQuery(VulkanDevice& device) : device_(device) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2;
  check(vkCreateQueryPool(device_.handle(), &info, nullptr, &pool_), "vkCreateQueryPool");
}

VulkanTimerQuery::~VulkanTimerQuery() { vkDestroyQueryPool(device_.handle(), pool_, nullptr); }

}  // namespace penumbra::vk
