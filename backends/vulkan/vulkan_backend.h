#pragma once
// The Vulkan KHR ray-tracing implementation of engine/rhi. Nothing outside
// backends/vulkan includes this header; apps reach it through
// backends/backend_factory.h.
#include <atomic>
#include <map>
#include <memory>
#include <vector>

#include "penumbra/rhi/rhi.h"
#include "penumbra/rhi/shader_table_records.h"
#include "vulkan_functions.h"

namespace penumbra::vk {

// Owns the VkInstance and the validation messenger. Shared by the devices
// created from it; counts validation warnings/errors for the tests.
class VulkanInstance {
 public:
  // `presentation`: the window system whose surface extensions to enable (None: headless).
  VulkanInstance(bool validation, rhi::WindowSystem presentation);
  ~VulkanInstance();
  VulkanInstance(const VulkanInstance&) = delete;
  VulkanInstance& operator=(const VulkanInstance&) = delete;

  VkInstance handle() const { return instance_; }
  bool hasDebugUtils() const { return debugUtils_; }
  uint64_t validationMessages() const { return validationMessages_; }
  std::vector<rhi::AdapterInfo> adapters();
  std::vector<VkPhysicalDevice> physicalDevices();

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL messengerCallback(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  bool debugUtils_ = false;
  std::atomic<uint64_t> validationMessages_{0};
};

class VulkanDevice;

class VulkanBuffer final : public rhi::IBuffer {
 public:
  VulkanBuffer(VulkanDevice& device, const rhi::BufferDesc& desc, uint64_t alignment = 0);
  ~VulkanBuffer() override;
  const rhi::BufferDesc& desc() const override { return desc_; }
  uint64_t deviceAddress() const override { return address_; }
  void* mappedData() override;
  VkBuffer handle() const { return buffer_; }
  // Bytes between the VkBuffer's start and the aligned address (see constructor).
  uint64_t alignedOffset() const { return alignedOffset_; }

 private:
  VulkanDevice& device_;
  rhi::BufferDesc desc_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  uint64_t address_ = 0;
  uint64_t alignedOffset_ = 0;
  void* mapped_ = nullptr;
};

class VulkanTexture final : public rhi::ITexture {
 public:
  VulkanTexture(VulkanDevice& device, const rhi::TextureDesc& desc);
  // A view of an image the texture does not own (a swapchain image).
  VulkanTexture(VulkanDevice& device, const rhi::TextureDesc& desc, VkImage externalImage);
  ~VulkanTexture() override;
  const rhi::TextureDesc& desc() const override { return desc_; }
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }

 private:
  void createView();
  VulkanDevice& device_;
  rhi::TextureDesc desc_;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  bool ownsImage_ = true;
};

class VulkanSampler final : public rhi::ISampler {
 public:
  VulkanSampler(VulkanDevice& device, const rhi::SamplerDesc& desc);
  ~VulkanSampler() override;
  const rhi::SamplerDesc& desc() const override { return desc_; }
  VkSampler handle() const { return sampler_; }

 private:
  VulkanDevice& device_;
  rhi::SamplerDesc desc_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

// The geometry arrays vkCmdBuildAccelerationStructuresKHR and
// vkGetAccelerationStructureBuildSizesKHR take, derived from an AccelStructDesc.
struct AccelStructBuildInputs {
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
  std::vector<uint32_t> maxPrimitiveCounts;
  VkAccelerationStructureBuildGeometryInfoKHR info{};
};

class VulkanAccelStruct final : public rhi::rt::IAccelStruct {
 public:
  VulkanAccelStruct(VulkanDevice& device, const rhi::rt::AccelStructDesc& desc);
  ~VulkanAccelStruct() override;
  const rhi::rt::AccelStructDesc& desc() const override { return desc_; }
  uint64_t deviceAddress() const override { return address_; }
  VkAccelerationStructureKHR handle() const { return handle_; }
  uint64_t scratchBytes() const { return scratchBytes_; }
  // Inputs for a build; for a top level, `instanceAddress`/`instanceCount`
  // describe the instance array.
  AccelStructBuildInputs buildInputs(uint64_t instanceAddress = 0, uint32_t instanceCount = 0) const;

