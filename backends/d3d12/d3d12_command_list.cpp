// Command recording: copies, clears, barriers, acceleration-structure
// builds, pipeline state, DispatchRays/Dispatch, draws and timestamps.
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "d3d12_backend.h"
#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {
namespace {

// RTV slots of a command list's own RTV heap (see rtvHeap_).
constexpr uint32_t kRtvDescriptors = 16;

bool isWriteState(rhi::ResourceState s) {
  return s == rhi::ResourceState::UnorderedAccess || s == rhi::ResourceState::AccelStructWrite;
}

D3D12_RESOURCE_BARRIER transition(ID3D12Resource* resource, D3D12_RESOURCE_STATES from,
                                  D3D12_RESOURCE_STATES to) {
  D3D12_RESOURCE_BARRIER b{};
  b.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
  b.Transition.pResource = resource;
  b.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
  b.Transition.StateBefore = from;
  b.Transition.StateAfter = to;
  return b;
}

}  // namespace

D3D12CommandList::D3D12CommandList(D3D12Device& device, const std::string& debugName)
    : device_(device), debugName_(debugName) {
  check(device_.handle()->CreateCommandAllocator(D3D12_COMMAND_LIST_TYPE_DIRECT,
                                                 IID_PPV_ARGS(&allocator_)),
        "CreateCommandAllocator");
  setName(allocator_.Get(), debugName + " allocator");
  // CreateCommandList1 makes the list closed, so open() can always Reset it.
  check(device_.handle()->CreateCommandList1(0, D3D12_COMMAND_LIST_TYPE_DIRECT,
                                             D3D12_COMMAND_LIST_FLAG_NONE, IID_PPV_ARGS(&list_)),
        "CreateCommandList1 (ID3D12GraphicsCommandList4)");
  setName(list_.Get(), debugName);
  rtvHeap_ = std::make_unique<DescriptorHeap>(device_.handle(), D3D12_DESCRIPTOR_HEAP_TYPE_RTV, kRtvDescriptors,
                                              false, debugName + " RTV heap");
  rtvDescriptors_ = rtvHeap_->allocate(kRtvDescriptors);
}

// D3D12: fence wait for the list's previous submission (resetting an
// allocator the GPU still reads is an error) + allocator Reset + list Reset.
D3D12CommandList::~D3D12CommandList() { device_.forgetSubmitted(this); }

void D3D12CommandList::open() {
  device_.waitForFence(submissionFence_);
  releaseTransientResources();
  // From here on the upload buffers are this recording's: a waitForIdle
  // while it records must leave them alone.
  device_.forgetSubmitted(this);
  check(allocator_->Reset(), "ID3D12CommandAllocator::Reset");
  check(list_->Reset(allocator_.Get(), nullptr), "ID3D12GraphicsCommandList::Reset");
  // One heap of each type may be bound at a time: the device's CBV/SRV/UAV
  // heap and its sampler heap hold every binding set's tables.
  ID3D12DescriptorHeap* heaps[] = {device_.shaderVisibleHeap().heap(),
                                   device_.samplerHeap().heap()};
  list_->SetDescriptorHeaps(2, heaps);
  boundRootSignature_ = nullptr;
  graphicsBound_ = false;
  nextRtv_ = 0;
}

void D3D12CommandList::close() {
  check(list_->Close(), "ID3D12GraphicsCommandList::Close");
}

void D3D12CommandList::releaseTransientResources() {
  transient_.clear();
  transientDescriptors_.clear();
}

std::shared_ptr<D3D12Buffer> D3D12CommandList::makeTransientBuffer(uint64_t bytes,
                                                                   rhi::BufferUsage usage,
                                                                   rhi::MemoryLocation memory,
                                                                   const char* name) {
  rhi::BufferDesc desc;
  desc.byteSize = std::max<uint64_t>(bytes, 4);
  desc.usage = usage;
  desc.memory = memory;
  desc.debugName = name;
  auto buffer = std::make_shared<D3D12Buffer>(device_, desc);
  transient_.push_back(buffer);
  return buffer;
}

