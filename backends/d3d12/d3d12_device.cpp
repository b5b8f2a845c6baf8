// The device: queue, fence, descriptor heaps, submission, timestamps and
// debug-layer messages.
#include <fmt/format.h>

#include <algorithm>

#include "d3d12_backend.h"
#include "d3d12_swapchain.h"
#include "penumbra/rhi/fault_injection.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"

namespace penumbra::d3d12 {
namespace {
// Shader-visible CBV/SRV/UAV heap size: binding sets plus one descriptor per
// UAV clear in flight. 65536 is far below every tier's limit (1M on tier 1).
constexpr uint32_t kShaderVisibleDescriptors = 65536;
constexpr uint32_t kCpuDescriptors = 4096;
// D3D12_MAX_SHADER_VISIBLE_SAMPLER_HEAP_SIZE: the most a shader-visible
// sampler heap may hold, shared by every binding set's sampler tables.
constexpr uint32_t kShaderVisibleSamplers = 2048;
}  // namespace

D3D12Device::D3D12Device(ComPtr<IDXGIFactory4> factory, Adapter adapter, bool validation,
                         const rhi::BindingOffsets& bindingOffsets)
    : factory_(std::move(factory)), adapter_(std::move(adapter)), bindingOffsets_(bindingOffsets) {
  check(library().createDevice(adapter_.adapter.Get(), D3D_FEATURE_LEVEL_11_0, IID_PPV_ARGS(&device_)),
        "D3D12CreateDevice (ID3D12Device5)");
  setName(device_.Get(), adapter_.info.name);

  D3D12_FEATURE_DATA_ROOT_SIGNATURE rootSignature{D3D_ROOT_SIGNATURE_VERSION_1_1};
  if (FAILED(device_->CheckFeatureSupport(D3D12_FEATURE_ROOT_SIGNATURE, &rootSignature, sizeof(rootSignature))) ||
      rootSignature.HighestVersion < D3D_ROOT_SIGNATURE_VERSION_1_1)
    throw Error(fmt::format("d3d12: {} does not support root signature 1.1", adapter_.info.name));

  if (validation && SUCCEEDED(device_.As(&infoQueue_))) {
    // Keep only what the tests count: corruption, errors and warnings.
    D3D12_MESSAGE_SEVERITY deny[] = {D3D12_MESSAGE_SEVERITY_INFO, D3D12_MESSAGE_SEVERITY_MESSAGE};
    D3D12_INFO_QUEUE_FILTER filter{};
    filter.DenyList.NumSeverities = UINT(std::size(deny));
    filter.DenyList.pSeverityList = deny;
    infoQueue_->PushStorageFilter(&filter);
  }

  D3D12_COMMAND_QUEUE_DESC queueDesc{};
  queueDesc.Type = D3D12_COMMAND_LIST_TYPE_DIRECT;  // timestamps and, later, presentation
  check(device_->CreateCommandQueue(&queueDesc, IID_PPV_ARGS(&queue_)), "CreateCommandQueue");
  setName(queue_.Get(), "main queue");
  check(queue_->GetTimestampFrequency(&timestampFrequency_), "GetTimestampFrequency");
  check(device_->CreateFence(0, D3D12_FENCE_FLAG_NONE, IID_PPV_ARGS(&fence_)), "CreateFence");
  setName(fence_.Get(), "main queue fence");
  fenceEvent_ = CreateEventA(nullptr, FALSE, FALSE, nullptr);
  if (!fenceEvent_) throw Error("d3d12: CreateEvent for the queue fence failed");

  shaderVisibleHeap_ = std::make_unique<DescriptorHeap>(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV,
                                                        kShaderVisibleDescriptors, true,
                                                        "shader-visible CBV/SRV/UAV heap");
  samplerHeap_ = std::make_unique<DescriptorHeap>(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_SAMPLER,
                                                  kShaderVisibleSamplers, true, "shader-visible sampler heap");
  cpuHeap_ = std::make_unique<DescriptorHeap>(device_.Get(), D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kCpuDescriptors,
                                              false, "CPU CBV/SRV/UAV heap");
}

D3D12Device::~D3D12Device() {
  try {
    waitForIdle();
  } catch (const std::exception& e) {
    log::warning("d3d12: waiting for the GPU at shutdown failed: {}", e.what());
  }
  if (fenceEvent_) CloseHandle(fenceEvent_);
}

void D3D12Device::checkDevice(HRESULT hr, const char* what) const {
  if (hr == DXGI_ERROR_DEVICE_REMOVED || hr == DXGI_ERROR_DEVICE_HUNG || hr == DXGI_ERROR_DEVICE_RESET) {
    drainMessages();
    throw Error(fmt::format("d3d12: {} failed: device removed ({}): the GPU hung or was reset, or "
                            "its driver failed; nothing more can run on it",
                            what, hresultName(device_->GetDeviceRemovedReason())));
  }
  check(hr, what);
}

void D3D12Device::drainMessages() const {
  if (!infoQueue_) return;
  const UINT64 count = infoQueue_->GetNumStoredMessages();
  for (UINT64 i = 0; i < count; ++i) {
    SIZE_T bytes = 0;
    if (FAILED(infoQueue_->GetMessage(i, nullptr, &bytes))) continue;
    std::vector<char> storage(bytes);
    auto* message = reinterpret_cast<D3D12_MESSAGE*>(storage.data());
    if (FAILED(infoQueue_->GetMessage(i, message, &bytes))) continue;
    if (message->Severity == D3D12_MESSAGE_SEVERITY_WARNING)
      log::warning("d3d12 debug layer: {}", message->pDescription);
    else
      log::error("d3d12 debug layer: {}", message->pDescription);
    ++validationMessages_;
  }
  infoQueue_->ClearStoredMessages();
}

uint64_t D3D12Device::validationMessageCount() const {
  drainMessages();
  return validationMessages_;
}

rhi::BufferHandle D3D12Device::createBuffer(const rhi::BufferDesc& desc) {
  return std::make_shared<D3D12Buffer>(*this, desc);
}

rhi::TextureHandle D3D12Device::createTexture(const rhi::TextureDesc& desc) {
  return std::make_shared<D3D12Texture>(*this, desc);
}

rhi::SamplerHandle D3D12Device::createSampler(const rhi::SamplerDesc& desc) {
  return std::make_shared<D3D12Sampler>(desc);
}

rhi::rt::AccelStructHandle D3D12Device::createAccelStruct(const rhi::rt::AccelStructDesc& desc) {
  return std::make_shared<D3D12AccelStruct>(*this, desc);
}

rhi::RayTracingPipelineHandle D3D12Device::createRayTracingPipeline(const rhi::RayTracingPipelineDesc& desc) {
  return std::make_shared<D3D12RayTracingPipeline>(*this, desc);
}

rhi::ComputePipelineHandle D3D12Device::createComputePipeline(const rhi::ComputePipelineDesc& desc) {
  return std::make_shared<D3D12ComputePipeline>(*this, desc);
}

rhi::GraphicsPipelineHandle D3D12Device::createGraphicsPipeline(const rhi::GraphicsPipelineDesc& desc) {
  return std::make_shared<D3D12GraphicsPipeline>(*this, desc);
}

rhi::BindingSetHandle D3D12Device::createBindingSet(const rhi::BindingSetDesc& desc,
                                                    const rhi::IPipeline& pipeline) {
  if (auto* rt = dynamic_cast<const D3D12RayTracingPipeline*>(&pipeline))
    return std::make_shared<D3D12BindingSet>(*this, desc, rt->rootSignature());
  if (auto* cs = dynamic_cast<const D3D12ComputePipeline*>(&pipeline))
    return std::make_shared<D3D12BindingSet>(*this, desc, cs->rootSignature());
  if (auto* gfx = dynamic_cast<const D3D12GraphicsPipeline*>(&pipeline))
    return std::make_shared<D3D12BindingSet>(*this, desc, gfx->rootSignature());
  throw Error("d3d12: createBindingSet needs a pipeline of this device's backend");
}

rhi::TimerQueryHandle D3D12Device::createTimerQuery() { return std::make_shared<D3D12TimerQuery>(*this); }

rhi::CommandListHandle D3D12Device::createCommandList(const std::string& debugName) {
  return std::make_shared<D3D12CommandList>(*this, debugName);
}

rhi::SwapchainHandle D3D12Device::createSwapchain(const rhi::SwapchainDesc& desc) {
  return std::make_shared<D3D12Swapchain>(*this, desc);
}

void D3D12Device::submit(rhi::ICommandList* commandList) {
  auto* list = static_cast<D3D12CommandList*>(commandList);
  // An armed fault injection (rhi/fault_injection.h) reports a removed device.
  if (rhi::faults::shouldFail(rhi::faults::Site::Submit))
    throw Error(fmt::format(
        "d3d12: the device {} was lost submitting command list '{}' "
        "(DXGI_ERROR_DEVICE_REMOVED, injected): the GPU hung or was reset, or its driver "
        "failed; nothing more can run on it",
        adapter().name, list->debugName()));
  ID3D12CommandList* lists[] = {list->handle()};
  queue_->ExecuteCommandLists(1, lists);
  list->setSubmissionFence(signalQueue());
  // A viewer resubmits the same few lists every frame; list them once.
  if (std::find(inFlight_.begin(), inFlight_.end(), list) == inFlight_.end()) inFlight_.push_back(list);
}

uint64_t D3D12Device::signalQueue() {
  checkDevice(queue_->Signal(fence_.Get(), ++fenceValue_), "ID3D12CommandQueue::Signal");
  return fenceValue_;
}

void D3D12Device::waitForFence(uint64_t value) {
  if (fence_->GetCompletedValue() < value) {
    checkDevice(fence_->SetEventOnCompletion(value, fenceEvent_), "ID3D12Fence::SetEventOnCompletion");
    WaitForSingleObject(fenceEvent_, INFINITE);
  }
  // A removed device completes its fence with UINT64_MAX.
  if (fence_->GetCompletedValue() == UINT64_MAX) checkDevice(device_->GetDeviceRemovedReason(), "fence wait");
}

void D3D12Device::waitForIdle() {
  waitForFence(signalQueue());
  for (auto* list : inFlight_) list->releaseTransientResources();
  inFlight_.clear();
  drainMessages();
}

void D3D12Device::forgetSubmitted(D3D12CommandList* list) {
  inFlight_.erase(std::remove(inFlight_.begin(), inFlight_.end(), list), inFlight_.end());
}

double D3D12Device::timerQuerySeconds(rhi::ITimerQuery* query) {
  auto* q = static_cast<D3D12TimerQuery*>(query);
  uint64_t ticks[2] = {};
  std::memcpy(ticks, q->results().mappedData(), sizeof(ticks));
  return double(ticks[1] - ticks[0]) / double(timestampFrequency_);
}

D3D12TimerQuery::D3D12TimerQuery(D3D12Device& device) {
  D3D12_QUERY_HEAP_DESC desc{};
  desc.Type = D3D12_QUERY_HEAP_TYPE_TIMESTAMP;
  desc.Count = 2;
  check(device.handle()->CreateQueryHeap(&desc, IID_PPV_ARGS(&heap_)), "CreateQueryHeap (timestamps)");
  setName(heap_.Get(), "timer query");
  rhi::BufferDesc results;
  results.byteSize = 2 * sizeof(uint64_t);
  results.usage = rhi::BufferUsage::CopyDest;
  results.memory = rhi::MemoryLocation::Readback;
  results.debugName = "timer query results";
  results_ = std::make_unique<D3D12Buffer>(device, results);
}

}  // namespace penumbra::d3d12