 private:
  VulkanDevice& device_;
  rhi::rt::AccelStructDesc desc_;
  std::unique_ptr<VulkanBuffer> storage_;
  VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
  uint64_t address_ = 0;
  uint64_t scratchBytes_ = 0;
};

// Descriptor set layouts + pipeline layout built from reflected SPIR-V.
class VulkanPipelineLayout {
 public:
  VulkanPipelineLayout(VulkanDevice& device, rhi::PipelineBindingLayout layout, VkShaderStageFlags stages);
  ~VulkanPipelineLayout();
  const rhi::PipelineBindingLayout& bindingLayout() const { return layout_; }
  VkPipelineLayout handle() const { return pipelineLayout_; }
  VkDescriptorSetLayout setLayout(uint32_t space) const { return setLayouts_.at(space); }
  // The bindings of a set layout, with the descriptor counts unbounded arrays
  // got (binding sets size their descriptor pools from them).
  const std::vector<VkDescriptorSetLayoutBinding>& setBindings(uint32_t space) const {
    return setBindings_.at(space);
  }
  VkShaderStageFlags stages() const { return stages_; }

 private:
  VulkanDevice& device_;
  rhi::PipelineBindingLayout layout_;
  VkShaderStageFlags stages_;
  std::vector<VkDescriptorSetLayout> setLayouts_;
  std::vector<std::vector<VkDescriptorSetLayoutBinding>> setBindings_;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
};

class VulkanComputePipeline final : public rhi::IComputePipeline {
 public:
  VulkanComputePipeline(VulkanDevice& device, const rhi::ComputePipelineDesc& desc);
  ~VulkanComputePipeline() override;
  const rhi::PipelineBindingLayout& bindingLayout() const override { return layout_->bindingLayout(); }
  const VulkanPipelineLayout& layout() const { return *layout_; }
  VkPipeline handle() const { return pipeline_; }

 private:
  VulkanDevice& device_;
  std::unique_ptr<VulkanPipelineLayout> layout_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

class VulkanGraphicsPipeline final : public rhi::IGraphicsPipeline {
 public:
  VulkanGraphicsPipeline(VulkanDevice& device, const rhi::GraphicsPipelineDesc& desc);
  ~VulkanGraphicsPipeline() override;
  const rhi::GraphicsPipelineDesc& desc() const override { return desc_; }
  const rhi::PipelineBindingLayout& bindingLayout() const override { return layout_->bindingLayout(); }
  const VulkanPipelineLayout& layout() const { return *layout_; }
  VkPipeline handle() const { return pipeline_; }

 private:
  VulkanDevice& device_;
  rhi::GraphicsPipelineDesc desc_;
  std::unique_ptr<VulkanPipelineLayout> layout_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

class VulkanRayTracingPipeline final : public rhi::IRayTracingPipeline,
                                       public std::enable_shared_from_this<VulkanRayTracingPipeline> {
 public:
  VulkanRayTracingPipeline(VulkanDevice& device, const rhi::RayTracingPipelineDesc& desc);
  ~VulkanRayTracingPipeline() override;
  const rhi::RayTracingPipelineDesc& desc() const override { return desc_; }
  const rhi::PipelineBindingLayout& bindingLayout() const override { return layout_->bindingLayout(); }
  rhi::ShaderTableHandle createShaderTable(const std::string& debugName) override;
  const VulkanPipelineLayout& layout() const { return *layout_; }
  VkPipeline handle() const { return pipeline_; }
  // The shader group handle of a raygen/miss shader or hit group, by export name.
  const uint8_t* groupHandle(const std::string& exportName) const;

 private:
  VulkanDevice& device_;
  rhi::RayTracingPipelineDesc desc_;
  std::unique_ptr<VulkanPipelineLayout> layout_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  std::map<std::string, uint32_t> groupIndex_;
  std::vector<uint8_t> groupHandles_;
};

class VulkanBindingSet final : public rhi::IBindingSet {
 public:
  VulkanBindingSet(VulkanDevice& device, const rhi::BindingSetDesc& desc, const VulkanPipelineLayout& layout);
  ~VulkanBindingSet() override;
  const rhi::BindingSetDesc& desc() const override { return desc_; }
  VkDescriptorSet handle() const { return set_; }
  // Whether the shaders write the resource at `slot` (UAV) or only read it.
  bool isWritable(uint32_t slot) const;

 private:
  VulkanDevice& device_;
  rhi::BindingSetDesc desc_;
  std::vector<rhi::BindingLayoutItem> layoutItems_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

// The records are rhi::ShaderTableRecords'; this adds the upload into a
// buffer aligned to shaderGroupBaseAlignment and the strided regions.
class VulkanShaderTable final : public rhi::ShaderTableRecords {
 public:
  VulkanShaderTable(VulkanDevice& device, std::shared_ptr<VulkanRayTracingPipeline> pipeline,
                    std::string debugName);

