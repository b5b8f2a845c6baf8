// Shader tables: 32-byte shader identifiers plus local root constants, laid
// out with D3D12's 32-byte record and 64-byte table alignment
// (rhi::ShaderTableRecords) in an upload-heap buffer.
#include <fmt/format.h>

#include <cstring>

#include "d3d12_backend.h"
#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {

D3D12ShaderTable::D3D12ShaderTable(D3D12Device& device, std::shared_ptr<D3D12RayTracingPipeline> pipeline,
                                   std::string debugName)
    : device_(device), pipeline_(std::move(pipeline)), debugName_(std::move(debugName)) {}

D3D12_DISPATCH_RAYS_DESC D3D12ShaderTable::prepare() {
  if (!changed()) return dispatch_;
  const auto& align = device_.adapter().shaderTable;
  const rhi::ShaderTableLayout layout = recordLayout(align);
  rhi::BufferDesc desc;
  desc.byteSize = layout.totalBytes;
  desc.usage = rhi::BufferUsage::ShaderTable;
  desc.memory = rhi::MemoryLocation::Upload;
  desc.debugName = debugName_;
  // A fresh buffer each time the records change: a list still in flight
  // keeps the old one alive. Committed resources start 64 KiB aligned, so
  // every region offset that is 64-byte aligned is too.
  buffer_ = std::make_shared<D3D12Buffer>(device_, desc);
  writeRecords(static_cast<uint8_t*>(buffer_->mappedData()), layout, D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES,
               [&](const std::string& name) { return pipeline_->shaderIdentifier(name); });

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
  return dispatch_;
}

}  // namespace penumbra::d3d12
