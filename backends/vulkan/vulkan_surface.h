#pragma once
// VkSurfaceKHR for a native window, through the window system's own surface
// extension (VK_KHR_xlib_surface, VK_KHR_wayland_surface, VK_KHR_win32_surface).
// The platform headers stay inside vulkan_surface.cpp: Xlib's macros (None,
// Bool, Status) would otherwise leak into every backend file.
#include <vector>

#include "penumbra/rhi/presentation.h"
#include "vulkan_functions.h"

namespace penumbra::vk {

// The instance extensions presenting to `system` needs (VK_KHR_surface first).
std::vector<const char*> surfaceInstanceExtensions(rhi::WindowSystem system);

// Owns a VkSurfaceKHR; destroyed with the instance's vkDestroySurfaceKHR.
class VulkanSurface {
 public:
  VulkanSurface(VkInstance instance, const rhi::NativeWindow& window);
  ~VulkanSurface();
  VulkanSurface(const VulkanSurface&) = delete;
  VulkanSurface& operator=(const VulkanSurface&) = delete;
  VkSurfaceKHR handle() const { return surface_; }

 private:
  VkInstance instance_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

}  // namespace penumbra::vk
