#pragma once
// Devices and adapters. A device is created by backend name and adapter index
// (backends/backend_factory.h); engine/ only ever sees these interfaces.
// Presentation (the viewer) is opt-in: DeviceCreateInfo::presentWindow and
// IDevice::createSwapchain (rhi/presentation.h).
#include "penumbra/rhi/binding_offsets.h"
#include "penumbra/rhi/command_list.h"
#include "penumbra/rhi/presentation.h"

namespace penumbra::rhi {

enum class AdapterType : uint8_t { Other, Integrated, Discrete, Virtual, Cpu };
const char* adapterTypeName(AdapterType type);

// Alignment rules of the API's shader tables (see shader_table_layout.h).
struct ShaderTableAlignment {
  uint32_t handleSize = 32;  // D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES / shaderGroupHandleSize
  uint32_t recordAlignment =
      32;  // D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT / shaderGroupHandleAlignment
  uint32_t tableAlignment =
      64;  // D3D12_RAYTRACING_SHADER_TABLE_BYTE_ALIGNMENT / shaderGroupBaseAlignment
  uint32_t maxRecordStride = 4096;
};

struct AdapterInfo {
  uint32_t index = 0;
  std::string name;
  std::string driver;
  std::string apiVersion;
  AdapterType type = AdapterType::Other;
  bool rayTracingPipeline = false;  // DXR tier 1.0 / VK_KHR_ray_tracing_pipeline
  bool accelerationStructure = false;
  bool rayQuery = false;  // DXR tier 1.1 / VK_KHR_ray_query
  uint32_t maxRecursionDepth = 0;
  ShaderTableAlignment shaderTable;
  bool supportsRayTracing() const { return rayTracingPipeline && accelerationStructure; }
};

struct DeviceCreateInfo {
  int adapterIndex = -1;    // -1: the first discrete/integrated GPU with ray tracing, else any
  bool validation = false;  // D3D12 debug layer / VK_LAYER_KHRONOS_validation
  // A window the device must be able to present to; WindowSystem::None (the
  // default) creates a headless device exactly as before.
  // D3D12: nothing extra (any queue presents). Vulkan: instance extensions
  // VK_KHR_surface + the window system's surface extension, device extension
  // VK_KHR_swapchain, and a queue family that can present to this window.
  NativeWindow presentWindow;
  // The register shifts and root-constant spaces the shaders were compiled
  // with (binding_offsets.h); no default: backends::createDevice refuses
  // offsets that are not valid(). Penumbra's renderer passes
  // render::kShaderBindingOffsets.
  BindingOffsets bindingOffsets;
};

class IDevice {
 public:
  virtual ~IDevice() = default;
  virtual const char* backendName() const = 0;
  virtual const AdapterInfo& adapter() const = 0;

  // D3D12: CreateCommittedResource (buffer). Vulkan: vkCreateBuffer + vkAllocateMemory.
  virtual BufferHandle createBuffer(const BufferDesc& desc) = 0;
  // D3D12: CreateCommittedResource (texture 2D). Vulkan: vkCreateImage + vkCreateImageView.
  virtual TextureHandle createTexture(const TextureDesc& desc) = 0;
  // D3D12: a D3D12_SAMPLER_DESC, written into the shader-visible sampler heap by
  // binding sets (CreateSampler). Vulkan: vkCreateSampler.
  virtual SamplerHandle createSampler(const SamplerDesc& desc) = 0;
  // Sizes and allocates the storage; the build happens on a command list.
  // D3D12: GetRaytracingAccelerationStructurePrebuildInfo + buffer.
  // Vulkan: vkGetAccelerationStructureBuildSizesKHR + buffer + vkCreateAccelerationStructureKHR.
  virtual rt::AccelStructHandle createAccelStruct(const rt::AccelStructDesc& desc) = 0;
  // D3D12: CreateStateObject (RAYTRACING_PIPELINE) + global root signature.
  // Vulkan: vkCreateRayTracingPipelinesKHR + descriptor set layouts + pipeline layout.
  virtual RayTracingPipelineHandle createRayTracingPipeline(const RayTracingPipelineDesc& desc) = 0;
  // D3D12: CreateComputePipelineState. Vulkan: vkCreateComputePipelines.
  virtual ComputePipelineHandle createComputePipeline(const ComputePipelineDesc& desc) = 0;
  // The raster subset (pipeline.h).
  // D3D12: CreateGraphicsPipelineState + root signature. Vulkan: vkCreateGraphicsPipelines
  // (dynamic rendering: VK_KHR_dynamic_rendering, enabled where the device has it).
  virtual GraphicsPipelineHandle createGraphicsPipeline(const GraphicsPipelineDesc& desc) = 0;
  // Checks the items against the pipeline's reflected layout for that space
  // (every slot filled, types matching) and throws penumbra::Error otherwise.
  // D3D12: descriptors written into a shader-visible heap range.
  // Vulkan: vkAllocateDescriptorSets + vkUpdateDescriptorSets.
  virtual BindingSetHandle createBindingSet(const BindingSetDesc& desc,
                                            const IPipeline& pipeline) = 0;
  virtual TimerQueryHandle createTimerQuery() = 0;
  // The name appears in the validation layer's errors and the API's debug tools.
  // D3D12: CreateCommandAllocator + CreateCommandList + SetName.
  // Vulkan: vkCreateCommandPool + vkAllocateCommandBuffers + vkSetDebugUtilsObjectNameEXT.
  virtual CommandListHandle createCommandList(const std::string& debugName = "command list") = 0;
  // Only on a device created with DeviceCreateInfo::presentWindow.
  // D3D12: IDXGIFactory4::CreateSwapChainForHwnd (flip model) on the device's queue.
  // Vulkan: vkCreate{Xlib,Wayland,Win32}SurfaceKHR + vkCreateSwapchainKHR.
  virtual SwapchainHandle createSwapchain(const SwapchainDesc& desc) = 0;

  // D3D12: ExecuteCommandLists + Signal. Vulkan: vkQueueSubmit with a fence.
  virtual void submit(ICommandList* commandList) = 0;
  // D3D12: fence wait. Vulkan: vkQueueWaitIdle. Releases what finished lists held.
  virtual void waitForIdle() = 0;
  // Seconds between begin and end of a finished query.
  // D3D12: resolved ticks / GetTimestampFrequency. Vulkan: vkGetQueryPoolResults * timestampPeriod.
  virtual double timerQuerySeconds(ITimerQuery* query) = 0;

  // Validation-layer warnings and errors seen so far (also written to the log).
  // Tests fail on any.
  virtual uint64_t validationMessageCount() const = 0;
};
using DeviceHandle = std::shared_ptr<IDevice>;

}  // namespace penumbra::rhi