void D3D12CommandList::uavBarrier(ID3D12Resource* resource) {
  D3D12_RESOURCE_BARRIER b{};
  b.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
  b.UAV.pResource = resource;  // nullptr: every UAV access
  list_->ResourceBarrier(1, &b);
}

// D3D12: a transition barrier between the states' D3D12 equivalents, or a
// UAV barrier when a resource stays in UNORDERED_ACCESS. Upload and readback
// buffers never change state in D3D12; only the RHI state is recorded.
void D3D12CommandList::setBufferState(rhi::IBuffer* buffer, rhi::ResourceState state) {
  auto* b = static_cast<D3D12Buffer*>(buffer);
  const rhi::ResourceState old = buffer->state;
  buffer->state = state;
  if (b->hasFixedState()) return;
  const auto from = toResourceStates(old), to = toResourceStates(state);
  if (from != to) {
    auto barrier = transition(b->resource(), from, to);
    list_->ResourceBarrier(1, &barrier);
  } else if (isWriteState(old)) {
    uavBarrier(b->resource());
  }
}

void D3D12CommandList::setTextureState(rhi::ITexture* texture, rhi::ResourceState state) {
  auto* t = static_cast<D3D12Texture*>(texture);
  const rhi::ResourceState old = texture->state;
  texture->state = state;
  const auto from = toResourceStates(old), to = toResourceStates(state);
  if (from != to) {
    auto barrier = transition(t->resource(), from, to);
    list_->ResourceBarrier(1, &barrier);
  } else if (isWriteState(old)) {
    uavBarrier(t->resource());
  }
}

// Acceleration structures live in RAYTRACING_ACCELERATION_STRUCTURE for
// good; ordering a build against later reads (or a read against a rebuild)
// takes a UAV barrier on the structure.
void D3D12CommandList::setAccelStructState(rhi::rt::IAccelStruct* as, rhi::ResourceState state) {
  const rhi::ResourceState old = as->state;
  as->state = state;
  if (old != rhi::ResourceState::Undefined && (isWriteState(old) || isWriteState(state)))
    uavBarrier(static_cast<D3D12AccelStruct*>(as)->resource());
}

void D3D12CommandList::writeBuffer(rhi::IBuffer* buffer, const void* data, size_t bytes,
                                   uint64_t offset) {
  if (bytes == 0) return;
  auto staging = makeTransientBuffer(bytes, rhi::BufferUsage::CopySource,
                                     rhi::MemoryLocation::Upload, "writeBuffer staging");
  std::memcpy(staging->mappedData(), data, bytes);
  setBufferState(buffer, rhi::ResourceState::CopyDest);
  list_->CopyBufferRegion(static_cast<D3D12Buffer*>(buffer)->resource(), offset,
                          staging->resource(), 0, bytes);
}

