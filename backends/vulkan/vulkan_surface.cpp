#include "vulkan_surface.h"

#include <fmt/format.h>

#include "penumbra/util/error.h"

// The window-system structs and function types. Only the types are needed
// (functions come from the loader at run time), so Wayland's are declared
// opaquely instead of pulling in wayland-client.h.
#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
// vulkan_win32.h uses HWND and HINSTANCE from windows.h.
#include <vulkan/vulkan_win32.h>
#else
#include <X11/Xlib.h>
#include <vulkan/vulkan_xlib.h>
#undef None  // Xlib's macro; rhi::WindowSystem::None is meant below
struct wl_display;
struct wl_surface;
#include <vulkan/vulkan_wayland.h>
#endif

namespace penumbra::vk {
namespace {

template <class Function>
Function instanceFunction(VkInstance instance, const char* name) {
  auto function = reinterpret_cast<Function>(instanceProcAddr()(instance, name));
  if (!function)
    throw Error(
        fmt::format("vulkan: the loader has no {} (its surface extension is not enabled)", name));
  return function;
}

}  // namespace

std::vector<const char*> surfaceInstanceExtensions(rhi::WindowSystem system) {
  switch (system) {
    case rhi::WindowSystem::None:
      return {};
    case rhi::WindowSystem::Win32:
      return {"VK_KHR_surface", "VK_KHR_win32_surface"};
    case rhi::WindowSystem::Xlib:
      return {"VK_KHR_surface", "VK_KHR_xlib_surface"};
    case rhi::WindowSystem::Wayland:
      return {"VK_KHR_surface", "VK_KHR_wayland_surface"};
  }
  return {};
}

VulkanSurface::VulkanSurface(VkInstance instance, const rhi::NativeWindow& window)
    : instance_(instance) {
  VkResult result = VK_ERROR_EXTENSION_NOT_PRESENT;
  switch (window.system) {
#if defined(_WIN32)
    case rhi::WindowSystem::Win32: {
      VkWin32SurfaceCreateInfoKHR info{VK_STRUCTURE_TYPE_WIN32_SURFACE_CREATE_INFO_KHR};
      info.hinstance = GetModuleHandleW(nullptr);
      info.hwnd = static_cast<HWND>(window.window);
      result = instanceFunction<PFN_vkCreateWin32SurfaceKHR>(instance, "vkCreateWin32SurfaceKHR")(
          instance, &info, nullptr, &surface_);
      break;
    }
#else
    case rhi::WindowSystem::Xlib: {
      VkXlibSurfaceCreateInfoKHR info{VK_STRUCTURE_TYPE_XLIB_SURFACE_CREATE_INFO_KHR};
      info.dpy = static_cast<Display*>(window.display);
      info.window = static_cast<Window>(reinterpret_cast<uintptr_t>(window.window));
      result = instanceFunction<PFN_vkCreateXlibSurfaceKHR>(instance, "vkCreateXlibSurfaceKHR")(
          instance, &info, nullptr, &surface_);
      break;
    }
    case rhi::WindowSystem::Wayland: {
      VkWaylandSurfaceCreateInfoKHR info{VK_STRUCTURE_TYPE_WAYLAND_SURFACE_CREATE_INFO_KHR};
      info.display = static_cast<wl_display*>(window.display);
      info.surface = static_cast<wl_surface*>(window.window);
      result = instanceFunction<PFN_vkCreateWaylandSurfaceKHR>(
          instance, "vkCreateWaylandSurfaceKHR")(instance, &info, nullptr, &surface_);
      break;
    }
#endif
    default:
      throw Error(fmt::format("vulkan: this build cannot present to {} windows",
                              rhi::windowSystemName(window.system)));
  }
  check(result, "creating the window surface");
}

VulkanSurface::~VulkanSurface() {
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
}

}  // namespace penumbra::vk
