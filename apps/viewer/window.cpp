#include "window.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "penumbra/util/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#if defined(_WIN32)
#define GLFW_EXPOSE_NATIVE_WIN32
// glfw3native.h includes <windows.h>: without its min/max macros.
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#else
#define GLFW_EXPOSE_NATIVE_X11
#if defined(PENUMBRA_GLFW_HAS_WAYLAND)
#define GLFW_EXPOSE_NATIVE_WAYLAND
#endif
#endif
#include <GLFW/glfw3native.h>
#undef None  // Xlib's macros, unused here
#undef Bool
#undef Status

namespace penumbra::viewer {
namespace {

std::string gLastGlfwError;

void onGlfwError(int, const char* description) {
  gLastGlfwError = description ? description : "?";
}

#if !defined(_WIN32)
bool envSet(const char* name) {
  const char* value = std::getenv(name);
  return value && *value;
}
#endif

}  // namespace

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
  glfwSetErrorCallback(&onGlfwError);
#if !defined(_WIN32)
  // Say why in words a user knows, rather than GLFW's platform message.
  if (!envSet("DISPLAY") && !envSet("WAYLAND_DISPLAY"))
    throw Error("cannot open a window: no display (DISPLAY and WAYLAND_DISPLAY are unset)");
#endif
  if (!glfwInit()) throw Error(fmt::format("cannot open a window: {}", gLastGlfwError));
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw Error(fmt::format("cannot open a window: {}", gLastGlfwError));
  }
  // The viewer polls keys once a frame (glfwGetKey): sticky keys keep a tap
  // shorter than a frame (F1, Home) from being lost between two polls.
  glfwSetInputMode(window_, GLFW_STICKY_KEYS, GLFW_TRUE);
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

rhi::NativeWindow Window::nativeWindow() const {
  rhi::NativeWindow native;
#if defined(_WIN32)
  native.system = rhi::WindowSystem::Win32;
  native.window = glfwGetWin32Window(window_);
#else
#if defined(PENUMBRA_GLFW_HAS_WAYLAND)
  // A GLFW built for Wayland reports its display; on X11 it has none.
  if (wl_display* display = glfwGetWaylandDisplay()) {
    native.system = rhi::WindowSystem::Wayland;
    native.display = display;
    native.window = glfwGetWaylandWindow(window_);
    return native;
  }
#endif
  native.system = rhi::WindowSystem::Xlib;
  native.display = glfwGetX11Display();
  native.window = reinterpret_cast<void*>(uintptr_t(glfwGetX11Window(window_)));
#endif
  return native;
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(window_);
}
void Window::requestClose() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void Window::framebufferSize(uint32_t& width, uint32_t& height) const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  width = uint32_t(std::max(w, 0));
  height = uint32_t(std::max(h, 0));
}

void Window::setTitle(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

}  // namespace penumbra::viewer
