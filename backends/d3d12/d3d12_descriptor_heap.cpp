// CBV/SRV/UAV and sampler descriptor heaps with a first-fit free list of ranges.
#include <fmt/format.h>

#include "d3d12_backend.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {

DescriptorHeap::DescriptorHeap(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type, uint32_t capacity,
                               bool shaderVisible, const std::string& name)
    : shaderVisible_(shaderVisible), capacity_(capacity) {
  D3D12_DESCRIPTOR_HEAP_DESC desc{};
  desc.Type = type;
  desc.NumDescriptors = capacity;
  desc.Flags = shaderVisible ? D3D12_DESCRIPTOR_HEAP_FLAG_SHADER_VISIBLE : D3D12_DESCRIPTOR_HEAP_FLAG_NONE;
  check(device->CreateDescriptorHeap(&desc, IID_PPV_ARGS(&heap_)), "CreateDescriptorHeap");
  setName(heap_.Get(), name);
  increment_ = device->GetDescriptorHandleIncrementSize(type);
  // Methods returning a struct take a hidden out-parameter in the Windows x64
  // member-function ABI: MSVC emits it itself, other compilers get
  // DirectX-Headers' explicit spelling of it.
#if defined(_MSC_VER)
  cpuStart_ = heap_->GetCPUDescriptorHandleForHeapStart();
  if (shaderVisible) gpuStart_ = heap_->GetGPUDescriptorHandleForHeapStart();
#else
  heap_->GetCPUDescriptorHandleForHeapStart(&cpuStart_);
  if (shaderVisible) heap_->GetGPUDescriptorHandleForHeapStart(&gpuStart_);
#endif
  free_[0] = capacity;
}

std::shared_ptr<DescriptorAllocation> DescriptorHeap::allocate(uint32_t count) {
  std::lock_guard lock(mutex_);
  if (count == 0) count = 1;  // an empty binding set still gets a valid table start
  for (auto it = free_.begin(); it != free_.end(); ++it) {
    if (it->second < count) continue;
    const uint32_t first = it->first, remaining = it->second - count;
    free_.erase(it);
    if (remaining > 0) free_[first + count] = remaining;
    return std::make_shared<DescriptorAllocation>(*this, first, count);
  }
  throw Error(fmt::format("d3d12: descriptor heap full ({} descriptors): {} more requested", capacity_, count));
}

void DescriptorHeap::release(uint32_t first, uint32_t count) {
  std::lock_guard lock(mutex_);
  auto [it, inserted] = free_.emplace(first, count);
  // Coalesce with the neighbours so ranges do not fragment over time.
  auto next = std::next(it);
  if (next != free_.end() && it->first + it->second == next->first) {
    it->second += next->second;
    free_.erase(next);
  }
  if (it != free_.begin()) {
    auto prev = std::prev(it);
    if (prev->first + prev->second == it->first) {
      prev->second += it->second;
      free_.erase(it);
    }
  }
}

DescriptorAllocation::~DescriptorAllocation() { heap_.release(first_, count_); }

D3D12_CPU_DESCRIPTOR_HANDLE DescriptorAllocation::cpu(uint32_t index) const {
  return {heap_.cpuStart_.ptr + SIZE_T(first_ + index) * heap_.increment_};
}

D3D12_GPU_DESCRIPTOR_HANDLE DescriptorAllocation::gpu(uint32_t index) const {
  if (!heap_.shaderVisible_) throw Error("d3d12: GPU handle requested from a CPU-only descriptor heap");
  return {heap_.gpuStart_.ptr + UINT64(first_ + index) * heap_.increment_};
}

}  // namespace penumbra::d3d12
