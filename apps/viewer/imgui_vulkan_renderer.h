#pragma once
// Dear ImGui drawn into the viewer's RGBA8 display texture with Debian's imgui_impl_vulkan
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
  // Call after ImGui::CreateContext (and ImGui_ImplGlfw_InitForVulkan when
  // there is a window). Up to `framesInFlight` frames may be recorded before
  // the first of them finishes.
  ImGuiVulkanRenderer(rhi::IDevice& device, uint32_t framesInFlight);
  ~ImGuiVulkanRenderer();
  ImGuiVulkanRenderer(const ImGuiVulkanRenderer&) = delete;
  ImGuiVulkanRenderer& operator=(const ImGuiVulkanRenderer&) = delete;

  void newFrame();
  // Draws ImGui::GetDrawData() over `target`, an RGBA8_UNORM texture with
  // RenderTarget usage, in ResourceState::RenderTarget. The same target
  // whether the frame is then presented or read back, so a capture shows
  // exactly what the window does.
  void render(rhi::ICommandList& commandList, rhi::ITexture& target);
  // Before a target is destroyed: its framebuffer refers to its view.
  void forgetTargets();

 private:
  struct Functions;
  rhi::IDevice& device_;
  vk::interop::DeviceHandles handles_;
  std::unique_ptr<Functions> fn_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  std::map<VkImageView, VkFramebuffer> framebuffers_;
};

}  // namespace penumbra::viewer
