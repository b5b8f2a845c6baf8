#pragma once
// The viewer's GLFW window: no client API (the RHI presents through its own
// swapchain), native handles for rhi::NativeWindow, and the input the camera
// controller and Dear ImGui read.
#include <string>

#include "penumbra/rhi/presentation.h"

struct GLFWwindow;

namespace penumbra::viewer {

class Window {
 public:
  // Throws penumbra::Error with one line when no window can be opened (no
  // display, DISPLAY/WAYLAND_DISPLAY unset, GLFW failing to start).
  Window(uint32_t width, uint32_t height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  rhi::NativeWindow nativeWindow() const;
  bool shouldClose() const;
  void requestClose();
  // Framebuffer pixels (differs from window coordinates on HiDPI screens).
  void framebufferSize(uint32_t& width, uint32_t& height) const;
  void setTitle(const std::string& title);

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace penumbra::viewer
