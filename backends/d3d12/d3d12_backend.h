#pragma once
// The D3D12/DXR implementation of engine/rhi (Windows builds only). Nothing
// outside backends/d3d12 includes this header; apps reach it through
// backends/backend_factory.h.
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "d3d12_common.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/rhi/root_signature_layout.h"
#include "penumbra/rhi/shader_table_records.h"

namespace penumbra::d3d12 {

// d3d12.dll and dxgi.dll, opened at run time (like the Vulkan loader) so a
// machine without D3D12 gets a one-line error instead of a failed start.
struct Library {
  PFN_D3D12_CREATE_DEVICE createDevice = nullptr;
  PFN_D3D12_GET_DEBUG_INTERFACE getDebugInterface = nullptr;
  PFN_D3D12_SERIALIZE_VERSIONED_ROOT_SIGNATURE serializeVersionedRootSignature = nullptr;
  HRESULT(WINAPI* createDxgiFactory2)(UINT, REFIID, void**) = nullptr;
};
const Library& library();

// One DXGI adapter and what it supports.
struct Adapter {
  ComPtr<IDXGIAdapter1> adapter;
  rhi::AdapterInfo info;
};
// Every DXGI adapter in DXGI order (index = --device N), with its DXR tier.
std::vector<Adapter> enumerateAdapters(IDXGIFactory4* factory);
ComPtr<IDXGIFactory4> createFactory(bool debug);

class D3D12Device;

// A range of a descriptor heap. Freed back to its heap when destroyed.
class DescriptorAllocation {
 public:
  DescriptorAllocation(class DescriptorHeap& heap, uint32_t first, uint32_t count)
      : heap_(heap), first_(first), count_(count) {}
  ~DescriptorAllocation();
  DescriptorAllocation(const DescriptorAllocation&) = delete;
  DescriptorAllocation& operator=(const DescriptorAllocation&) = delete;
  D3D12_CPU_DESCRIPTOR_HANDLE cpu(uint32_t index = 0) const;
  D3D12_GPU_DESCRIPTOR_HANDLE gpu(uint32_t index = 0) const;
  uint32_t count() const { return count_; }

 private:
  class DescriptorHeap& heap_;
  uint32_t first_, count_;
};

// A CBV/SRV/UAV, sampler or RTV heap with a first-fit free list of ranges. The
// device owns one shader-visible CBV/SRV/UAV heap (binding sets and UAV-clear
// handles), one shader-visible sampler heap (binding sets' sampler tables)
// and one CPU-only CBV/SRV/UAV heap (the second handle
// ClearUnorderedAccessView* needs); each command list a CPU-only RTV heap.
class DescriptorHeap {
 public:
  DescriptorHeap(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type, uint32_t capacity, bool shaderVisible,
                 const std::string& name);
  std::shared_ptr<DescriptorAllocation> allocate(uint32_t count);
  ID3D12DescriptorHeap* heap() const { return heap_.Get(); }

 private:
  friend class DescriptorAllocation;
  void release(uint32_t first, uint32_t count);
  ComPtr<ID3D12DescriptorHeap> heap_;
  bool shaderVisible_;
  uint32_t capacity_;
  uint32_t increment_ = 0;
  D3D12_CPU_DESCRIPTOR_HANDLE cpuStart_{};
  D3D12_GPU_DESCRIPTOR_HANDLE gpuStart_{};
  std::mutex mutex_;
  std::map<uint32_t, uint32_t> free_;  // first -> count
};

class D3D12Buffer final : public rhi::IBuffer {
 public:
  D3D12Buffer(D3D12Device& device, const rhi::BufferDesc& desc);
  const rhi::BufferDesc& desc() const override { return desc_; }
  uint64_t deviceAddress() const override { return resource_->GetGPUVirtualAddress(); }
  void* mappedData() override;
  ID3D12Resource* resource() const { return resource_.Get(); }
  // Upload heaps stay in GENERIC_READ and readback heaps in COPY_DEST for
  // their whole life (D3D12 requires it): no barriers for those.
  bool hasFixedState() const { return desc_.memory != rhi::MemoryLocation::DeviceLocal; }
  bool isAccelStructStorage() const { return hasFlag(desc_.usage, rhi::BufferUsage::AccelStructStorage); }
  // Bytes of the resource: byteSize, rounded up to 256 for constant buffers.
  uint64_t resourceBytes() const { return resourceBytes_; }

