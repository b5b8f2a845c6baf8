#pragma once
// The validation layer's wrappers (rhi/validation.h). Internal to the layer:
// the rest of the engine sees only the RHI interfaces.
#include <fmt/format.h>

#include <optional>
#include <set>

#include "penumbra/rhi/validation.h"
#include "penumbra/util/error.h"

namespace penumbra::rhi::validation {

// Every rule's error: the call, then what is wrong, naming the objects.
template <class... Args>
[[noreturn]] void fail(const char* call, fmt::format_string<Args...> format, Args&&... args) {
  throw Error(fmt::format("{}: {}", call, fmt::format(format, std::forward<Args>(args)...)));
}

class ValidationDevice;

// The backend's pipeline behind a wrapper (binding sets are created against it).
const IPipeline& backendObject(const IPipeline& pipeline);

class ValidationRayTracingPipeline final
    : public IRayTracingPipeline,
      public std::enable_shared_from_this<ValidationRayTracingPipeline> {
 public:
  explicit ValidationRayTracingPipeline(RayTracingPipelineHandle backend);
  const RayTracingPipelineDesc& desc() const override { return backend_->desc(); }
  const PipelineBindingLayout& bindingLayout() const override { return backend_->bindingLayout(); }
  ShaderTableHandle createShaderTable(const std::string& debugName) override;

  IRayTracingPipeline* backend() const { return backend_.get(); }
  // The stage of a shader export, or nullopt when no shader has that name.
  std::optional<ShaderStage> shaderStage(const std::string& exportName) const;
  bool isHitGroup(const std::string& exportName) const;
  // Bytes of record data the export's shaders read, rounded up to whole
  // 32-bit values (D3D12 local root constants are DWORDs).
  uint32_t recordCapacity(const std::string& exportName) const;

 private:
  RayTracingPipelineHandle backend_;
};

class ValidationComputePipeline final : public IComputePipeline {
 public:
  ValidationComputePipeline(ComputePipelineHandle backend, std::string debugName)
      : backend_(std::move(backend)), debugName_(std::move(debugName)) {}
  const PipelineBindingLayout& bindingLayout() const override { return backend_->bindingLayout(); }
  IComputePipeline* backend() const { return backend_.get(); }
  const std::string& debugName() const { return debugName_; }

 private:
  ComputePipelineHandle backend_;
  std::string debugName_;
};

class ValidationGraphicsPipeline final : public IGraphicsPipeline {
 public:
  explicit ValidationGraphicsPipeline(GraphicsPipelineHandle backend)
      : backend_(std::move(backend)) {}
  const GraphicsPipelineDesc& desc() const override { return backend_->desc(); }
  const PipelineBindingLayout& bindingLayout() const override { return backend_->bindingLayout(); }
  IGraphicsPipeline* backend() const { return backend_.get(); }

 private:
  GraphicsPipelineHandle backend_;
};

class ValidationShaderTable final : public IShaderTable {
 public:
  ValidationShaderTable(std::shared_ptr<ValidationRayTracingPipeline> pipeline,
                        ShaderTableHandle backend, std::string debugName);
  void setRayGenerationShader(const std::string& exportName, const void* localData,
                              size_t localBytes) override;
  uint32_t addMissShader(const std::string& exportName, const void* localData,
                         size_t localBytes) override;
  uint32_t addHitGroup(const std::string& exportName, const void* localData,
                       size_t localBytes) override;
  void clearMissShaders() override;
  void clearHitGroups() override;

  IShaderTable* backend() const { return backend_.get(); }
  const ValidationRayTracingPipeline* pipeline() const { return pipeline_.get(); }
  const std::string& debugName() const { return debugName_; }
  bool hasRayGeneration() const { return hasRayGeneration_; }

 private:
  void checkRecord(const char* call, const std::string& exportName, const void* localData,
                   size_t localBytes) const;
  std::shared_ptr<ValidationRayTracingPipeline> pipeline_;
  ShaderTableHandle backend_;
  std::string debugName_;
  bool hasRayGeneration_ = false;
};

class ValidationBindingSet final : public IBindingSet {
 public:
  ValidationBindingSet(BindingSetHandle backend, BindingLayout layout)
      : backend_(std::move(backend)), layout_(std::move(layout)) {}
  const BindingSetDesc& desc() const override { return backend_->desc(); }
  IBindingSet* backend() const { return backend_.get(); }
  // The layout of its space in the pipeline it was created for.
  const BindingLayout& layout() const { return layout_; }

 private:
  BindingSetHandle backend_;
  BindingLayout layout_;
};

class ValidationCommandList final : public ICommandList {
 public:
  ValidationCommandList(CommandListHandle backend, std::string debugName, const IDevice* device);

