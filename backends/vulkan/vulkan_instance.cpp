#include <fmt/format.h>

#include <cstring>
#include <map>
#include <mutex>

#include "penumbra/util/error.h"
#include "penumbra/util/log.h"
#include "vulkan_backend.h"
#include "vulkan_surface.h"

namespace penumbra::vk {
namespace {

bool hasInstanceLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

// `layer`: an extension a layer provides (nullptr: the loader's and drivers').
bool hasInstanceExtension(const char* name, const char* layer = nullptr) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, exts.data());
  for (const auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

rhi::AdapterType toAdapterType(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return rhi::AdapterType::Discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return rhi::AdapterType::Integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return rhi::AdapterType::Virtual;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return rhi::AdapterType::Cpu;
    default: return rhi::AdapterType::Other;
  }
}

rhi::AdapterInfo describe(VkPhysicalDevice physical, uint32_t index) {
  rhi::AdapterInfo info;
  info.index = index;

  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data());
  auto has = [&](const char* name) {
    for (const auto& e : exts)
      if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
  };

  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rtProps{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceDriverProperties driverProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  driverProps.pNext = &rtProps;
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &driverProps;
  vkGetPhysicalDeviceProperties2(physical, &props);

  info.name = props.properties.deviceName;
  info.driver = fmt::format("{} {}", driverProps.driverName, driverProps.driverInfo);
  uint32_t v = props.properties.apiVersion;
  info.apiVersion = fmt::format("Vulkan {}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v),
                                VK_API_VERSION_PATCH(v));
  info.type = toAdapterType(props.properties.deviceType);

  const bool api12 = v >= VK_API_VERSION_1_2;
  if (api12 && has(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) &&
      has(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
      has(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME)) {
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rtFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR asFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    rtFeatures.pNext = &asFeatures;
    asFeatures.pNext = &v12;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &rtFeatures;
    vkGetPhysicalDeviceFeatures2(physical, &features);
    info.rayTracingPipeline = rtFeatures.rayTracingPipeline && v12.bufferDeviceAddress;
    info.accelerationStructure = asFeatures.accelerationStructure;
  }
  info.rayQuery = api12 && has(VK_KHR_RAY_QUERY_EXTENSION_NAME);
  info.maxRecursionDepth = rtProps.maxRayRecursionDepth;
  info.shaderTable.handleSize = rtProps.shaderGroupHandleSize;
  info.shaderTable.recordAlignment = rtProps.shaderGroupHandleAlignment;
  info.shaderTable.tableAlignment = rtProps.shaderGroupBaseAlignment;
  info.shaderTable.maxRecordStride = rtProps.maxShaderGroupStride;
  return info;
}

}  // namespace

VulkanInstance::VulkanInstance(bool validation, rhi::WindowSystem presentation) {
  loadLoader();
  uint32_t version = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion) vkEnumerateInstanceVersion(&version);
  if (version < VK_API_VERSION_1_2)
    throw Error("vulkan: the Vulkan loader is older than 1.2; ray tracing needs Vulkan 1.2");

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  bool validationFeatures = false;
  if (validation) {
    if (!hasInstanceLayer("VK_LAYER_KHRONOS_validation"))
      throw Error("vulkan: validation was requested but VK_LAYER_KHRONOS_validation is not "
                  "installed (Debian: vulkan-validationlayers)");
    layers.push_back("VK_LAYER_KHRONOS_validation");
    validationFeatures = hasInstanceExtension(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME,
                                              "VK_LAYER_KHRONOS_validation");
    if (validationFeatures) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
  }
  debugUtils_ = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  for (const char* name : surfaceInstanceExtensions(presentation)) {
    if (!hasInstanceExtension(name))
      throw Error(fmt::format("vulkan: presenting to a {} window needs {}, which this Vulkan "
                              "installation does not offer",
                              rhi::windowSystemName(presentation), name));
    extensions.push_back(name);
  }

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "penumbra";
  app.pEngineName = "penumbra";
  app.apiVersion = VK_API_VERSION_1_2;

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &VulkanInstance::messengerCallback;
  messengerInfo.pUserData = this;

