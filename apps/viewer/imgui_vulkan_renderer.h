#pragma once
// Dear ImGui drawn into the back buffer with Debian's imgui_impl_vulkan
// (compiled into the viewer with IMGUI_IMPL_VULKAN_NO_PROTOTYPES, so it loads
// its functions from the same loader the RHI opened). The RHI has no raster
// pipelines, so this records native Vulkan commands into the frame's command
// list (backends/vulkan/vulkan_interop.h), between the RHI's barriers.
#include <map>

#include "rhi/rhi.h"
#include "vulkan/vulkan_interop.h"

namespace penumbra::viewer {

class ImGuiVulkanRenderer {
 public:
  // Call after ImGui::CreateContext and ImGui_ImplGlfw_InitForVulkan.
  ImGuiVulkanRenderer(rhi::IDevice& device, rhi::ISwapchain& swapchain);
  ~ImGuiVulkanRenderer();
  ImGuiVulkanRenderer(const ImGuiVulkanRenderer&) = delete;
  ImGuiVulkanRenderer& operator=(const ImGuiVulkanRenderer&) = delete;

  void newFrame();
  // Draws ImGui::GetDrawData() over `backBuffer`, which must be in
  // ResourceState::RenderTarget.
  void render(rhi::ICommandList& commandList, rhi::ITexture& backBuffer);
  // After ISwapchain::resize: the old framebuffers refer to destroyed views.
  void swapchainResized();

 private:
  struct Functions;
  rhi::IDevice& device_;
  rhi::ISwapchain& swapchain_;
  vk::interop::DeviceHandles handles_;
  std::unique_ptr<Functions> fn_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  std::map<VkImageView, VkFramebuffer> framebuffers_;
};

}  // namespace penumbra::viewer