// D3D12: an upload-heap buffer holding each level's rows padded to
// D3D12_TEXTURE_DATA_PITCH_ALIGNMENT (256 bytes), each level placed at a
// multiple of D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT (512), copied with one
// CopyTextureRegion per level from its placed footprint into subresource
// `level`. `bytes` is every level, tightly packed (checked by the validation layer).
void D3D12CommandList::writeTexture(rhi::ITexture* texture, const void* data, size_t /*bytes*/) {
  auto* t = static_cast<D3D12Texture*>(texture);
  const auto& d = texture->desc();
  struct Level {
    uint32_t width, height;
    uint64_t rowBytes, pitch, offset;
  };
  std::vector<Level> levels;
  uint64_t stagingBytes = 0;
  for (uint32_t i = 0; i < d.mipLevels; ++i) {
    Level l{std::max(1u, d.width >> i), std::max(1u, d.height >> i), 0, 0, 0};
    l.rowBytes = uint64_t(l.width) * rhi::formatByteSize(d.format);
    l.pitch = rhi::alignUp(l.rowBytes, D3D12_TEXTURE_DATA_PITCH_ALIGNMENT);
    l.offset = rhi::alignUp(stagingBytes, D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT);
    stagingBytes = l.offset + l.pitch * l.height;
    levels.push_back(l);
  }
  // Upload-heap committed resources start 64 KiB aligned, beyond the
  // 512-byte placement alignment footprints need.
  auto staging = makeTransientBuffer(stagingBytes, rhi::BufferUsage::CopySource,
                                     rhi::MemoryLocation::Upload, "writeTexture staging");
  auto* dst = static_cast<uint8_t*>(staging->mappedData());
  const auto* src = static_cast<const uint8_t*>(data);
  setTextureState(texture, rhi::ResourceState::CopyDest);
  for (uint32_t i = 0; i < d.mipLevels; ++i) {
    const Level& l = levels[i];
    for (uint32_t row = 0; row < l.height; ++row)
      std::memcpy(dst + l.offset + row * l.pitch, src + row * l.rowBytes, l.rowBytes);
    src += l.rowBytes * l.height;
    D3D12_TEXTURE_COPY_LOCATION from{};
    from.pResource = staging->resource();
    from.Type = D3D12_TEXTURE_COPY_TYPE_PLACED_FOOTPRINT;
    from.PlacedFootprint.Offset = l.offset;
    from.PlacedFootprint.Footprint.Format = t->format();
    from.PlacedFootprint.Footprint.Width = l.width;
    from.PlacedFootprint.Footprint.Height = l.height;
    from.PlacedFootprint.Footprint.Depth = 1;
    from.PlacedFootprint.Footprint.RowPitch = UINT(l.pitch);
    D3D12_TEXTURE_COPY_LOCATION to{};
    to.pResource = t->resource();
    to.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
    to.SubresourceIndex = i;
    list_->CopyTextureRegion(&to, 0, 0, 0, &from, nullptr);
  }
}

void D3D12CommandList::copyBuffer(rhi::IBuffer* dst, uint64_t dstOffset, rhi::IBuffer* src,
                                  uint64_t srcOffset, uint64_t bytes) {
  setBufferState(src, rhi::ResourceState::CopySource);
  setBufferState(dst, rhi::ResourceState::CopyDest);
  list_->CopyBufferRegion(static_cast<D3D12Buffer*>(dst)->resource(), dstOffset,
                          static_cast<D3D12Buffer*>(src)->resource(), srcOffset, bytes);
  if (dst->desc().memory == rhi::MemoryLocation::Readback)
    setBufferState(dst, rhi::ResourceState::HostRead);
}

