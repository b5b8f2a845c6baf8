// Buffers, textures and acceleration structures: committed resources, one
// heap each (scenes are small; see docs/ARCHITECTURE.md).
#include <fmt/format.h>

#include "d3d12_backend.h"
#include "penumbra/rhi/fault_injection.h"
#include "penumbra/rhi/geometry_input.h"
#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {

DXGI_FORMAT toDxgiFormat(rhi::Format format) {
  switch (format) {
    case rhi::Format::RGBA8_UNORM:
      return DXGI_FORMAT_R8G8B8A8_UNORM;
    case rhi::Format::RGBA8_SRGB:
      return DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
    case rhi::Format::BGRA8_UNORM:
      return DXGI_FORMAT_B8G8R8A8_UNORM;
    case rhi::Format::RGBA32_FLOAT:
      return DXGI_FORMAT_R32G32B32A32_FLOAT;
    case rhi::Format::RGB32_FLOAT:
      return DXGI_FORMAT_R32G32B32_FLOAT;
    case rhi::Format::RG32_FLOAT:
      return DXGI_FORMAT_R32G32_FLOAT;
    case rhi::Format::R32_UINT:
      return DXGI_FORMAT_R32_UINT;
    case rhi::Format::R16_UINT:
      return DXGI_FORMAT_R16_UINT;
    case rhi::Format::Unknown:
      break;
  }
  throw Error("d3d12: unsupported format");
}

D3D12_RESOURCE_STATES toResourceStates(rhi::ResourceState state) {
  using S = rhi::ResourceState;
  switch (state) {
    case S::Undefined:
      return D3D12_RESOURCE_STATE_COMMON;
    // Both shader-resource states: pixel shaders of graphics pipelines read
    // the same binding sets' resources as every other stage.
    case S::ShaderResource:
      return D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE | D3D12_RESOURCE_STATE_PIXEL_SHADER_RESOURCE;
    case S::UnorderedAccess:
      return D3D12_RESOURCE_STATE_UNORDERED_ACCESS;
    case S::ConstantBuffer:
      return D3D12_RESOURCE_STATE_VERTEX_AND_CONSTANT_BUFFER;
    case S::CopySource:
      return D3D12_RESOURCE_STATE_COPY_SOURCE;
    case S::CopyDest:
      return D3D12_RESOURCE_STATE_COPY_DEST;
    // DXR reads vertex, index, AABB and instance buffers as non-pixel shader resources.
    case S::AccelStructBuildInput:
      return D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE;
    case S::AccelStructWrite:
    case S::AccelStructRead:
      return D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE;
    case S::ShaderTable:
      return D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE;
    case S::HostRead:
      return D3D12_RESOURCE_STATE_COPY_DEST;  // readback heaps only
    case S::RenderTarget:
      return D3D12_RESOURCE_STATE_RENDER_TARGET;
    case S::VertexInput:
      return D3D12_RESOURCE_STATE_VERTEX_AND_CONSTANT_BUFFER | D3D12_RESOURCE_STATE_INDEX_BUFFER;
    case S::Present:
      return D3D12_RESOURCE_STATE_PRESENT;
  }
  return D3D12_RESOURCE_STATE_COMMON;
}

namespace {
D3D12_HEAP_PROPERTIES heapProperties(D3D12_HEAP_TYPE type) {
  D3D12_HEAP_PROPERTIES p{};
  p.Type = type;
  p.CPUPageProperty = D3D12_CPU_PAGE_PROPERTY_UNKNOWN;
  p.MemoryPoolPreference = D3D12_MEMORY_POOL_UNKNOWN;
  p.CreationNodeMask = 1;
  p.VisibleNodeMask = 1;
  return p;
}
}  // namespace