  VkInstanceCreateInfo create{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  create.pApplicationInfo = &app;
  create.enabledLayerCount = uint32_t(layers.size());
  create.ppEnabledLayerNames = layers.data();
  create.enabledExtensionCount = uint32_t(extensions.size());
  create.ppEnabledExtensionNames = extensions.data();
  // Also report problems of vkCreateInstance/vkDestroyInstance themselves.
  if (debugUtils_) create.pNext = &messengerInfo;
  // Validation includes synchronization validation: a missing or wrong
  // barrier is as much a bug as a wrong argument, and the RHI records its
  // barriers itself, so every test exercises them.
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  if (validationFeatures) {
    features.pNext = create.pNext;
    create.pNext = &features;
  }
  VkResult created = vkCreateInstance(&create, nullptr, &instance_);
  if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw Error("vulkan: no Vulkan driver found; install a GPU driver or Mesa's lavapipe "
                "(scripts/setup.sh)");
  check(created, "vkCreateInstance");
  loadInstanceFunctions(instance_);
  if (debugUtils_)
    check(vkCreateDebugUtilsMessengerEXT(instance_, &messengerInfo, nullptr, &messenger_),
          "vkCreateDebugUtilsMessengerEXT");
}

VulkanInstance::~VulkanInstance() {
  if (messenger_) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanInstance::messengerCallback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<VulkanInstance*>(user);
  const bool isValidation = (types & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT) != 0;
  const bool isError = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  const char* message = data && data->pMessage ? data->pMessage : "(no message)";
  if (isValidation) {
    // Every validation warning or error counts; tests fail on any.
    ++self->validationMessages_;
    if (isError)
      log::error("vulkan validation: {}", message);
    else
      log::warning("vulkan validation: {}", message);
  } else {
    // Loader and performance notes: shown with --verbose only, so a failure
    // still ends in one line (the exception that follows).
    log::debug("vulkan: {}", message);
  }
  return VK_FALSE;
}

std::vector<VkPhysicalDevice> VulkanInstance::physicalDevices() {
  uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
  return devices;
}

std::vector<rhi::AdapterInfo> VulkanInstance::adapters() {
  std::vector<rhi::AdapterInfo> result;
  auto devices = physicalDevices();
  for (uint32_t i = 0; i < devices.size(); ++i) result.push_back(describe(devices[i], i));
  return result;
}

std::shared_ptr<VulkanInstance> processInstance(bool validation, rhi::WindowSystem presentation) {
  // One instance per kind for the whole process, created on first use: the
  // NVIDIA driver (580) refuses vkCreateInstance after 30 instances were
  // created and destroyed in one process (VK_ERROR_INCOMPATIBLE_DRIVER; no
  // file descriptor, mapping or thread was left behind), which a viewer
  // switching scenes, a long study or a farm worker would reach. Devices
  // come and go; their instance stays (tests/rhi/test_device_lifetimes.cpp).
  // Never destroyed: at exit the driver's own handlers may have run before
  // a static's destructor (vkDestroyInstance then crashed in the NVIDIA
  // driver), and the system reclaims what a process holds anyway.
  static std::mutex mutex;
  static auto* instances =
      new std::map<std::pair<bool, rhi::WindowSystem>, std::shared_ptr<VulkanInstance>>;
  std::lock_guard lock(mutex);
  auto& instance = (*instances)[{validation, presentation}];
  if (!instance) instance = std::make_shared<VulkanInstance>(validation, presentation);
  return instance;
}

std::vector<rhi::AdapterInfo> listAdapters() {
  return processInstance(false, rhi::WindowSystem::None)->adapters();
}

rhi::DeviceHandle createDevice(const rhi::DeviceCreateInfo& info) {
  auto instance = processInstance(info.validation, info.presentWindow.system);
  auto adapters = instance->adapters();
  auto physical = instance->physicalDevices();
  if (adapters.empty()) throw Error("vulkan: no Vulkan device found");

  int chosen = info.adapterIndex;
  if (chosen >= 0) {
    if (chosen >= int(adapters.size()))
      throw Error(fmt::format("vulkan: --device {} does not exist ({} device(s); see 'penumbra devices')",
                              chosen, adapters.size()));
    if (!adapters[chosen].supportsRayTracing())
      throw Error(fmt::format("vulkan: device {} ({}) has no ray-tracing support "
                              "(VK_KHR_ray_tracing_pipeline + VK_KHR_acceleration_structure)",
                              chosen, adapters[chosen].name));
  } else {
    // Prefer a real GPU; fall back to a CPU implementation such as lavapipe.
    auto rank = [](rhi::AdapterType t) {
      switch (t) {
        case rhi::AdapterType::Discrete: return 0;
        case rhi::AdapterType::Integrated: return 1;
        case rhi::AdapterType::Virtual: return 2;
        case rhi::AdapterType::Other: return 3;
        case rhi::AdapterType::Cpu: return 4;
      }
      return 5;
    };
    for (int i = 0; i < int(adapters.size()); ++i)
      if (adapters[i].supportsRayTracing() &&
          (chosen < 0 || rank(adapters[i].type) < rank(adapters[chosen].type)))
        chosen = i;
    if (chosen < 0)
      throw Error("vulkan: no device with ray tracing (VK_KHR_ray_tracing_pipeline + "
                  "VK_KHR_acceleration_structure); on Debian 12 install mesa-vulkan-drivers "
                  "from bookworm-backports (scripts/setup.sh)");
  }
  return std::make_shared<VulkanDevice>(instance, physical[chosen], adapters[chosen],
                                        info.presentWindow);
}

}  // namespace penumbra::vk
