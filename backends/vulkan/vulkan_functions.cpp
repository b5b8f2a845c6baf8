#include "vulkan_functions.h"

#include <fmt/format.h>

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#else
#include <dlfcn.h>
#endif

#include <mutex>

#include "penumbra/util/error.h"

namespace penumbra::vk {
#define PENUMBRA_VK_DEFINE(name) PFN_##name name = nullptr;
PENUMBRA_VK_LOADER_FUNCTIONS(PENUMBRA_VK_DEFINE)
PENUMBRA_VK_INSTANCE_FUNCTIONS(PENUMBRA_VK_DEFINE)
PENUMBRA_VK_DEVICE_FUNCTIONS(PENUMBRA_VK_DEFINE)
#undef PENUMBRA_VK_DEFINE

namespace {
PFN_vkGetInstanceProcAddr gGetInstanceProcAddr = nullptr;
std::mutex gMutex;
}  // namespace

void loadLoader() {
  std::lock_guard lock(gMutex);
  if (gGetInstanceProcAddr) return;
#ifdef _WIN32
  // The loader ships with every GPU driver (and the Vulkan runtime) as vulkan-1.dll.
  HMODULE library = LoadLibraryA("vulkan-1.dll");
  if (!library) throw Error("vulkan: no Vulkan loader found (vulkan-1.dll); install a GPU driver with Vulkan");
  // FARPROC -> the documented signature, through void* (-Wcast-function-type).
  gGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(
      reinterpret_cast<void*>(GetProcAddress(library, "vkGetInstanceProcAddr")));
  if (!gGetInstanceProcAddr) throw Error("vulkan: vulkan-1.dll has no vkGetInstanceProcAddr");
#else
  void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
  if (!library) library = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
  if (!library)
    throw Error("vulkan: no Vulkan loader found (libvulkan.so.1); install libvulkan1");
  gGetInstanceProcAddr =
      reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
  if (!gGetInstanceProcAddr) throw Error("vulkan: libvulkan.so.1 has no vkGetInstanceProcAddr");
#endif
#define PENUMBRA_VK_LOAD_GLOBAL(name) \
  name = reinterpret_cast<PFN_##name>(gGetInstanceProcAddr(nullptr, #name));
  PENUMBRA_VK_LOADER_FUNCTIONS(PENUMBRA_VK_LOAD_GLOBAL)
#undef PENUMBRA_VK_LOAD_GLOBAL
  if (!vkCreateInstance) throw Error("vulkan: the loader does not provide vkCreateInstance");
}

void loadInstanceFunctions(VkInstance instance) {
  std::lock_guard lock(gMutex);
#define PENUMBRA_VK_LOAD(name) \
  name = reinterpret_cast<PFN_##name>(gGetInstanceProcAddr(instance, #name));
  PENUMBRA_VK_INSTANCE_FUNCTIONS(PENUMBRA_VK_LOAD)
  PENUMBRA_VK_DEVICE_FUNCTIONS(PENUMBRA_VK_LOAD)
#undef PENUMBRA_VK_LOAD
}

PFN_vkGetInstanceProcAddr instanceProcAddr() {
  std::lock_guard lock(gMutex);
  return gGetInstanceProcAddr;
}

const char* resultName(VkResult result) {
  switch (result) {
#define PENUMBRA_CASE(r) \
  case r: return #r;
    PENUMBRA_CASE(VK_SUCCESS)
    PENUMBRA_CASE(VK_NOT_READY)
    PENUMBRA_CASE(VK_TIMEOUT)
    PENUMBRA_CASE(VK_INCOMPLETE)
    PENUMBRA_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    PENUMBRA_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    PENUMBRA_CASE(VK_ERROR_INITIALIZATION_FAILED)
    PENUMBRA_CASE(VK_ERROR_DEVICE_LOST)
    PENUMBRA_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    PENUMBRA_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    PENUMBRA_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    PENUMBRA_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    PENUMBRA_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    PENUMBRA_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    PENUMBRA_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    PENUMBRA_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    PENUMBRA_CASE(VK_ERROR_SURFACE_LOST_KHR)
    PENUMBRA_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    PENUMBRA_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    PENUMBRA_CASE(VK_SUBOPTIMAL_KHR)
#undef PENUMBRA_CASE
    default: return "VkResult error";
  }
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw Error(fmt::format("vulkan: {} failed: {}", what, resultName(result)));
}

}  // namespace penumbra::vk