// D3D12: CopyTextureRegion into a placed footprint. Footprint rows are
// padded to 256 bytes and placed 512-byte aligned; when the tight layout
// the RHI promises differs, the rows go to a scratch buffer first and are
// repacked with one CopyBufferRegion per row.
void D3D12CommandList::copyTextureToBuffer(rhi::ITexture* src, rhi::IBuffer* dst,
                                           uint64_t dstOffset) {
  auto* texture = static_cast<D3D12Texture*>(src);
  auto* buffer = static_cast<D3D12Buffer*>(dst);
  const auto& d = src->desc();
  const uint64_t rowBytes = uint64_t(d.width) * rhi::formatByteSize(d.format);
  setTextureState(src, rhi::ResourceState::CopySource);

  const uint64_t pitch = rhi::alignUp(rowBytes, D3D12_TEXTURE_DATA_PITCH_ALIGNMENT);
  const bool direct = pitch == rowBytes && dstOffset % D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT == 0;
  std::shared_ptr<D3D12Buffer> staging;
  ID3D12Resource* target = buffer->resource();
  uint64_t targetOffset = dstOffset;
  if (!direct) {
    staging = makeTransientBuffer(pitch * d.height,
                                  rhi::BufferUsage::CopyDest | rhi::BufferUsage::CopySource,
                                  rhi::MemoryLocation::DeviceLocal, "texture readback rows");
    setBufferState(staging.get(), rhi::ResourceState::CopyDest);
    target = staging->resource();
    targetOffset = 0;
  } else {
    setBufferState(dst, rhi::ResourceState::CopyDest);
  }
  D3D12_TEXTURE_COPY_LOCATION from{};
  from.pResource = texture->resource();
  from.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
  from.SubresourceIndex = 0;
  D3D12_TEXTURE_COPY_LOCATION to{};
  to.pResource = target;
  to.Type = D3D12_TEXTURE_COPY_TYPE_PLACED_FOOTPRINT;
  to.PlacedFootprint.Offset = targetOffset;
  to.PlacedFootprint.Footprint.Format = texture->format();
  to.PlacedFootprint.Footprint.Width = d.width;
  to.PlacedFootprint.Footprint.Height = d.height;
  to.PlacedFootprint.Footprint.Depth = 1;
  to.PlacedFootprint.Footprint.RowPitch = UINT(pitch);
  list_->CopyTextureRegion(&to, 0, 0, 0, &from, nullptr);
  if (!direct) {
    setBufferState(staging.get(), rhi::ResourceState::CopySource);
    setBufferState(dst, rhi::ResourceState::CopyDest);
    for (uint32_t row = 0; row < d.height; ++row)
      list_->CopyBufferRegion(buffer->resource(), dstOffset + row * rowBytes, staging->resource(),
                              row * pitch, rowBytes);
  }
  if (dst->desc().memory == rhi::MemoryLocation::Readback)
    setBufferState(dst, rhi::ResourceState::HostRead);
}

// D3D12: CopyTextureRegion between subresource 0 of each; unlike Vulkan's
// blit there is no conversion, so the formats must match (the D3D12
// swapchain is RGBA8 for this reason).
void D3D12CommandList::copyTexture(rhi::ITexture* dst, rhi::ITexture* src) {
  const auto &d = dst->desc(), &s = src->desc();
  // The validation layer checked the sizes; D3D12 has no format conversion.
  if (d.format != s.format)
    throw Error(fmt::format("d3d12: copyTexture from '{}' to '{}' needs equal formats",
                            s.debugName, d.debugName));
  setTextureState(src, rhi::ResourceState::CopySource);
  setTextureState(dst, rhi::ResourceState::CopyDest);
  D3D12_TEXTURE_COPY_LOCATION from{};
  from.pResource = static_cast<D3D12Texture*>(src)->resource();
  from.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
  D3D12_TEXTURE_COPY_LOCATION to{};
  to.pResource = static_cast<D3D12Texture*>(dst)->resource();
  to.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
  list_->CopyTextureRegion(&to, 0, 0, 0, &from, nullptr);
}

// D3D12: ClearUnorderedAccessViewFloat, which wants the UAV twice: in the
// shader-visible heap (GPU handle) and in a CPU-only heap (CPU handle). Both
// descriptors live until the list has finished on the GPU.
void D3D12CommandList::clearTextureFloat(rhi::ITexture* texture, float r, float g, float b,
                                         float a) {
  auto* t = static_cast<D3D12Texture*>(texture);
  setTextureState(texture, rhi::ResourceState::UnorderedAccess);
  D3D12_UNORDERED_ACCESS_VIEW_DESC uav{};
  uav.Format = t->format();
  uav.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2D;
  auto gpu = device_.shaderVisibleHeap().allocate(1);
  auto cpu = device_.cpuHeap().allocate(1);
  device_.handle()->CreateUnorderedAccessView(t->resource(), nullptr, &uav, gpu->cpu());
  device_.handle()->CreateUnorderedAccessView(t->resource(), nullptr, &uav, cpu->cpu());
  const FLOAT color[4] = {r, g, b, a};
  list_->ClearUnorderedAccessViewFloat(gpu->gpu(), cpu->cpu(), t->resource(), color, 0, nullptr);
  transientDescriptors_.push_back(std::move(gpu));
  transientDescriptors_.push_back(std::move(cpu));
}