  // Uploads the records if they changed and returns the regions to trace with.
  struct Regions {
    VkStridedDeviceAddressRegionKHR rayGen{}, miss{}, hit{}, callable{};
  };
  Regions prepare();
  std::shared_ptr<VulkanBuffer> buffer() const;

 private:
  VulkanDevice& device_;
  std::shared_ptr<VulkanRayTracingPipeline> pipeline_;
  std::string debugName_;
};

class VulkanTimerQuery final : public rhi::ITimerQuery {
 public:
  explicit VulkanTimerQuery(VulkanDevice& device);
  ~VulkanTimerQuery() override;
  VkQueryPool pool() const { return pool_; }

 private:
  VulkanDevice& device_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
};

class VulkanCommandList final : public rhi::ICommandList {
 public:
  VulkanCommandList(VulkanDevice& device, const std::string& debugName);
  ~VulkanCommandList() override;
  void open() override;
  void close() override;
  void writeBuffer(rhi::IBuffer* buffer, const void* data, size_t bytes, uint64_t offset) override;
  void writeTexture(rhi::ITexture* texture, const void* data, size_t bytes) override;
  void copyBuffer(rhi::IBuffer* dst, uint64_t dstOffset, rhi::IBuffer* src, uint64_t srcOffset,
                  uint64_t bytes) override;
  void copyTextureToBuffer(rhi::ITexture* src, rhi::IBuffer* dst, uint64_t dstOffset) override;
  void copyTexture(rhi::ITexture* dst, rhi::ITexture* src) override;
  void clearTextureFloat(rhi::ITexture* texture, float r, float g, float b, float a) override;
  void clearBufferUint(rhi::IBuffer* buffer, uint32_t value) override;
  void setBufferState(rhi::IBuffer* buffer, rhi::ResourceState state) override;
  void setTextureState(rhi::ITexture* texture, rhi::ResourceState state) override;
  void setAccelStructState(rhi::rt::IAccelStruct* as, rhi::ResourceState state) override;
  void buildBottomLevelAccelStruct(rhi::rt::IAccelStruct* as) override;
  void buildTopLevelAccelStruct(rhi::rt::IAccelStruct* as, const rhi::rt::InstanceDesc* instances,
                                uint32_t count) override;
  void setRayTracingState(const rhi::RayTracingState& state) override;
  void setComputeState(const rhi::ComputeState& state) override;
  void setGraphicsState(const rhi::GraphicsState& state) override;
  void beginRendering(rhi::ITexture* target, const float* clearColor) override;
  void endRendering() override;
  void setViewport(const rhi::Viewport& viewport) override;
  void setScissor(const rhi::ScissorRect& rect) override;
  void drawIndexed(uint32_t indexCount, uint32_t firstIndex, int32_t vertexOffset) override;
  void setPushConstants(const void* data, size_t bytes) override;
  void dispatchRays(uint32_t width, uint32_t height, uint32_t depth) override;
  void dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) override;
  void beginTimerQuery(rhi::ITimerQuery* query) override;
  void endTimerQuery(rhi::ITimerQuery* query) override;

  VkCommandBuffer handle() const { return commandBuffer_; }
  VkFence fence() const { return fence_; }
  const std::string& debugName() const { return debugName_; }
  // After a failed vkQueueSubmit: a new fence, created signaled.
  void replaceFenceSignaled();
  // Called by the device once the GPU finished this list's work.
  void releaseTransientResources() { transient_.clear(); }

