// Shader tables: 32-byte shader identifiers plus local root constants, laid
// out with D3D12's 32-byte record and 64-byte table alignment
// (rhi::ShaderTableRecords) in an upload-heap buffer.
#include "d3d12_backend.h"

namespace penumbra::d3d12 {

D3D12ShaderTable::D3D12ShaderTable(D3D12Device& device, std::shared_ptr<D3D12RayTracingPipeline> pipeline,
                                   std::string debugName)
    : device_(device), pipeline_(std::move(pipeline)), debugName_(std::move(debugName)) {}

D3D12_DISPATCH_RAYS_DESC D3D12ShaderTable::prepare() {
  // Committed resources start 64 KiB aligned, so every region offset that
  // is 64-byte aligned is too.
  const rhi::ShaderTableRanges& ranges = upload(
      device_.adapter().shaderTable, debugName_,
      [&](const rhi::BufferDesc& desc) { return std::make_shared<D3D12Buffer>(device_, desc); },
      [&](const std::string& name) { return pipeline_->shaderIdentifier(name); });
  auto range = [](const rhi::ShaderTableRange& r) {
    return D3D12_GPU_VIRTUAL_ADDRESS_RANGE_AND_STRIDE{r.address, r.size, r.stride};
  };
  D3D12_DISPATCH_RAYS_DESC dispatch{};
  dispatch.RayGenerationShaderRecord = {ranges.rayGeneration.address, ranges.rayGeneration.size};
  dispatch.MissShaderTable = range(ranges.miss);
  dispatch.HitGroupTable = range(ranges.hitGroup);
  return dispatch;
}

std::shared_ptr<D3D12Buffer> D3D12ShaderTable::buffer() const {
  return std::static_pointer_cast<D3D12Buffer>(uploadBuffer());
}

}  // namespace penumbra::d3d12