// D3D12: ClearUnorderedAccessViewUint on a raw (R32_TYPELESS) view of the
// whole buffer, both handles as for textures.
void D3D12CommandList::clearBufferUint(rhi::IBuffer* buffer, uint32_t value) {
  auto* b = static_cast<D3D12Buffer*>(buffer);
  setBufferState(buffer, rhi::ResourceState::UnorderedAccess);
  D3D12_UNORDERED_ACCESS_VIEW_DESC uav{};
  uav.Format = DXGI_FORMAT_R32_TYPELESS;
  uav.ViewDimension = D3D12_UAV_DIMENSION_BUFFER;
  uav.Buffer.NumElements = UINT(b->resourceBytes() / 4);
  uav.Buffer.Flags = D3D12_BUFFER_UAV_FLAG_RAW;
  auto gpu = device_.shaderVisibleHeap().allocate(1);
  auto cpu = device_.cpuHeap().allocate(1);
  device_.handle()->CreateUnorderedAccessView(b->resource(), nullptr, &uav, gpu->cpu());
  device_.handle()->CreateUnorderedAccessView(b->resource(), nullptr, &uav, cpu->cpu());
  const UINT values[4] = {value, value, value, value};
  list_->ClearUnorderedAccessViewUint(gpu->gpu(), cpu->cpu(), b->resource(), values, 0, nullptr);
  transientDescriptors_.push_back(std::move(gpu));
  transientDescriptors_.push_back(std::move(cpu));
}

void D3D12CommandList::buildBottomLevelAccelStruct(rhi::rt::IAccelStruct* as) {
  auto* das = static_cast<D3D12AccelStruct*>(as);
  for (const auto& g : das->desc().bottomLevelGeometries) {
    if (g.type == rhi::rt::GeometryType::Triangles) {
      setBufferState(g.triangles.vertexBuffer, rhi::ResourceState::AccelStructBuildInput);
      if (g.triangles.indexBuffer)
        setBufferState(g.triangles.indexBuffer, rhi::ResourceState::AccelStructBuildInput);
      if (g.triangles.transformBuffer)
        setBufferState(g.triangles.transformBuffer, rhi::ResourceState::AccelStructBuildInput);
    } else {
      setBufferState(g.aabbs.buffer, rhi::ResourceState::AccelStructBuildInput);
    }
  }
  setAccelStructState(as, rhi::ResourceState::AccelStructWrite);
  auto scratch = makeTransientBuffer(das->scratchBytes(), rhi::BufferUsage::StorageBuffer,
                                     rhi::MemoryLocation::DeviceLocal, "BLAS scratch");
  setBufferState(scratch.get(), rhi::ResourceState::UnorderedAccess);
  AccelStructBuildInputs inputs = das->buildInputs();
  D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_DESC build{};
  build.DestAccelerationStructureData = das->deviceAddress();
  build.Inputs = inputs.inputs;
  build.ScratchAccelerationStructureData = scratch->deviceAddress();
  list_->BuildRaytracingAccelerationStructure(&build, 0, nullptr);
  // The structure is complete before anything recorded after it. Without
  // this barrier vkd3d-proton (3.0.1) on lavapipe (Mesa 25.0) leaves an AABB
  // structure built after a copy that followed a triangle build without its
  // boxes, and the implicit surfaces vanish (docs/windows.md, "Known
  // problems", tools/d3d12_repro). Builds no longer overlap; Penumbra builds
  // its structures once per scene.
  uavBarrier(das->resource());
}