 private:
  std::shared_ptr<VulkanBuffer> makeTransientBuffer(uint64_t bytes, rhi::BufferUsage usage,
                                                    rhi::MemoryLocation memory, uint64_t alignment,
                                                    const char* name);
  void transitionBindingSets(const std::vector<rhi::IBindingSet*>& sets);
  VulkanDevice& device_;
  std::string debugName_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkPipelineLayout boundLayout_ = VK_NULL_HANDLE;
  VkShaderStageFlags boundStages_ = 0;
  VulkanShaderTable::Regions boundRegions_;
  std::vector<std::shared_ptr<VulkanBuffer>> transient_;
};

class VulkanDevice final : public rhi::IDevice {
 public:
  // A `presentWindow` other than WindowSystem::None enables VK_KHR_swapchain
  // and requires the queue to present to that window.
  VulkanDevice(std::shared_ptr<VulkanInstance> instance, VkPhysicalDevice physicalDevice,
               rhi::AdapterInfo adapter, const rhi::NativeWindow& presentWindow);
  ~VulkanDevice() override;
  const char* backendName() const override { return "vulkan"; }
  const rhi::AdapterInfo& adapter() const override { return adapter_; }
  rhi::BufferHandle createBuffer(const rhi::BufferDesc& desc) override;
  rhi::TextureHandle createTexture(const rhi::TextureDesc& desc) override;
  rhi::SamplerHandle createSampler(const rhi::SamplerDesc& desc) override;
  rhi::rt::AccelStructHandle createAccelStruct(const rhi::rt::AccelStructDesc& desc) override;
  rhi::RayTracingPipelineHandle createRayTracingPipeline(const rhi::RayTracingPipelineDesc& desc) override;
  rhi::ComputePipelineHandle createComputePipeline(const rhi::ComputePipelineDesc& desc) override;
  rhi::GraphicsPipelineHandle createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) override;
  rhi::BindingSetHandle createBindingSet(const rhi::BindingSetDesc& desc, const rhi::IPipeline& pipeline) override;
  rhi::TimerQueryHandle createTimerQuery() override;
  rhi::CommandListHandle createCommandList(const std::string& debugName) override;
  rhi::SwapchainHandle createSwapchain(const rhi::SwapchainDesc& desc) override;
  void submit(rhi::ICommandList* commandList) override;
  // submit() that also waits for and signals semaphores (the swapchain's).
  void submit(rhi::ICommandList* commandList, VkSemaphore wait, VkSemaphore signal);
  void waitForIdle() override;
  // A list being recorded again, or destroyed, is no longer one whose
  // transient resources waitForIdle may release.
  void forgetSubmitted(VulkanCommandList* list);
  double timerQuerySeconds(rhi::ITimerQuery* query) override;
  // The instance is the process's (it outlives devices): this device's are
  // those since it was created.
  uint64_t validationMessageCount() const override {
    return instance_->validationMessages() - validationBaseline_;
  }

  VkDevice handle() const { return device_; }
  VkInstance instance() const { return instance_->handle(); }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkQueue queue() const { return queue_; }
  bool canPresent() const { return canPresent_; }
  // Whether VK_KHR_dynamic_rendering is enabled (the raster subset needs it).
  bool dynamicRendering() const { return dynamicRendering_; }
  // The shader stages a barrier for shader access waits on or blocks: ray
  // tracing and compute, plus vertex and fragment on a graphics queue.
  VkPipelineStageFlags shaderStages() const { return shaderStages_; }
  uint32_t queueFamily() const { return queueFamily_; }
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;
  uint64_t scratchAlignment() const { return scratchAlignment_; }
  // Descriptors an unbounded array of `type` gets in a set layout:
  // min(rhi::kMaxBindlessDescriptors, the device's per-stage and per-set limits).
  uint32_t bindlessCapacity(rhi::ResourceType type) const;
  // Like check(), but device loss and running out of memory get messages
  // that say what happened to the GPU; `what` names the operation.
  void checkDevice(VkResult result, const char* what) const;
  // VK_EXT_debug_utils object name, shown by RenderDoc/Nsight and in validation messages.
  void setName(VkObjectType type, uint64_t handle, const std::string& name) const;

 private:
  std::shared_ptr<VulkanInstance> instance_;
  VkPhysicalDevice physicalDevice_;
  rhi::AdapterInfo adapter_;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  uint64_t scratchAlignment_ = 128;
  VkPhysicalDeviceLimits limits_{};
  double timestampPeriodNs_ = 1.0;
  uint32_t timestampValidBits_ = 64;
  bool canPresent_ = false;
  bool dynamicRendering_ = false;
  VkPipelineStageFlags shaderStages_ = 0;
  uint64_t validationBaseline_ = 0;
  std::vector<VulkanCommandList*> inFlight_;
};

// Device listing and creation for backends/backend_factory.cpp.
std::vector<rhi::AdapterInfo> listAdapters();
rhi::DeviceHandle createDevice(const rhi::DeviceCreateInfo& info);

// Maps of RHI enums to Vulkan ones.
VkFormat toVkFormat(rhi::Format format);

}  // namespace penumbra::vk
