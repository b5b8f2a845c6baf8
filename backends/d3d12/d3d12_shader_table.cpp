// Shader tables: 32-byte shader identifiers plus local root constants, laid
// out with D3D12's 32-byte record and 64-byte table alignment
// (rhi::computeShaderTableLayout) in an upload-heap buffer.
#include <fmt/format.h>

#include <cstring>

#include "d3d12_backend.h"
#include "rhi/shader_table_layout.h"
#include "util/error.h"

namespace penumbra::d3d12 {

D3D12ShaderTable::D3D12ShaderTable(D3D12Device& device, std::shared_ptr<D3D12RayTracingPipeline> pipeline,
                                   std::string debugName)
    : device_(device), pipeline_(std::move(pipeline)), debugName_(std::move(debugName)) {}

D3D12ShaderTable::Record D3D12ShaderTable::makeRecord(const std::string& exportName, const void* data,
                                                      size_t bytes) const {
  pipeline_->shaderIdentifier(exportName);  // throws on an unknown name, now rather than at dispatch
  // The local root signature holds exactly the shader's declared record
  // constants; more data than that would be silently ignored by the GPU.
  const uint32_t capacity = rhi::computeShaderRecordConstants(pipeline_->localRootBytes(exportName)).num32BitValues * 4;
  if (bytes > capacity)
    throw Error(fmt::format("d3d12: shader table '{}': {} bytes of local data for '{}', whose shaders read {}",
                            debugName_, bytes, exportName, capacity));
  Record r{exportName, {}};
  if (bytes > 0) {
    const auto* p = static_cast<const uint8_t*>(data);
    r.localData.assign(p, p + bytes);
  }
  return r;
}

void D3D12ShaderTable::setRayGenerationShader(const std::string& exportName, const void* localData,
                                              size_t localBytes) {
  rayGen_ = makeRecord(exportName, localData, localBytes);
  dirty_ = true;
}

uint32_t D3D12ShaderTable::addMissShader(const std::string& exportName, const void* localData, size_t localBytes) {
  miss_.push_back(makeRecord(exportName, localData, localBytes));
  dirty_ = true;
  return uint32_t(miss_.size() - 1);
}

uint32_t D3D12ShaderTable::addHitGroup(const std::string& exportName, const void* localData, size_t localBytes) {
  hit_.push_back(makeRecord(exportName, localData, localBytes));
  dirty_ = true;
  return uint32_t(hit_.size() - 1);
}

void D3D12ShaderTable::clearMissShaders() {
  miss_.clear();
  dirty_ = true;
}

void D3D12ShaderTable::clearHitGroups() {
  hit_.clear();
  dirty_ = true;
}

D3D12_DISPATCH_RAYS_DESC D3D12ShaderTable::prepare() {
  if (!dirty_) return dispatch_;
  if (rayGen_.exportName.empty())
    throw Error(fmt::format("d3d12: shader table '{}' has no ray generation shader", debugName_));
  auto maxLocal = [](const std::vector<Record>& records) {
    uint32_t m = 0;
    for (const auto& r : records) m = std::max(m, uint32_t(r.localData.size()));
    return m;
  };
  const auto& align = device_.adapter().shaderTable;
  const rhi::ShaderTableLayout layout =
      rhi::computeShaderTableLayout(align, uint32_t(rayGen_.localData.size()), uint32_t(miss_.size()),
                                    maxLocal(miss_), uint32_t(hit_.size()), maxLocal(hit_));
  rhi::BufferDesc desc;
  desc.byteSize = layout.totalBytes;
  desc.usage = rhi::BufferUsage::ShaderTable;
  desc.memory = rhi::MemoryLocation::Upload;
  desc.debugName = debugName_;
  // A fresh buffer each time the records change: a list still in flight
  // keeps the old one alive. Committed resources start 64 KiB aligned, so
  // every region offset that is 64-byte aligned is too.
  buffer_ = std::make_shared<D3D12Buffer>(device_, desc);
  auto* base = static_cast<uint8_t*>(buffer_->mappedData());
  std::memset(base, 0, layout.totalBytes);
  auto write = [&](const rhi::ShaderTableRegion& region, uint32_t i, const Record& r) {
    uint8_t* dst = base + region.offset + region.stride * i;
    std::memcpy(dst, pipeline_->shaderIdentifier(r.exportName), D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES);
    if (!r.localData.empty())
      std::memcpy(dst + D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES, r.localData.data(), r.localData.size());
  };
  write(layout.rayGeneration, 0, rayGen_);
  for (uint32_t i = 0; i < miss_.size(); ++i) write(layout.miss, i, miss_[i]);
  for (uint32_t i = 0; i < hit_.size(); ++i) write(layout.hitGroup, i, hit_[i]);

  const uint64_t address = buffer_->deviceAddress();
  auto range = [&](const rhi::ShaderTableRegion& r) {
    D3D12_GPU_VIRTUAL_ADDRESS_RANGE_AND_STRIDE v{};
    if (r.count == 0) return v;
    v.StartAddress = address + r.offset;
    v.SizeInBytes = r.size;
    v.StrideInBytes = r.stride;
    return v;
  };
  dispatch_ = {};
  dispatch_.RayGenerationShaderRecord.StartAddress = address + layout.rayGeneration.offset;
  dispatch_.RayGenerationShaderRecord.SizeInBytes = layout.rayGeneration.stride;
  dispatch_.MissShaderTable = range(layout.miss);
  dispatch_.HitGroupTable = range(layout.hitGroup);
  dirty_ = false;
  return dispatch_;
}

}  // namespace penumbra::d3d12