void D3D12CommandList::buildTopLevelAccelStruct(rhi::rt::IAccelStruct* as,
                                                const rhi::rt::InstanceDesc* instances,
                                                uint32_t count) {
  auto* das = static_cast<D3D12AccelStruct*>(as);
  static_assert(sizeof(rhi::rt::InstanceDesc) == sizeof(D3D12_RAYTRACING_INSTANCE_DESC));
  // Bottom levels built earlier in this list are read by this build; the
  // instances only hold their addresses, so one global UAV barrier orders
  // every earlier AS write before it.
  uavBarrier(nullptr);
  const uint64_t bytes = uint64_t(count) * sizeof(rhi::rt::InstanceDesc);
  // Upload-heap committed resources are 64 KiB aligned, beyond the 16 bytes
  // DXR asks of instance descriptions.
  auto instanceBuffer = makeTransientBuffer(bytes, rhi::BufferUsage::AccelStructBuildInput,
                                            rhi::MemoryLocation::Upload, "TLAS instances");
  if (count > 0) std::memcpy(instanceBuffer->mappedData(), instances, bytes);
  auto scratch = makeTransientBuffer(das->scratchBytes(), rhi::BufferUsage::StorageBuffer,
                                     rhi::MemoryLocation::DeviceLocal, "TLAS scratch");
  setBufferState(scratch.get(), rhi::ResourceState::UnorderedAccess);
  setAccelStructState(as, rhi::ResourceState::AccelStructWrite);
  AccelStructBuildInputs inputs = das->buildInputs(instanceBuffer->deviceAddress(), count);
  D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_DESC build{};
  build.DestAccelerationStructureData = das->deviceAddress();
  build.Inputs = inputs.inputs;
  build.ScratchAccelerationStructureData = scratch->deviceAddress();
  list_->BuildRaytracingAccelerationStructure(&build, 0, nullptr);
}

void D3D12CommandList::transitionBindingSets(const std::vector<rhi::IBindingSet*>& sets) {
  for (auto* s : sets) {
    if (!s) continue;
    auto* set = static_cast<D3D12BindingSet*>(s);
    for (const auto& item : set->desc().items) {
      const rhi::ResourceState state = set->requiredState(item);
      switch (item.type) {
        case rhi::ResourceType::AccelStruct:
          setAccelStructState(item.accelStruct.get(), state);
          break;
        case rhi::ResourceType::StorageBuffer:
        case rhi::ResourceType::ConstantBuffer:
          setBufferState(item.buffer.get(), state);
          break;
        case rhi::ResourceType::StorageTexture:
          setTextureState(item.texture.get(), state);
          break;
        case rhi::ResourceType::SampledTexture:
          for (const auto& texture : item.textures) setTextureState(texture.get(), state);
          break;
        case rhi::ResourceType::Sampler:
          break;  // no resource behind a sampler
      }
    }
  }
}

void D3D12CommandList::bindDescriptorTables(const D3D12RootSignature& rootSignature,
                                            const std::vector<rhi::IBindingSet*>& sets, bool graphics) {
  // The validation layer checked that sets[space] is given for every space the
  // shaders use, made for this layout.
  for (const auto& table : rootSignature.rootLayout().tables) {
    const auto* set = static_cast<const D3D12BindingSet*>(sets.at(table.space));
    if (graphics)
      list_->SetGraphicsRootDescriptorTable(table.rootParameterIndex,
                                            set->tableStart(table.rootParameterIndex));
    else
      list_->SetComputeRootDescriptorTable(table.rootParameterIndex,
                                           set->tableStart(table.rootParameterIndex));
  }
}

// D3D12: SetPipelineState1(state object) + SetComputeRootSignature +
// SetComputeRootDescriptorTable per space; the shader table is uploaded now.
void D3D12CommandList::setRayTracingState(const rhi::RayTracingState& state) {
  auto* pipeline = static_cast<D3D12RayTracingPipeline*>(state.pipeline);
  auto* table = static_cast<D3D12ShaderTable*>(state.shaderTable);
  transitionBindingSets(state.bindingSets);
  boundDispatch_ = table->prepare();
  transient_.push_back(table->buffer());
  list_->SetPipelineState1(pipeline->handle());
  list_->SetComputeRootSignature(pipeline->rootSignature().handle());
  bindDescriptorTables(pipeline->rootSignature(), state.bindingSets);
  boundRootSignature_ = &pipeline->rootSignature();
  graphicsBound_ = false;
}