 private:
  rhi::BufferDesc desc_;
  ComPtr<ID3D12Resource> resource_;
  uint64_t resourceBytes_ = 0;
  void* mapped_ = nullptr;
};

class D3D12Texture final : public rhi::ITexture {
 public:
  D3D12Texture(D3D12Device& device, const rhi::TextureDesc& desc);
  // A resource made elsewhere (a swapchain back buffer).
  D3D12Texture(const rhi::TextureDesc& desc, ComPtr<ID3D12Resource> resource);
  const rhi::TextureDesc& desc() const override { return desc_; }
  ID3D12Resource* resource() const { return resource_.Get(); }
  DXGI_FORMAT format() const;

 private:
  rhi::TextureDesc desc_;
  ComPtr<ID3D12Resource> resource_;
};

// D3D12: a D3D12_SAMPLER_DESC; binding sets write it into their range of the
// shader-visible sampler heap with CreateSampler.
class D3D12Sampler final : public rhi::ISampler {
 public:
  explicit D3D12Sampler(const rhi::SamplerDesc& desc);
  const rhi::SamplerDesc& desc() const override { return desc_; }
  const D3D12_SAMPLER_DESC& samplerDesc() const { return samplerDesc_; }

 private:
  rhi::SamplerDesc desc_;
  D3D12_SAMPLER_DESC samplerDesc_{};
};

// Geometry descriptions for BuildRaytracingAccelerationStructure and
// GetRaytracingAccelerationStructurePrebuildInfo, derived from an AccelStructDesc.
struct AccelStructBuildInputs {
  std::vector<D3D12_RAYTRACING_GEOMETRY_DESC> geometries;
  D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS inputs{};
};

class D3D12AccelStruct final : public rhi::rt::IAccelStruct {
 public:
  D3D12AccelStruct(D3D12Device& device, const rhi::rt::AccelStructDesc& desc);
  const rhi::rt::AccelStructDesc& desc() const override { return desc_; }
  uint64_t deviceAddress() const override { return storage_->deviceAddress(); }
  ID3D12Resource* resource() const { return storage_->resource(); }
  uint64_t scratchBytes() const { return scratchBytes_; }
  // For a top level, `instanceAddress`/`instanceCount` describe the instance array.
  AccelStructBuildInputs buildInputs(uint64_t instanceAddress = 0, uint32_t instanceCount = 0) const;

 private:
  rhi::rt::AccelStructDesc desc_;
  std::unique_ptr<D3D12Buffer> storage_;
  uint64_t scratchBytes_ = 0;
};

// The global root signature of a pipeline, built from its shaders' merged
// binding layout through rhi::computeRootSignatureLayout. `flags` adds
// D3D12_ROOT_SIGNATURE_FLAGS (graphics pipelines: ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT).
class D3D12RootSignature {
 public:
  D3D12RootSignature(D3D12Device& device, rhi::PipelineBindingLayout layout, const std::string& name,
                     D3D12_ROOT_SIGNATURE_FLAGS flags = D3D12_ROOT_SIGNATURE_FLAG_NONE);
  const rhi::PipelineBindingLayout& bindingLayout() const { return layout_; }
  const rhi::RootSignatureLayout& rootLayout() const { return rootLayout_; }
  ID3D12RootSignature* handle() const { return rootSignature_.Get(); }

 private:
  rhi::PipelineBindingLayout layout_;
  rhi::RootSignatureLayout rootLayout_;
  ComPtr<ID3D12RootSignature> rootSignature_;
};

// Serializes (D3D12SerializeVersionedRootSignature) and creates a root
// signature; names it `name`. Serializer errors become penumbra::Error.
ComPtr<ID3D12RootSignature> createRootSignature(D3D12Device& device,
                                                const D3D12_VERSIONED_ROOT_SIGNATURE_DESC& desc,
                                                const std::string& name);

class D3D12ComputePipeline final : public rhi::IComputePipeline {
 public:
  D3D12ComputePipeline(D3D12Device& device, const rhi::ComputePipelineDesc& desc);
  const rhi::PipelineBindingLayout& bindingLayout() const override { return rootSignature_->bindingLayout(); }
  const D3D12RootSignature& rootSignature() const { return *rootSignature_; }
  ID3D12PipelineState* handle() const { return pipeline_.Get(); }