// D3D12: CreateCommittedResource on a DEFAULT, UPLOAD or READBACK heap.
// Device-local buffers allow unordered access (UAVs, clears, AS storage and
// scratch all need it). Upload heaps start, and stay, in GENERIC_READ;
// readback heaps in COPY_DEST; acceleration-structure storage in
// RAYTRACING_ACCELERATION_STRUCTURE - as D3D12 requires of each.
D3D12Buffer::D3D12Buffer(D3D12Device& device, const rhi::BufferDesc& desc) : desc_(desc) {
  resourceBytes_ = desc.byteSize;
  // CBVs cover whole 256-byte units (D3D12_CONSTANT_BUFFER_DATA_PLACEMENT_ALIGNMENT).
  if (hasFlag(desc.usage, rhi::BufferUsage::ConstantBuffer))
    resourceBytes_ = rhi::alignUp(resourceBytes_, D3D12_CONSTANT_BUFFER_DATA_PLACEMENT_ALIGNMENT);

  D3D12_HEAP_TYPE heapType = D3D12_HEAP_TYPE_DEFAULT;
  D3D12_RESOURCE_STATES initial = D3D12_RESOURCE_STATE_COMMON;
  D3D12_RESOURCE_FLAGS flags = D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS;
  switch (desc.memory) {
    case rhi::MemoryLocation::DeviceLocal:
      if (isAccelStructStorage()) initial = D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE;
      break;
    case rhi::MemoryLocation::Upload:
      heapType = D3D12_HEAP_TYPE_UPLOAD;
      initial = D3D12_RESOURCE_STATE_GENERIC_READ;
      flags = D3D12_RESOURCE_FLAG_NONE;
      break;
    case rhi::MemoryLocation::Readback:
      heapType = D3D12_HEAP_TYPE_READBACK;
      initial = D3D12_RESOURCE_STATE_COPY_DEST;
      flags = D3D12_RESOURCE_FLAG_NONE;
      break;
  }
  D3D12_RESOURCE_DESC rd{};
  rd.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
  rd.Width = resourceBytes_;
  rd.Height = 1;
  rd.DepthOrArraySize = 1;
  rd.MipLevels = 1;
  rd.Format = DXGI_FORMAT_UNKNOWN;
  rd.SampleDesc.Count = 1;
  rd.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
  rd.Flags = flags;
  const auto heap = heapProperties(heapType);
  // An armed fault injection (rhi/fault_injection.h) fails as a full device does.
  HRESULT hr = rhi::faults::shouldFail(rhi::faults::Site::Allocation)
                   ? E_OUTOFMEMORY
                   : device.handle()->CreateCommittedResource(&heap, D3D12_HEAP_FLAG_NONE, &rd, initial,
                                                              nullptr, IID_PPV_ARGS(&resource_));
  if (hr == E_OUTOFMEMORY)
    throw Error(fmt::format("d3d12: out of device memory allocating {:.1f} MiB for buffer '{}' on {} "
                            "(E_OUTOFMEMORY): the scene or image is too large for this device",
                            double(resourceBytes_) / (1024.0 * 1024.0), desc.debugName,
                            device.adapter().name));
  if (FAILED(hr))
    throw Error(fmt::format("d3d12: allocating {} bytes for buffer '{}' failed: {}", resourceBytes_,
                            desc.debugName, hresultName(hr)));
  setName(resource_.Get(), desc.debugName);
  if (desc.memory != rhi::MemoryLocation::DeviceLocal) {
    // Readback: the CPU may read everything; upload: it reads nothing.
    D3D12_RANGE readNothing{0, 0};
    check(resource_->Map(0, desc.memory == rhi::MemoryLocation::Upload ? &readNothing : nullptr,
                         &mapped_),
          "ID3D12Resource::Map");
  }
}

void* D3D12Buffer::mappedData() {
  if (!mapped_)
    throw Error(
        fmt::format("d3d12: buffer '{}' is device-local and cannot be mapped", desc_.debugName));
  return mapped_;
}

DXGI_FORMAT D3D12Texture::format() const {
  return toDxgiFormat(desc_.format);
}