// D3D12: SetPipelineState + SetComputeRootSignature + descriptor tables.
void D3D12CommandList::setComputeState(const rhi::ComputeState& state) {
  auto* pipeline = static_cast<D3D12ComputePipeline*>(state.pipeline);
  transitionBindingSets(state.bindingSets);
  list_->SetPipelineState(pipeline->handle());
  list_->SetComputeRootSignature(pipeline->rootSignature().handle());
  bindDescriptorTables(pipeline->rootSignature(), state.bindingSets);
  boundRootSignature_ = &pipeline->rootSignature();
  graphicsBound_ = false;
}

// D3D12: SetGraphicsRoot32BitConstants after setGraphicsState, else
// SetComputeRoot32BitConstants, into the root-constants parameter.
void D3D12CommandList::setPushConstants(const void* data, size_t bytes) {
  // The validation layer checked that a pipeline is bound and `bytes` is what
  // its shaders declare, so the root layout has the constants.
  const auto& constants = boundRootSignature_->rootLayout().pushConstants;
  if (graphicsBound_)
    list_->SetGraphicsRoot32BitConstants(constants->rootParameterIndex, UINT(bytes / 4), data, 0);
  else
    list_->SetComputeRoot32BitConstants(constants->rootParameterIndex, UINT(bytes / 4), data, 0);
}