 private:
  std::unique_ptr<D3D12RootSignature> rootSignature_;
  ComPtr<ID3D12PipelineState> pipeline_;
};

// D3D12: ID3D12PipelineState from CreateGraphicsPipelineState (TRIANGLE
// topology, CULL_NONE, depth off, one RTV format, opaque or alpha blending,
// TEXCOORD<location> input elements) + a root signature built from the
// merged layouts of the vertex and pixel shaders.
class D3D12GraphicsPipeline final : public rhi::IGraphicsPipeline {
 public:
  D3D12GraphicsPipeline(D3D12Device& device, const rhi::GraphicsPipelineDesc& desc);
  const rhi::GraphicsPipelineDesc& desc() const override { return desc_; }
  const rhi::PipelineBindingLayout& bindingLayout() const override { return rootSignature_->bindingLayout(); }
  const D3D12RootSignature& rootSignature() const { return *rootSignature_; }
  ID3D12PipelineState* handle() const { return pipeline_.Get(); }

 private:
  rhi::GraphicsPipelineDesc desc_;
  std::unique_ptr<D3D12RootSignature> rootSignature_;
  ComPtr<ID3D12PipelineState> pipeline_;
};

class D3D12RayTracingPipeline final : public rhi::IRayTracingPipeline,
                                      public std::enable_shared_from_this<D3D12RayTracingPipeline> {
 public:
  D3D12RayTracingPipeline(D3D12Device& device, const rhi::RayTracingPipelineDesc& desc);
  const rhi::RayTracingPipelineDesc& desc() const override { return desc_; }
  const rhi::PipelineBindingLayout& bindingLayout() const override { return rootSignature_->bindingLayout(); }
  rhi::ShaderTableHandle createShaderTable(const std::string& debugName) override;
  const D3D12RootSignature& rootSignature() const { return *rootSignature_; }
  ID3D12StateObject* handle() const { return stateObject_.Get(); }
  // The 32-byte shader identifier of a raygen/miss shader or hit group, by RHI export name.
  const void* shaderIdentifier(const std::string& exportName) const;
  // Bytes of local root constants the record of `exportName` may carry.
  uint32_t localRootBytes(const std::string& exportName) const;

 private:
  D3D12Device& device_;
  rhi::RayTracingPipelineDesc desc_;
  std::unique_ptr<D3D12RootSignature> rootSignature_;
  std::vector<ComPtr<ID3D12RootSignature>> localRootSignatures_;
  ComPtr<ID3D12StateObject> stateObject_;
  ComPtr<ID3D12StateObjectProperties> properties_;
  std::map<std::string, std::wstring> d3dNames_;     // RHI export name -> DXR export name
  std::map<std::string, uint32_t> localRootBytes_;  // RHI export name -> record bytes
};

// A binding set: the descriptors of one space, written into one range of
// the matching shader-visible heap per descriptor table of that space (the
// CBV/SRV/UAV table, the sampler table, one per unbounded array), in the
// order of the root signature's tables.
class D3D12BindingSet final : public rhi::IBindingSet {
 public:
  D3D12BindingSet(D3D12Device& device, const rhi::BindingSetDesc& desc, const D3D12RootSignature& rootSignature);
  const rhi::BindingSetDesc& desc() const override { return desc_; }
  // Where the descriptor table at root parameter `rootParameterIndex` starts.
  D3D12_GPU_DESCRIPTOR_HANDLE tableStart(uint32_t rootParameterIndex) const;
  // The state the shaders need `item` in (SRV, UAV or CBV per its descriptor range).
  rhi::ResourceState requiredState(const rhi::BindingSetItem& item) const;