// D3D12: CreateCommittedResource (TEXTURE2D, desc.mipLevels) on a DEFAULT heap;
// storage textures allow unordered access, render targets RTVs.
D3D12Texture::D3D12Texture(D3D12Device& device, const rhi::TextureDesc& desc) : desc_(desc) {
  D3D12_RESOURCE_DESC rd{};
  rd.Dimension = D3D12_RESOURCE_DIMENSION_TEXTURE2D;
  rd.Width = desc.width;
  rd.Height = desc.height;
  rd.DepthOrArraySize = 1;
  rd.MipLevels = UINT16(desc.mipLevels);
  rd.Format = toDxgiFormat(desc.format);
  rd.SampleDesc.Count = 1;
  rd.Layout = D3D12_TEXTURE_LAYOUT_UNKNOWN;
  rd.Flags = hasFlag(desc.usage, rhi::TextureUsage::Storage)
                 ? D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS
                 : D3D12_RESOURCE_FLAG_NONE;
  if (hasFlag(desc.usage, rhi::TextureUsage::RenderTarget))
    rd.Flags |= D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET;
  const auto heap = heapProperties(D3D12_HEAP_TYPE_DEFAULT);
  HRESULT hr = rhi::faults::shouldFail(rhi::faults::Site::Allocation)
                   ? E_OUTOFMEMORY
                   : device.handle()->CreateCommittedResource(&heap, D3D12_HEAP_FLAG_NONE, &rd,
                                                              D3D12_RESOURCE_STATE_COMMON, nullptr,
                                                              IID_PPV_ARGS(&resource_));
  if (hr == E_OUTOFMEMORY)
    throw Error(fmt::format("d3d12: out of device memory creating texture '{}' ({}x{}) on {} "
                            "(E_OUTOFMEMORY): the scene or image is too large for this device",
                            desc.debugName, desc.width, desc.height, device.adapter().name));
  if (FAILED(hr))
    throw Error(fmt::format("d3d12: creating texture '{}' ({}x{}) failed: {}", desc.debugName,
                            desc.width, desc.height, hresultName(hr)));
  setName(resource_.Get(), desc.debugName);
}

D3D12Texture::D3D12Texture(const rhi::TextureDesc& desc, ComPtr<ID3D12Resource> resource)
    : desc_(desc), resource_(std::move(resource)) {
  setName(resource_.Get(), desc.debugName);
}

namespace {
D3D12_TEXTURE_ADDRESS_MODE toAddressMode(rhi::AddressMode mode) {
  switch (mode) {
    case rhi::AddressMode::Repeat:
      return D3D12_TEXTURE_ADDRESS_MODE_WRAP;
    case rhi::AddressMode::MirroredRepeat:
      return D3D12_TEXTURE_ADDRESS_MODE_MIRROR;
    case rhi::AddressMode::ClampToEdge:
      return D3D12_TEXTURE_ADDRESS_MODE_CLAMP;
  }
  return D3D12_TEXTURE_ADDRESS_MODE_WRAP;
}

// MipFilter::None filters between levels by point; MaxLOD 0 keeps level 0.
D3D12_FILTER toFilter(rhi::Filter minFilter, rhi::Filter magFilter, rhi::MipFilter mipFilter) {
  auto type = [](bool linear) {
    return linear ? D3D12_FILTER_TYPE_LINEAR : D3D12_FILTER_TYPE_POINT;
  };
  return D3D12_ENCODE_BASIC_FILTER(
      type(minFilter == rhi::Filter::Linear), type(magFilter == rhi::Filter::Linear),
      type(mipFilter == rhi::MipFilter::Linear), D3D12_FILTER_REDUCTION_TYPE_STANDARD);
}
}  // namespace

// D3D12: the D3D12_SAMPLER_DESC binding sets write with CreateSampler; LOD
// range [0, 0] for MipFilter::None and no anisotropy, as on Vulkan.
D3D12Sampler::D3D12Sampler(const rhi::SamplerDesc& desc) : desc_(desc) {
  samplerDesc_.Filter = toFilter(desc.minFilter, desc.magFilter, desc.mipFilter);
  samplerDesc_.AddressU = toAddressMode(desc.addressU);
  samplerDesc_.AddressV = toAddressMode(desc.addressV);
  samplerDesc_.AddressW = D3D12_TEXTURE_ADDRESS_MODE_CLAMP;
  samplerDesc_.MipLODBias = 0.0f;
  samplerDesc_.MaxAnisotropy = 1;
  samplerDesc_.ComparisonFunc = D3D12_COMPARISON_FUNC_NEVER;
  samplerDesc_.MinLOD = 0.0f;
  samplerDesc_.MaxLOD = desc.mipFilter == rhi::MipFilter::None ? 0.0f : D3D12_FLOAT32_MAX;
}

