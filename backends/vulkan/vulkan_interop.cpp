#include "vulkan_interop.h"

#include "rhi/validation.h"
#include "util/error.h"
#include "vulkan_backend.h"

namespace penumbra::vk::interop {
namespace {
template <class Derived, class Base>
Derived& backendObject(Base& object, const char* what) {
  auto* derived = dynamic_cast<Derived*>(&rhi::validation::backendObject(object));
  if (!derived) throw Error(std::string("vulkan interop: the ") + what + " is not a Vulkan one");
  return *derived;
}
}  // namespace

DeviceHandles deviceHandles(rhi::IDevice& device) {
  auto& vkDevice = backendObject<VulkanDevice>(device, "device");
  DeviceHandles handles;
  handles.instance = vkDevice.instance();
  handles.physicalDevice = vkDevice.physicalDevice();
  handles.device = vkDevice.handle();
  handles.queueFamily = vkDevice.queueFamily();
  handles.queue = vkDevice.queue();
  handles.getInstanceProcAddr = instanceProcAddr();
  return handles;
}

VkCommandBuffer commandBuffer(rhi::ICommandList& commandList) {
  return backendObject<VulkanCommandList>(commandList, "command list").handle();
}

VkImageView imageView(rhi::ITexture& texture) {
  auto* vkTexture = dynamic_cast<VulkanTexture*>(&texture);
  if (!vkTexture) throw Error("vulkan interop: the texture is not a Vulkan one");
  return vkTexture->view();
}

}  // namespace penumbra::vk::interop
