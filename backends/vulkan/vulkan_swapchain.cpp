#include "vulkan_swapchain.h"

#include <fmt/format.h>

#include <algorithm>

#include "penumbra/util/error.h"
#include "penumbra/util/log.h"

namespace penumbra::vk {

VulkanSwapchain::VulkanSwapchain(VulkanDevice& device, const rhi::SwapchainDesc& desc)
    : device_(device), desc_(desc) {
  if (desc_.framesInFlight < 1 || desc_.framesInFlight > 4)
    throw Error(fmt::format("vulkan: {} frames in flight is outside 1..4", desc_.framesInFlight));
  surface_ = std::make_unique<VulkanSurface>(device_.instance(), desc_.window);
  VkBool32 supported = VK_FALSE;
  check(vkGetPhysicalDeviceSurfaceSupportKHR(device_.physicalDevice(), device_.queueFamily(),
                                             surface_->handle(), &supported),
        "vkGetPhysicalDeviceSurfaceSupportKHR");
  if (!supported) throw Error("vulkan: the device's queue cannot present to this window");

  VkDevice dev = device_.handle();
  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  imageAcquired_.resize(desc_.framesInFlight);
  slotDone_.resize(desc_.framesInFlight);
  for (uint32_t i = 0; i < desc_.framesInFlight; ++i) {
    check(vkCreateSemaphore(dev, &semaphoreInfo, nullptr, &imageAcquired_[i]), "vkCreateSemaphore");
    check(vkCreateFence(dev, &fenceInfo, nullptr, &slotDone_[i]), "vkCreateFence");
    device_.setName(VK_OBJECT_TYPE_SEMAPHORE, uint64_t(imageAcquired_[i]),
                    fmt::format("{} image acquired {}", desc_.debugName, i));
    device_.setName(VK_OBJECT_TYPE_FENCE, uint64_t(slotDone_[i]),
                    fmt::format("{} frame slot {}", desc_.debugName, i));
  }
  create();
}

VulkanSwapchain::~VulkanSwapchain() {
  VkDevice dev = device_.handle();
  vkDeviceWaitIdle(dev);
  destroyImages();
  if (swapchain_) vkDestroySwapchainKHR(dev, swapchain_, nullptr);
  for (VkSemaphore s : imageAcquired_) vkDestroySemaphore(dev, s, nullptr);
  for (VkFence f : slotDone_) vkDestroyFence(dev, f, nullptr);
}

VkPresentModeKHR VulkanSwapchain::choosePresentMode() const {
  if (desc_.vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always available
  uint32_t count = 0;
  vkGetPhysicalDeviceSurfacePresentModesKHR(device_.physicalDevice(), surface_->handle(), &count,
                                            nullptr);
  std::vector<VkPresentModeKHR> modes(count);
  vkGetPhysicalDeviceSurfacePresentModesKHR(device_.physicalDevice(), surface_->handle(), &count,
                                            modes.data());
  // Without vsync: never wait for a vertical blank; MAILBOX avoids tearing.
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;
}

void VulkanSwapchain::destroyImages() {
  VkDevice dev = device_.handle();
  images_.clear();
  for (VkSemaphore s : renderFinished_) vkDestroySemaphore(dev, s, nullptr);
  renderFinished_.clear();
}

void VulkanSwapchain::create() {
  VkPhysicalDevice physical = device_.physicalDevice();
  VkSurfaceCapabilitiesKHR caps{};
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_->handle(), &caps),
        "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  constexpr VkImageUsageFlags kUsage =
      VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if ((caps.supportedUsageFlags & kUsage) != kUsage)
    throw Error("vulkan: the window's swapchain images cannot be copied to and drawn into");

  uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface_->handle(), &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface_->handle(), &count, formats.data());
  // UNORM, not SRGB: the tonemapper writes sRGB-encoded values already, and
  // Dear ImGui's colours are meant for a UNORM target.
  vkFormat_ = VK_FORMAT_UNDEFINED;
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
    for (const auto& f : formats)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
        vkFormat_ = wanted;
    if (vkFormat_ != VK_FORMAT_UNDEFINED) break;
  }
  if (vkFormat_ == VK_FORMAT_UNDEFINED)
    throw Error("vulkan: the window offers neither B8G8R8A8_UNORM nor R8G8B8A8_UNORM");
  format_ =
      vkFormat_ == VK_FORMAT_B8G8R8A8_UNORM ? rhi::Format::BGRA8_UNORM : rhi::Format::RGBA8_UNORM;

  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) {  // the window takes the swapchain's size (Wayland)
    extent.width = std::clamp(desc_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height =
        std::clamp(desc_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  desc_.width = extent.width;
  desc_.height = extent.height;
  // One image more than the frames in flight, so acquiring never waits for
  // the image on screen.
  uint32_t images = std::max(caps.minImageCount, desc_.framesInFlight + 1);
  if (caps.maxImageCount > 0) images = std::min(images, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_->handle();
  info.minImageCount = images;
  info.imageFormat = vkFormat_;
  info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = kUsage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                          ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                          : caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  for (VkCompositeAlphaFlagBitsKHR mode :
       {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR}) {
    if (caps.supportedCompositeAlpha & mode) {
      info.compositeAlpha = mode;
      break;
    }
  }
  info.presentMode = choosePresentMode();
  info.clipped = VK_TRUE;
  VkSwapchainKHR old = swapchain_;
  info.oldSwapchain = old;
  VkDevice dev = device_.handle();
  check(vkCreateSwapchainKHR(dev, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
  if (old) vkDestroySwapchainKHR(dev, old, nullptr);
  device_.setName(VK_OBJECT_TYPE_SWAPCHAIN_KHR, uint64_t(swapchain_), desc_.debugName);

  check(vkGetSwapchainImagesKHR(dev, swapchain_, &count, nullptr), "vkGetSwapchainImagesKHR");
  std::vector<VkImage> handles(count);
  check(vkGetSwapchainImagesKHR(dev, swapchain_, &count, handles.data()),
        "vkGetSwapchainImagesKHR");
  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  for (uint32_t i = 0; i < count; ++i) {
    rhi::TextureDesc texture;
    texture.width = extent.width;
    texture.height = extent.height;
    texture.format = format_;
    texture.usage = rhi::TextureUsage::CopyDest | rhi::TextureUsage::RenderTarget;
    texture.debugName = fmt::format("{} image {}", desc_.debugName, i);
    images_.push_back(std::make_unique<VulkanTexture>(device_, texture, handles[i]));
    VkSemaphore semaphore = VK_NULL_HANDLE;
    check(vkCreateSemaphore(dev, &semaphoreInfo, nullptr, &semaphore), "vkCreateSemaphore");
    device_.setName(VK_OBJECT_TYPE_SEMAPHORE, uint64_t(semaphore),
                    fmt::format("{} render finished {}", desc_.debugName, i));
    renderFinished_.push_back(semaphore);
  }
}

rhi::ITexture* VulkanSwapchain::acquireNextImage() {
  if (acquired_) throw Error("vulkan: acquireNextImage twice without present");
  VkDevice dev = device_.handle();
  device_.checkDevice(vkWaitForFences(dev, 1, &slotDone_[slot_], VK_TRUE, UINT64_MAX),
                      "waiting for a frame slot (vkWaitForFences)");
  VkResult result = vkAcquireNextImageKHR(dev, swapchain_, UINT64_MAX, imageAcquired_[slot_],
                                          VK_NULL_HANDLE, &imageIndex_);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return nullptr;
  // SUBOPTIMAL still signals the semaphore: use the image, present() reports it.
  if (result != VK_SUBOPTIMAL_KHR) check(result, "vkAcquireNextImageKHR");
  acquired_ = true;
  auto* image = images_[imageIndex_].get();
  image->state = rhi::ResourceState::Undefined;  // the old contents are not needed
  return image;
}

bool VulkanSwapchain::present(rhi::ICommandList* commandList) {
  if (!acquired_) throw Error("vulkan: present without acquireNextImage");
  acquired_ = false;
  if (images_[imageIndex_]->state != rhi::ResourceState::Present)
    throw Error(
        "vulkan: present: the command list must leave the back buffer in ResourceState::Present");
  VkSemaphore finished = renderFinished_[imageIndex_];
  device_.submit(commandList, imageAcquired_[slot_], finished);
  // An empty submission signals the slot's fence once everything before it
  // (this frame) has finished: frame pacing independent of the caller's lists.
  VkDevice dev = device_.handle();
  check(vkResetFences(dev, 1, &slotDone_[slot_]), "vkResetFences");
  check(vkQueueSubmit(device_.queue(), 0, nullptr, slotDone_[slot_]),
        "vkQueueSubmit (frame fence)");

  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &finished;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &imageIndex_;
  VkResult result = vkQueuePresentKHR(device_.queue(), &info);
  slot_ = (slot_ + 1) % desc_.framesInFlight;
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
  check(result, "vkQueuePresentKHR");
  return true;
}

void VulkanSwapchain::resize(uint32_t width, uint32_t height) {
  if (acquired_) throw Error("vulkan: resize between acquireNextImage and present");
  device_.waitForIdle();
  desc_.width = width;
  desc_.height = height;
  destroyImages();
  create();
}

void VulkanSwapchain::setVsync(bool vsync) {
  if (vsync == desc_.vsync) return;
  desc_.vsync = vsync;
  resize(desc_.width, desc_.height);
}

}  // namespace penumbra::vk