// D3D12: barriers (vertex and index buffers to VERTEX_AND_CONSTANT_BUFFER |
// INDEX_BUFFER; upload-heap buffers stay in GENERIC_READ, which includes
// both, and only their RHI state changes, as setBufferState does for them)
// + SetPipelineState + SetGraphicsRootSignature + SetGraphicsRootDescriptorTable
// per space + IASetPrimitiveTopology(TRIANGLELIST) + IASetVertexBuffers +
// IASetIndexBuffer.
void D3D12CommandList::setGraphicsState(const rhi::GraphicsState& state) {
  auto* pipeline = static_cast<D3D12GraphicsPipeline*>(state.pipeline);
  if (state.vertexBuffer) setBufferState(state.vertexBuffer, rhi::ResourceState::VertexInput);
  if (state.indexBuffer) setBufferState(state.indexBuffer, rhi::ResourceState::VertexInput);
  transitionBindingSets(state.bindingSets);
  list_->SetPipelineState(pipeline->handle());
  list_->SetGraphicsRootSignature(pipeline->rootSignature().handle());
  bindDescriptorTables(pipeline->rootSignature(), state.bindingSets, true);
  list_->IASetPrimitiveTopology(D3D_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  if (state.vertexBuffer) {
    D3D12_VERTEX_BUFFER_VIEW view{};
    view.BufferLocation = state.vertexBuffer->deviceAddress() + state.vertexOffset;
    view.SizeInBytes = UINT(state.vertexBuffer->desc().byteSize - state.vertexOffset);
    view.StrideInBytes = pipeline->desc().vertexLayout.stride;
    list_->IASetVertexBuffers(0, 1, &view);
  }
  if (state.indexBuffer) {
    D3D12_INDEX_BUFFER_VIEW view{};
    view.BufferLocation = state.indexBuffer->deviceAddress() + state.indexOffset;
    view.SizeInBytes = UINT(state.indexBuffer->desc().byteSize - state.indexOffset);
    view.Format = toDxgiFormat(state.indexFormat);  // R16_UINT or R32_UINT
    list_->IASetIndexBuffer(&view);
  }
  boundRootSignature_ = &pipeline->rootSignature();
  graphicsBound_ = true;
}

// D3D12: a transition to RENDER_TARGET + CreateRenderTargetView into the
// list's RTV heap + OMSetRenderTargets + ClearRenderTargetView (with a clear
// colour) + RSSetViewports and RSSetScissorRects over the whole target.
void D3D12CommandList::beginRendering(rhi::ITexture* target, const float* clearColor) {
  auto* t = static_cast<D3D12Texture*>(target);
  setTextureState(target, rhi::ResourceState::RenderTarget);
  // The descriptor is read when the calls below are recorded: the slot may be reused at once.
  const D3D12_CPU_DESCRIPTOR_HANDLE rtv = rtvDescriptors_->cpu(nextRtv_);
  nextRtv_ = (nextRtv_ + 1) % kRtvDescriptors;
  D3D12_RENDER_TARGET_VIEW_DESC view{};
  view.Format = t->format();
  view.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE2D;
  device_.handle()->CreateRenderTargetView(t->resource(), &view, rtv);
  list_->OMSetRenderTargets(1, &rtv, FALSE, nullptr);
  if (clearColor) list_->ClearRenderTargetView(rtv, clearColor, 0, nullptr);
  const auto& d = target->desc();
  setViewport({0.0f, 0.0f, float(d.width), float(d.height)});
  setScissor({0, 0, d.width, d.height});
}

// D3D12: nothing to record; the render target stays bound until the next
// beginRendering (or the list's end).
void D3D12CommandList::endRendering() {}

// D3D12: RSSetViewports, depth range [0, 1].
void D3D12CommandList::setViewport(const rhi::Viewport& viewport) {
  const D3D12_VIEWPORT v{viewport.x, viewport.y, viewport.width, viewport.height, 0.0f, 1.0f};
  list_->RSSetViewports(1, &v);
}

// D3D12: RSSetScissorRects.
void D3D12CommandList::setScissor(const rhi::ScissorRect& rect) {
  const D3D12_RECT r{LONG(rect.x), LONG(rect.y), LONG(rect.x + int64_t(rect.width)),
                     LONG(rect.y + int64_t(rect.height))};
  list_->RSSetScissorRects(1, &r);
}

// D3D12: DrawIndexedInstanced(indexCount, 1, firstIndex, vertexOffset, 0).
void D3D12CommandList::drawIndexed(uint32_t indexCount, uint32_t firstIndex, int32_t vertexOffset) {
  list_->DrawIndexedInstanced(indexCount, 1, firstIndex, vertexOffset, 0);
}

void D3D12CommandList::dispatchRays(uint32_t width, uint32_t height, uint32_t depth) {
  D3D12_DISPATCH_RAYS_DESC desc = boundDispatch_;
  desc.Width = width;
  desc.Height = height;
  desc.Depth = depth;
  list_->DispatchRays(&desc);
}

void D3D12CommandList::dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
  list_->Dispatch(groupsX, groupsY, groupsZ);
}

// D3D12: EndQuery(TIMESTAMP) into slot 0; the end query resolves both.
void D3D12CommandList::beginTimerQuery(rhi::ITimerQuery* query) {
  list_->EndQuery(static_cast<D3D12TimerQuery*>(query)->heap(), D3D12_QUERY_TYPE_TIMESTAMP, 0);
}

// D3D12: EndQuery(TIMESTAMP) into slot 1 + ResolveQueryData into the
// query's readback buffer.
void D3D12CommandList::endTimerQuery(rhi::ITimerQuery* query) {
  auto* q = static_cast<D3D12TimerQuery*>(query);
  list_->EndQuery(q->heap(), D3D12_QUERY_TYPE_TIMESTAMP, 1);
  list_->ResolveQueryData(q->heap(), D3D12_QUERY_TYPE_TIMESTAMP, 0, 2, q->results().resource(), 0);
}

}  // namespace penumbra::d3d12