  void open() override;
  void close() override;
  void writeBuffer(IBuffer* buffer, const void* data, size_t bytes, uint64_t offset) override;
  void writeTexture(ITexture* texture, const void* data, size_t bytes) override;
  void copyBuffer(IBuffer* dst, uint64_t dstOffset, IBuffer* src, uint64_t srcOffset,
                  uint64_t bytes) override;
  void copyTextureToBuffer(ITexture* src, IBuffer* dst, uint64_t dstOffset) override;
  void copyTexture(ITexture* dst, ITexture* src) override;
  void clearTextureFloat(ITexture* texture, float r, float g, float b, float a) override;
  void clearBufferUint(IBuffer* buffer, uint32_t value) override;
  void setBufferState(IBuffer* buffer, ResourceState state) override;
  void setTextureState(ITexture* texture, ResourceState state) override;
  void setAccelStructState(rt::IAccelStruct* as, ResourceState state) override;
  void buildBottomLevelAccelStruct(rt::IAccelStruct* as) override;
  void buildTopLevelAccelStruct(rt::IAccelStruct* as, const rt::InstanceDesc* instances,
                                uint32_t count) override;
  void setRayTracingState(const RayTracingState& state) override;
  void setComputeState(const ComputeState& state) override;
  void setGraphicsState(const GraphicsState& state) override;
  void beginRendering(ITexture* target, const float* clearColor) override;
  void endRendering() override;
  void setViewport(const Viewport& viewport) override;
  void setScissor(const ScissorRect& rect) override;
  void drawIndexed(uint32_t indexCount, uint32_t firstIndex, int32_t vertexOffset) override;
  void setPushConstants(const void* data, size_t bytes) override;
  void dispatchRays(uint32_t width, uint32_t height, uint32_t depth) override;
  void dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) override;
  void beginTimerQuery(ITimerQuery* query) override;
  void endTimerQuery(ITimerQuery* query) override;

  ICommandList* backend() const { return backend_.get(); }
  const std::string& debugName() const { return debugName_; }
  bool isOpen() const { return open_; }
  const IDevice* device() const { return device_; }

 private:
  void requireOpen(const char* call) const;
  // Open and outside beginRendering/endRendering: copies, barriers, builds,
  // dispatches and queries cannot be recorded inside a Vulkan render pass.
  void requireOutsideRendering(const char* call) const;
  void requireInsideRendering(const char* call) const;
  // Checks the binding sets against the pipeline's layout and returns the
  // backend's sets, in the same order.
  std::vector<IBindingSet*> checkBindingSets(const char* call, const PipelineBindingLayout& layout,
                                             const std::vector<IBindingSet*>& sets,
                                             const std::string& pipelineName) const;
  enum class Bound : uint8_t { Nothing, RayTracing, Compute, Graphics };

  CommandListHandle backend_;
  std::string debugName_;
  const IDevice* device_;
  bool open_ = false;
  Bound bound_ = Bound::Nothing;
  uint32_t boundPushConstantBytes_ = 0;
  std::string boundPipelineName_;
  std::set<const ITimerQuery*> runningQueries_;
  ITexture* renderTarget_ = nullptr;  // between beginRendering and endRendering
  const GraphicsPipelineDesc* boundGraphics_ = nullptr;
  const BufferDesc* boundIndexBuffer_ = nullptr;
  uint64_t boundIndexOffset_ = 0;
  uint32_t boundIndexBytes_ = 0;
};

class ValidationSwapchain final : public ISwapchain {
 public:
  explicit ValidationSwapchain(SwapchainHandle backend) : backend_(std::move(backend)) {}
  const SwapchainDesc& desc() const override { return backend_->desc(); }
  Format format() const override { return backend_->format(); }
  ITexture* acquireNextImage() override;
  bool present(ICommandList* commandList) override;
  void resize(uint32_t width, uint32_t height) override { backend_->resize(width, height); }
  void setVsync(bool vsync) override { backend_->setVsync(vsync); }
  uint32_t imageCount() const override { return backend_->imageCount(); }
  ISwapchain* backend() const { return backend_.get(); }

 private:
  SwapchainHandle backend_;
  ITexture* acquired_ = nullptr;
};

class ValidationDevice final : public IDevice {
 public:
  explicit ValidationDevice(DeviceHandle backend) : backend_(std::move(backend)) {}
  const char* backendName() const override { return backend_->backendName(); }
  const AdapterInfo& adapter() const override { return backend_->adapter(); }
  BufferHandle createBuffer(const BufferDesc& desc) override;
  TextureHandle createTexture(const TextureDesc& desc) override;
  SamplerHandle createSampler(const SamplerDesc& desc) override {
    return backend_->createSampler(desc);
  }
  rt::AccelStructHandle createAccelStruct(const rt::AccelStructDesc& desc) override;
  RayTracingPipelineHandle createRayTracingPipeline(const RayTracingPipelineDesc& desc) override;
  ComputePipelineHandle createComputePipeline(const ComputePipelineDesc& desc) override;
  GraphicsPipelineHandle createGraphicsPipeline(const GraphicsPipelineDesc& desc) override;
  BindingSetHandle createBindingSet(const BindingSetDesc& desc, const IPipeline& pipeline) override;
  TimerQueryHandle createTimerQuery() override { return backend_->createTimerQuery(); }
  CommandListHandle createCommandList(const std::string& debugName) override;
  SwapchainHandle createSwapchain(const SwapchainDesc& desc) override;
  void submit(ICommandList* commandList) override;
  void waitForIdle() override { backend_->waitForIdle(); }
  double timerQuerySeconds(ITimerQuery* query) override {
    return backend_->timerQuerySeconds(query);
  }
  uint64_t validationMessageCount() const override { return backend_->validationMessageCount(); }
  IDevice& backend() const { return *backend_; }

 private:
  DeviceHandle backend_;
};

// The name of a resource in errors.
inline std::string nameOf(const BufferDesc& d) {
  return fmt::format("buffer '{}'", d.debugName);
}
inline std::string nameOf(const TextureDesc& d) {
  return fmt::format("texture '{}'", d.debugName);
}

}  // namespace penumbra::rhi::validation
