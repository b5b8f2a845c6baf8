#pragma once
// Presentation: a swapchain over a native window, for the interactive viewer.
// Headless use never touches any of this (DeviceCreateInfo::presentWindow
// stays WindowSystem::None).
//
// A frame with N frames in flight:
//   ITexture* backBuffer = swapchain->acquireNextImage();  // nullptr: resize first
//   list->open(); ... copyTexture(backBuffer, image) ... setTextureState(backBuffer, Present);
//   list->close(); swapchain->present(list);
// acquireNextImage waits until the frame slot N frames back has finished on
// the GPU, so the CPU never runs more than N frames ahead.
#include <memory>
#include <string>

#include "penumbra/rhi/resources.h"

namespace penumbra::rhi {

class ICommandList;

enum class WindowSystem : uint8_t { None, Win32, Xlib, Wayland };
const char* windowSystemName(WindowSystem system);

// What a window is to the operating system. The RHI takes no windowing
// library's types (the viewer fills this from GLFW's native accessors).
struct NativeWindow {
  WindowSystem system = WindowSystem::None;
  void* display = nullptr;  // Xlib: Display*. Wayland: wl_display*. Win32: unused.
  void* window = nullptr;   // Xlib: the Window id (cast). Wayland: wl_surface*. Win32: HWND.
};

struct SwapchainDesc {
  NativeWindow window;
  uint32_t width = 0;  // framebuffer pixels
  uint32_t height = 0;
  bool vsync = true;
  uint32_t framesInFlight = 2;  // CPU frames recorded ahead of the GPU, 1..4
  std::string debugName = "swapchain";
};

// D3D12: IDXGISwapChain3 (flip-model, FLIP_DISCARD), one fence value per frame
// slot. Vulkan: VkSurfaceKHR + VkSwapchainKHR, one acquire semaphore and fence
// per frame slot, one render-finished semaphore per image.
class ISwapchain {
 public:
  virtual ~ISwapchain() = default;
  // The size is the back buffers' current one (after resize or what the
  // window system chose). D3D12: DXGI_SWAP_CHAIN_DESC1. Vulkan: VkSwapchainCreateInfoKHR.
  virtual const SwapchainDesc& desc() const = 0;
  // RGBA8_UNORM or BGRA8_UNORM; values are written display-encoded (sRGB),
  // the swapchain does no encoding of its own.
  // D3D12: always DXGI_FORMAT_R8G8B8A8_UNORM. Vulkan: B8G8R8A8_UNORM or
  // R8G8B8A8_UNORM with SRGB_NONLINEAR, whichever the surface offers.
  virtual Format format() const = 0;

  // Waits for the frame slot to be free, then takes the next back buffer. The
  // texture stays valid until resize(). nullptr when the window changed size
  // (or is minimised): call resize() and try again.
  // D3D12: fence wait + GetCurrentBackBufferIndex.
  // Vulkan: vkWaitForFences + vkAcquireNextImageKHR (VK_ERROR_OUT_OF_DATE_KHR -> nullptr).
  virtual ITexture* acquireNextImage() = 0;
  // Submits the frame's last command list, which must leave the back buffer
  // in ResourceState::Present, and queues the image for display. Returns false
  // when the swapchain must be resized.
  // D3D12: ExecuteCommandLists + Signal + IDXGISwapChain::Present(sync, flags).
  // Vulkan: vkQueueSubmit (waits on the acquire semaphore, signals the image's
  // render-finished semaphore) + vkQueuePresentKHR.
  virtual bool present(ICommandList* commandList) = 0;
  // Recreates the back buffers at the new size after the GPU is idle.
  // D3D12: ResizeBuffers. Vulkan: vkCreateSwapchainKHR with oldSwapchain.
  virtual void resize(uint32_t width, uint32_t height) = 0;
  // D3D12: Present sync interval 1, or 0 with ALLOW_TEARING where supported.
  // Vulkan: FIFO, or MAILBOX / IMMEDIATE where supported (recreates the swapchain).
  virtual void setVsync(bool vsync) = 0;
  // D3D12: BufferCount. Vulkan: the count vkGetSwapchainImagesKHR returns.
  virtual uint32_t imageCount() const = 0;
};
using SwapchainHandle = std::shared_ptr<ISwapchain>;

}  // namespace penumbra::rhi
