#pragma once
// VK_KHR_swapchain behind rhi::ISwapchain.
#include <memory>
#include <vector>

#include "penumbra/rhi/presentation.h"
#include "vulkan_backend.h"
#include "vulkan_surface.h"

namespace penumbra::vk {

class VulkanSwapchain final : public rhi::ISwapchain {
 public:
  VulkanSwapchain(VulkanDevice& device, const rhi::SwapchainDesc& desc);
  ~VulkanSwapchain() override;
  const rhi::SwapchainDesc& desc() const override { return desc_; }
  rhi::Format format() const override { return format_; }
  rhi::ITexture* acquireNextImage() override;
  bool present(rhi::ICommandList* commandList) override;
  void resize(uint32_t width, uint32_t height) override;
  void setVsync(bool vsync) override;
  uint32_t imageCount() const override { return uint32_t(images_.size()); }


 private:
  void create();
  void destroyImages();
  VkPresentModeKHR choosePresentMode() const;
  VulkanDevice& device_;
  rhi::SwapchainDesc desc_;
  std::unique_ptr<VulkanSurface> surface_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat vkFormat_ = VK_FORMAT_UNDEFINED;
  rhi::Format format_ = rhi::Format::Unknown;
  std::vector<std::unique_ptr<VulkanTexture>> images_;
  std::vector<VkSemaphore> renderFinished_;  // per image: the present waits on it
  std::vector<VkSemaphore> imageAcquired_;   // per frame slot
  std::vector<VkFence> slotDone_;            // per frame slot: its last frame finished
  uint32_t slot_ = 0;
  uint32_t imageIndex_ = 0;
  bool acquired_ = false;
};

}  // namespace penumbra::vk