// D3D12: GetRaytracingAccelerationStructurePrebuildInfo sizes the result
// and scratch; the result lives in a buffer that stays in
// RAYTRACING_ACCELERATION_STRUCTURE state. Scratch is allocated per build by
// the command list.
D3D12AccelStruct::D3D12AccelStruct(D3D12Device& device, const rhi::rt::AccelStructDesc& desc)
    : desc_(desc) {
  AccelStructBuildInputs inputs = buildInputs(0, desc.topLevelMaxInstances);
  D3D12_RAYTRACING_ACCELERATION_STRUCTURE_PREBUILD_INFO info{};
  device.handle()->GetRaytracingAccelerationStructurePrebuildInfo(&inputs.inputs, &info);
  if (info.ResultDataMaxSizeInBytes == 0)
    throw Error(fmt::format("d3d12: the driver reports no size for acceleration structure '{}'",
                            desc.debugName));
  scratchBytes_ = rhi::alignUp(info.ScratchDataSizeInBytes,
                               D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BYTE_ALIGNMENT);

  rhi::BufferDesc storage;
  storage.byteSize = rhi::alignUp(info.ResultDataMaxSizeInBytes,
                                  D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BYTE_ALIGNMENT);
  storage.usage = rhi::BufferUsage::AccelStructStorage;
  storage.debugName = desc.debugName;
  storage_ = std::make_unique<D3D12Buffer>(device, storage);
}

AccelStructBuildInputs D3D12AccelStruct::buildInputs(uint64_t instanceAddress,
                                                     uint32_t instanceCount) const {
  AccelStructBuildInputs in;
  auto& inputs = in.inputs;
  inputs.Flags = desc_.buildFlags == rhi::rt::BuildFlags::PreferFastBuild
                     ? D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_BUILD
                     : D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_TRACE;
  inputs.DescsLayout = D3D12_ELEMENTS_LAYOUT_ARRAY;
  if (desc_.isTopLevel) {
    inputs.Type = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL;
    inputs.NumDescs = instanceCount;
    inputs.InstanceDescs =
        instanceAddress;  // rhi::rt::InstanceDesc == D3D12_RAYTRACING_INSTANCE_DESC
    return in;
  }
  inputs.Type = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL;
  for (const auto& geometry : desc_.bottomLevelGeometries) {
    const rhi::rt::GeometryInput input = rhi::rt::geometryInput(geometry);
    D3D12_RAYTRACING_GEOMETRY_DESC g{};
    g.Flags = D3D12_RAYTRACING_GEOMETRY_FLAG_NONE;
    if (input.opaque) g.Flags |= D3D12_RAYTRACING_GEOMETRY_FLAG_OPAQUE;
    if (input.noDuplicateAnyHitInvocation)
      g.Flags |= D3D12_RAYTRACING_GEOMETRY_FLAG_NO_DUPLICATE_ANYHIT_INVOCATION;
    if (input.triangles) {
      g.Type = D3D12_RAYTRACING_GEOMETRY_TYPE_TRIANGLES;
      auto& tri = g.Triangles;
      tri.Transform3x4 = input.transformAddress;
      tri.VertexFormat = toDxgiFormat(input.vertexFormat);
      tri.VertexCount = input.vertexCount;
      tri.VertexBuffer = {input.vertexAddress, input.vertexStride};
      tri.IndexFormat = input.indexed ? toDxgiFormat(input.indexFormat) : DXGI_FORMAT_UNKNOWN;
      tri.IndexCount = input.indexCount;
      tri.IndexBuffer = input.indexAddress;
    } else {
      g.Type = D3D12_RAYTRACING_GEOMETRY_TYPE_PROCEDURAL_PRIMITIVE_AABBS;
      g.AABBs.AABBCount = input.primitiveCount;
      g.AABBs.AABBs = {input.aabbAddress, input.aabbStride};
    }
    in.geometries.push_back(g);
  }
  inputs.NumDescs = UINT(in.geometries.size());
  inputs.pGeometryDescs = in.geometries.data();
  return in;
}

}  // namespace penumbra::d3d12
