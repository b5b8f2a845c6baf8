#include "imgui_vulkan_renderer.h"

#include <fmt/format.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "backends/imgui_impl_vulkan.h"
#include "util/error.h"

namespace penumbra::viewer {
namespace {

void checkResult(VkResult result) {
  if (result != VK_SUCCESS) throw Error(fmt::format("imgui vulkan: VkResult {}", int(result)));
}

// imgui_impl_vulkan loads the WSI functions of its ImGui_ImplVulkanH_*
// window helpers too, and fails when any is missing; an offscreen device
// enables no surface or swapchain extension, so the loader has none. The
// renderer never calls them (the RHI owns the swapchain): they get this.
[[noreturn]] void unusedWsiFunction() {
  std::fprintf(stderr, "imgui vulkan: a window-system function was called without a window\n");
  std::abort();
}

bool isWsiFunction(const char* name) {
  const std::string_view n(name);
  return n.find("Surface") != std::string_view::npos ||
         n.find("Swapchain") != std::string_view::npos || n == "vkAcquireNextImageKHR" ||
         n == "vkQueuePresentKHR";
}

}  // namespace

// The few Vulkan functions this file calls itself, from the RHI's loader.
struct ImGuiVulkanRenderer::Functions {
  PFN_vkCreateRenderPass createRenderPass;
  PFN_vkDestroyRenderPass destroyRenderPass;
  PFN_vkCreateFramebuffer createFramebuffer;
  PFN_vkDestroyFramebuffer destroyFramebuffer;
  PFN_vkCreateDescriptorPool createDescriptorPool;
  PFN_vkDestroyDescriptorPool destroyDescriptorPool;
  PFN_vkCmdBeginRenderPass cmdBeginRenderPass;
  PFN_vkCmdEndRenderPass cmdEndRenderPass;
};

ImGuiVulkanRenderer::ImGuiVulkanRenderer(rhi::IDevice& device, uint32_t framesInFlight)
    : device_(device), handles_(vk::interop::deviceHandles(device)) {
  auto load = [&](const char* name) {
    auto function = handles_.getInstanceProcAddr(handles_.instance, name);
    if (!function) throw Error(fmt::format("imgui vulkan: the loader has no {}", name));
    return function;
  };
  fn_ = std::make_unique<Functions>();
#define PENUMBRA_LOAD(member, name) fn_->member = reinterpret_cast<PFN_##name>(load(#name))
  PENUMBRA_LOAD(createRenderPass, vkCreateRenderPass);
  PENUMBRA_LOAD(destroyRenderPass, vkDestroyRenderPass);
  PENUMBRA_LOAD(createFramebuffer, vkCreateFramebuffer);
  PENUMBRA_LOAD(destroyFramebuffer, vkDestroyFramebuffer);
  PENUMBRA_LOAD(createDescriptorPool, vkCreateDescriptorPool);
  PENUMBRA_LOAD(destroyDescriptorPool, vkDestroyDescriptorPool);
  PENUMBRA_LOAD(cmdBeginRenderPass, vkCmdBeginRenderPass);
  PENUMBRA_LOAD(cmdEndRenderPass, vkCmdEndRenderPass);
#undef PENUMBRA_LOAD

  // Before anything is created, so a failure leaks nothing.
  // imgui_impl_vulkan calls the loader through this (IMGUI_IMPL_VULKAN_NO_PROTOTYPES).
  if (!ImGui_ImplVulkan_LoadFunctions(
          [](const char* name, void* user) {
            auto* h = static_cast<vk::interop::DeviceHandles*>(user);
            PFN_vkVoidFunction function = h->getInstanceProcAddr(h->instance, name);
            if (!function && isWsiFunction(name))
              function = reinterpret_cast<PFN_vkVoidFunction>(&unusedWsiFunction);
            return function;
          },
          &handles_))
    throw Error("imgui vulkan: ImGui_ImplVulkan_LoadFunctions failed");

  // The target arrives in COLOR_ATTACHMENT_OPTIMAL (the RHI's barrier)
  // holding the tone-mapped image, which the UI draws over: LOAD, and leave
  // the layout for the RHI's next barrier.
  VkAttachmentDescription color{};
  color.format = VK_FORMAT_R8G8B8A8_UNORM;  // rhi::Format::RGBA8_UNORM
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  VkRenderPassCreateInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  pass.attachmentCount = 1;
  pass.pAttachments = &color;
  pass.subpassCount = 1;
  pass.pSubpasses = &subpass;
  checkResult(fn_->createRenderPass(handles_.device, &pass, nullptr, &renderPass_));

  VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};  // the font atlas
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &poolSize;
  checkResult(fn_->createDescriptorPool(handles_.device, &poolInfo, nullptr, &descriptorPool_));

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = handles_.instance;
  info.PhysicalDevice = handles_.physicalDevice;
  info.Device = handles_.device;
  info.QueueFamily = handles_.queueFamily;
  info.Queue = handles_.queue;
  info.DescriptorPool = descriptorPool_;
  // Its vertex buffers rotate per drawn frame: one set per frame in flight,
  // so none is rewritten while a frame still executing reads it.
  info.MinImageCount = std::max(2u, framesInFlight);
  info.ImageCount = std::max(2u, framesInFlight);
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = &checkResult;
  if (!ImGui_ImplVulkan_Init(&info, renderPass_))
    throw Error("imgui vulkan: ImGui_ImplVulkan_Init failed");

  auto upload = device_.createCommandList("ImGui font upload");
  upload->open();
  ImGui_ImplVulkan_CreateFontsTexture(vk::interop::commandBuffer(*upload));
  upload->close();
  device_.submit(upload.get());
  device_.waitForIdle();
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiVulkanRenderer::~ImGuiVulkanRenderer() {
  device_.waitForIdle();
  ImGui_ImplVulkan_Shutdown();
  forgetTargets();
  fn_->destroyDescriptorPool(handles_.device, descriptorPool_, nullptr);
  fn_->destroyRenderPass(handles_.device, renderPass_, nullptr);
}

void ImGuiVulkanRenderer::newFrame() {
  ImGui_ImplVulkan_NewFrame();
}

void ImGuiVulkanRenderer::forgetTargets() {
  for (auto& [view, framebuffer] : framebuffers_)
    fn_->destroyFramebuffer(handles_.device, framebuffer, nullptr);
  framebuffers_.clear();
}

void ImGuiVulkanRenderer::render(rhi::ICommandList& commandList, rhi::ITexture& target) {
  ImDrawData* draw = ImGui::GetDrawData();
  if (!draw || draw->CmdListsCount == 0) return;
  const auto& d = target.desc();
  if (d.format != rhi::Format::RGBA8_UNORM ||
      !rhi::hasFlag(d.usage, rhi::TextureUsage::RenderTarget))
    throw Error(fmt::format("imgui vulkan: '{}' is not an RGBA8_UNORM render target", d.debugName));
  VkImageView view = vk::interop::imageView(target);
  VkFramebuffer& framebuffer = framebuffers_[view];
  if (!framebuffer) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = d.width;
    info.height = d.height;
    info.layers = 1;
    checkResult(fn_->createFramebuffer(handles_.device, &info, nullptr, &framebuffer));
  }
  VkCommandBuffer cb = vk::interop::commandBuffer(commandList);
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffer;
  begin.renderArea.extent = {d.width, d.height};
  fn_->cmdBeginRenderPass(cb, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(draw, cb);
  fn_->cmdEndRenderPass(cb);
}

}  // namespace penumbra::viewer