 private:
  rhi::BindingSetDesc desc_;
  std::map<uint32_t, std::shared_ptr<DescriptorAllocation>> tables_;  // root parameter -> heap range
  std::map<uint32_t, rhi::DescriptorRangeType> rangeTypes_;           // slot -> range type
};

// The records are rhi::ShaderTableRecords'; this adds the upload into an
// upload-heap buffer and the DispatchRays ranges.
class D3D12ShaderTable final : public rhi::ShaderTableRecords {
 public:
  D3D12ShaderTable(D3D12Device& device, std::shared_ptr<D3D12RayTracingPipeline> pipeline, std::string debugName);

  // Uploads the records if they changed and returns the DispatchRays ranges
  // (width/height/depth left for the caller).
  D3D12_DISPATCH_RAYS_DESC prepare();
  std::shared_ptr<D3D12Buffer> buffer() const;

 private:
  D3D12Device& device_;
  std::shared_ptr<D3D12RayTracingPipeline> pipeline_;
  std::string debugName_;
};

class D3D12TimerQuery final : public rhi::ITimerQuery {
 public:
  explicit D3D12TimerQuery(D3D12Device& device);
  ID3D12QueryHeap* heap() const { return heap_.Get(); }
  D3D12Buffer& results() const { return *results_; }

 private:
  ComPtr<ID3D12QueryHeap> heap_;
  std::unique_ptr<D3D12Buffer> results_;  // two resolved uint64 ticks (readback heap)
};

class D3D12CommandList final : public rhi::ICommandList {
 public:
  D3D12CommandList(D3D12Device& device, const std::string& debugName);
  ~D3D12CommandList() override;
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
  void setPushConstants(const void* data, size_t bytes) override;
  void setGraphicsState(const rhi::GraphicsState& state) override;
  void beginRendering(rhi::ITexture* target, const float* clearColor) override;
  void endRendering() override;
  void setViewport(const rhi::Viewport& viewport) override;
  void setScissor(const rhi::ScissorRect& rect) override;
  void drawIndexed(uint32_t indexCount, uint32_t firstIndex, int32_t vertexOffset) override;
  void dispatchRays(uint32_t width, uint32_t height, uint32_t depth) override;
  void dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) override;
  void beginTimerQuery(rhi::ITimerQuery* query) override;
  void endTimerQuery(rhi::ITimerQuery* query) override;

  ID3D12GraphicsCommandList4* handle() const { return list_.Get(); }
  const std::string& debugName() const { return debugName_; }
  // Called by the device once the GPU finished this list's work.
  void releaseTransientResources();
  // The queue fence value that marks this list's last submission as done.
  void setSubmissionFence(uint64_t value) { submissionFence_ = value; }

 private:
  std::shared_ptr<D3D12Buffer> makeTransientBuffer(uint64_t bytes, rhi::BufferUsage usage,
                                                   rhi::MemoryLocation memory, const char* name);
  void transitionBindingSets(const std::vector<rhi::IBindingSet*>& sets);
  // SetGraphicsRootDescriptorTable when `graphics`, else SetComputeRootDescriptorTable.
  void bindDescriptorTables(const D3D12RootSignature& rootSignature, const std::vector<rhi::IBindingSet*>& sets,
                            bool graphics = false);
  void uavBarrier(ID3D12Resource* resource);
  D3D12Device& device_;
  std::string debugName_;
  ComPtr<ID3D12CommandAllocator> allocator_;
  ComPtr<ID3D12GraphicsCommandList4> list_;
  // beginRendering's RTVs: a small non-shader-visible heap of the list's own,
  // used round-robin from slot 0 on each open(). D3D12 copies an RTV into
  // the list when OMSetRenderTargets / ClearRenderTargetView are recorded, so
  // a slot may be rewritten right after; nothing has to outlive recording.
  // (The heap is declared before its allocation, which must die first.)
  std::unique_ptr<DescriptorHeap> rtvHeap_;
  std::shared_ptr<DescriptorAllocation> rtvDescriptors_;
  uint32_t nextRtv_ = 0;
  const D3D12RootSignature* boundRootSignature_ = nullptr;
  bool graphicsBound_ = false;  // push constants go to the graphics root, else the compute root
  D3D12_DISPATCH_RAYS_DESC boundDispatch_{};
  std::vector<std::shared_ptr<D3D12Buffer>> transient_;
  std::vector<std::shared_ptr<DescriptorAllocation>> transientDescriptors_;
  uint64_t submissionFence_ = 0;
};

class D3D12Device final : public rhi::IDevice {
 public:
  D3D12Device(ComPtr<IDXGIFactory4> factory, Adapter adapter, bool validation,
              const rhi::BindingOffsets& bindingOffsets);
  ~D3D12Device() override;
  // The shaders' register shifts and root-constant spaces, which root
  // signatures map reflected bindings back through.
  const rhi::BindingOffsets& bindingOffsets() const { return bindingOffsets_; }
  const char* backendName() const override { return "d3d12"; }
  const rhi::AdapterInfo& adapter() const override { return adapter_.info; }
  rhi::BufferHandle createBuffer(const rhi::BufferDesc& desc) override;
  rhi::TextureHandle createTexture(const rhi::TextureDesc& desc) override;
  rhi::SamplerHandle createSampler(const rhi::SamplerDesc& desc) override;
  rhi::rt::AccelStructHandle createAccelStruct(const rhi::rt::AccelStructDesc& desc) override;
  rhi::RayTracingPipelineHandle createRayTracingPipeline(const rhi::RayTracingPipelineDesc& desc) override;
  rhi::ComputePipelineHandle createComputePipeline(const rhi::ComputePipelineDesc& desc) override;
  // D3D12: CreateGraphicsPipelineState + root signature (D3D12GraphicsPipeline).
  rhi::GraphicsPipelineHandle createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) override;
  rhi::BindingSetHandle createBindingSet(const rhi::BindingSetDesc& desc, const rhi::IPipeline& pipeline) override;
  rhi::TimerQueryHandle createTimerQuery() override;
  rhi::CommandListHandle createCommandList(const std::string& debugName) override;
  rhi::SwapchainHandle createSwapchain(const rhi::SwapchainDesc& desc) override;
  void submit(rhi::ICommandList* commandList) override;
  void waitForIdle() override;
  // A list being recorded again, or destroyed, is no longer one whose
  // transient resources waitForIdle may release.
  void forgetSubmitted(D3D12CommandList* list);
  double timerQuerySeconds(rhi::ITimerQuery* query) override;
  uint64_t validationMessageCount() const override;

  ID3D12Device5* handle() const { return device_.Get(); }
  ID3D12CommandQueue* queue() const { return queue_.Get(); }
  IDXGIFactory4* factory() const { return factory_.Get(); }
  // Signals the queue fence and returns the value that marks everything
  // submitted so far; waitForFence blocks until the GPU has reached it.
  uint64_t signalQueue();
  void waitForFence(uint64_t value);
  DescriptorHeap& shaderVisibleHeap() { return *shaderVisibleHeap_; }
  DescriptorHeap& samplerHeap() { return *samplerHeap_; }
  DescriptorHeap& cpuHeap() { return *cpuHeap_; }
  // Throws with the device-removed reason when `hr` is a removal.
  void checkDevice(HRESULT hr, const char* what) const;

 private:
  // Moves debug-layer messages from the info queue to the log and the counter.
  void drainMessages() const;
  ComPtr<IDXGIFactory4> factory_;
  Adapter adapter_;
  rhi::BindingOffsets bindingOffsets_;
  ComPtr<ID3D12Device5> device_;
  ComPtr<ID3D12CommandQueue> queue_;
  ComPtr<ID3D12Fence> fence_;
  HANDLE fenceEvent_ = nullptr;
  uint64_t fenceValue_ = 0;
  uint64_t timestampFrequency_ = 1;
  ComPtr<ID3D12InfoQueue> infoQueue_;
  mutable uint64_t validationMessages_ = 0;
  std::unique_ptr<DescriptorHeap> shaderVisibleHeap_;
  std::unique_ptr<DescriptorHeap> samplerHeap_;
  std::unique_ptr<DescriptorHeap> cpuHeap_;
  std::vector<D3D12CommandList*> inFlight_;
};

// Device listing and creation for backends/backend_factory.cpp.
std::vector<rhi::AdapterInfo> listAdapters();
rhi::DeviceHandle createDevice(const rhi::DeviceCreateInfo& info);

DXGI_FORMAT toDxgiFormat(rhi::Format format);
D3D12_RESOURCE_STATES toResourceStates(rhi::ResourceState state);

}  // namespace penumbra::d3d12
