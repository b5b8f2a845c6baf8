// Root signatures (from the reflected layout), compute and graphics
// pipelines, ray-tracing state objects and binding sets.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <list>

#include "d3d12_backend.h"
#include "penumbra/rhi/binding_layout.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {
namespace {

D3D12_DESCRIPTOR_RANGE_TYPE toRangeType(rhi::DescriptorRangeType type) {
  switch (type) {
    case rhi::DescriptorRangeType::SRV: return D3D12_DESCRIPTOR_RANGE_TYPE_SRV;
    case rhi::DescriptorRangeType::UAV: return D3D12_DESCRIPTOR_RANGE_TYPE_UAV;
    case rhi::DescriptorRangeType::CBV: return D3D12_DESCRIPTOR_RANGE_TYPE_CBV;
    case rhi::DescriptorRangeType::Sampler: return D3D12_DESCRIPTOR_RANGE_TYPE_SAMPLER;
  }
  return D3D12_DESCRIPTOR_RANGE_TYPE_SRV;
}

D3D12_SHADER_BYTECODE dxilOf(const rhi::ShaderDesc& shader) {
  if (shader.dxil.empty())
    throw Error(fmt::format("d3d12: this build has no DXIL for shader '{}': configure with DXC (Windows SDK, "
                            "Vulkan SDK, or -DDXC_EXECUTABLE=path/to/dxc) to use the D3D12 backend",
                            shader.exportName));
  return {shader.dxil.data(), shader.dxil.size()};
}

// DXR export names are identifiers; RHI names such as "path_trace.rgen" are
// file names. Map every character outside [A-Za-z0-9_] to '_'.
std::wstring exportIdentifier(const std::string& name) {
  std::string id = name;
  for (char& c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "_" + id;
  return toWide(id);
}

}  // namespace

ComPtr<ID3D12RootSignature> createRootSignature(D3D12Device& device, const D3D12_VERSIONED_ROOT_SIGNATURE_DESC& desc,
                                                const std::string& name) {
  ComPtr<ID3DBlob> blob, errors;
  HRESULT hr = library().serializeVersionedRootSignature(&desc, &blob, &errors);
  if (FAILED(hr)) {
    std::string message = errors ? std::string(static_cast<const char*>(errors->GetBufferPointer()),
                                               errors->GetBufferSize())
                                 : hresultName(hr);
    while (!message.empty() && (message.back() == '\n' || message.back() == '\0')) message.pop_back();
    throw Error(fmt::format("d3d12: root signature of '{}': {}", name, message));
  }
  ComPtr<ID3D12RootSignature> rootSignature;
  check(device.handle()->CreateRootSignature(0, blob->GetBufferPointer(), blob->GetBufferSize(),
                                             IID_PPV_ARGS(&rootSignature)),
        "CreateRootSignature");
  setName(rootSignature.Get(), name);
  return rootSignature;
}

// D3D12: one global root signature (version 1.1) translated from
// rhi::computeRootSignatureLayout: root constants for the push constants,
// per space a CBV/SRV/UAV table, a sampler table and one table per unbounded
// array (root_signature_layout.h).
D3D12RootSignature::D3D12RootSignature(D3D12Device& device, rhi::PipelineBindingLayout layout,
                                       const std::string& name, D3D12_ROOT_SIGNATURE_FLAGS flags)
    : layout_(std::move(layout)),
      rootLayout_(rhi::computeRootSignatureLayout(layout_, device.bindingOffsets())) {
  std::vector<D3D12_ROOT_PARAMETER1> parameters(rootLayout_.parameterCount());
  std::vector<std::vector<D3D12_DESCRIPTOR_RANGE1>> ranges;
  if (rootLayout_.pushConstants) {
    auto& p = parameters[rootLayout_.pushConstants->rootParameterIndex];
    p.ParameterType = D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS;
    p.Constants.ShaderRegister = rootLayout_.pushConstants->shaderRegister;
    p.Constants.RegisterSpace = rootLayout_.pushConstants->registerSpace;
    p.Constants.Num32BitValues = rootLayout_.pushConstants->num32BitValues;
    p.ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
  }
  for (const auto& table : rootLayout_.tables) {
    auto& r = ranges.emplace_back();
    for (const auto& range : table.ranges) {
      D3D12_DESCRIPTOR_RANGE1 d{};
      d.RangeType = toRangeType(range.type);
      d.NumDescriptors = range.count;  // rhi::kUnboundedDescriptors == UINT_MAX: unbounded
      d.BaseShaderRegister = range.baseRegister;
      d.RegisterSpace = table.space;
      // Volatile descriptors: array entries a binding set leaves unwritten
      // are legal as long as the shaders do not read them. SRV/CBV data does
      // not change during a dispatch; UAV data does. Sampler ranges take no
      // DATA_* flags (samplers have no data).
      d.Flags = D3D12_DESCRIPTOR_RANGE_FLAG_DESCRIPTORS_VOLATILE;
      if (range.type == rhi::DescriptorRangeType::UAV)
        d.Flags |= D3D12_DESCRIPTOR_RANGE_FLAG_DATA_VOLATILE;
      else if (range.type != rhi::DescriptorRangeType::Sampler)
        d.Flags |= D3D12_DESCRIPTOR_RANGE_FLAG_DATA_STATIC_WHILE_SET_AT_EXECUTE;
      d.OffsetInDescriptorsFromTableStart = range.offsetInTable;
      r.push_back(d);
    }
    auto& p = parameters[table.rootParameterIndex];
    p.ParameterType = D3D12_ROOT_PARAMETER_TYPE_DESCRIPTOR_TABLE;
    p.DescriptorTable.NumDescriptorRanges = UINT(r.size());
    p.DescriptorTable.pDescriptorRanges = r.data();
    p.ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
  }
  D3D12_VERSIONED_ROOT_SIGNATURE_DESC desc{};
  desc.Version = D3D_ROOT_SIGNATURE_VERSION_1_1;
  desc.Desc_1_1.NumParameters = UINT(parameters.size());
  desc.Desc_1_1.pParameters = parameters.data();
  desc.Desc_1_1.Flags = flags;
  rootSignature_ = createRootSignature(device, desc, name + " root signature");
}

// D3D12: CreateComputePipelineState with the global root signature.
D3D12ComputePipeline::D3D12ComputePipeline(D3D12Device& device, const rhi::ComputePipelineDesc& desc) {
  const D3D12_SHADER_BYTECODE bytecode = dxilOf(desc.shader);
  rhi::PipelineBindingLayout layout;
  rhi::mergeBindingLayout(layout, desc.shader.bindingLayout, desc.shader.exportName);
  rootSignature_ = std::make_unique<D3D12RootSignature>(device, std::move(layout), desc.debugName);
  D3D12_COMPUTE_PIPELINE_STATE_DESC pso{};
  pso.pRootSignature = rootSignature_->handle();
  pso.CS = bytecode;
  check(device.handle()->CreateComputePipelineState(&pso, IID_PPV_ARGS(&pipeline_)),
        "CreateComputePipelineState");
  setName(pipeline_.Get(), desc.debugName);
}

// D3D12: CreateGraphicsPipelineState with a root signature from the vertex
// and pixel shaders' merged layouts (ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT), one
// TEXCOORD<location> input element per vertex attribute from slot 0,
// triangles, no culling, no depth or stencil, one render target.
D3D12GraphicsPipeline::D3D12GraphicsPipeline(D3D12Device& device, const rhi::GraphicsPipelineDesc& desc)
    : desc_(desc) {
  const D3D12_SHADER_BYTECODE vs = dxilOf(desc.vertexShader), ps = dxilOf(desc.pixelShader);
  rhi::PipelineBindingLayout layout;
  rhi::mergeBindingLayout(layout, desc.vertexShader.bindingLayout, desc.vertexShader.exportName);
  rhi::mergeBindingLayout(layout, desc.pixelShader.bindingLayout, desc.pixelShader.exportName);
  rootSignature_ = std::make_unique<D3D12RootSignature>(device, std::move(layout), desc.debugName,
                                                        D3D12_ROOT_SIGNATURE_FLAG_ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT);

  std::vector<D3D12_INPUT_ELEMENT_DESC> elements;
  for (const auto& attribute : desc.vertexLayout.attributes) {
    D3D12_INPUT_ELEMENT_DESC e{};
    e.SemanticName = "TEXCOORD";
    e.SemanticIndex = attribute.location;
    e.Format = toDxgiFormat(attribute.format);
    e.InputSlot = 0;
    e.AlignedByteOffset = attribute.offset;
    e.InputSlotClass = D3D12_INPUT_CLASSIFICATION_PER_VERTEX_DATA;
    e.InstanceDataStepRate = 0;
    elements.push_back(e);
  }

  D3D12_GRAPHICS_PIPELINE_STATE_DESC pso{};
  pso.pRootSignature = rootSignature_->handle();
  pso.VS = vs;
  pso.PS = ps;
  // Disabled blending still wants valid factors: the pass-through ONE/ZERO/ADD.
  D3D12_RENDER_TARGET_BLEND_DESC& blend = pso.BlendState.RenderTarget[0];
  blend.BlendEnable = FALSE;
  blend.LogicOpEnable = FALSE;
  blend.SrcBlend = D3D12_BLEND_ONE;
  blend.DestBlend = D3D12_BLEND_ZERO;
  blend.BlendOp = D3D12_BLEND_OP_ADD;
  blend.SrcBlendAlpha = D3D12_BLEND_ONE;
  blend.DestBlendAlpha = D3D12_BLEND_ZERO;
  blend.BlendOpAlpha = D3D12_BLEND_OP_ADD;
  blend.LogicOp = D3D12_LOGIC_OP_NOOP;
  blend.RenderTargetWriteMask = D3D12_COLOR_WRITE_ENABLE_ALL;
  if (desc.blend == rhi::BlendMode::AlphaBlend) {
    blend.BlendEnable = TRUE;
    blend.SrcBlend = D3D12_BLEND_SRC_ALPHA;
    blend.DestBlend = D3D12_BLEND_INV_SRC_ALPHA;
    blend.DestBlendAlpha = D3D12_BLEND_INV_SRC_ALPHA;
  }
  pso.SampleMask = UINT_MAX;
  pso.RasterizerState.FillMode = D3D12_FILL_MODE_SOLID;
  pso.RasterizerState.CullMode = D3D12_CULL_MODE_NONE;
  pso.RasterizerState.FrontCounterClockwise = FALSE;
  pso.RasterizerState.DepthClipEnable = TRUE;
  pso.RasterizerState.ConservativeRaster = D3D12_CONSERVATIVE_RASTERIZATION_MODE_OFF;
  // Depth and stencil off; the functions and ops are the defaults nonetheless.
  const D3D12_DEPTH_STENCILOP_DESC keep{D3D12_STENCIL_OP_KEEP, D3D12_STENCIL_OP_KEEP, D3D12_STENCIL_OP_KEEP,
                                        D3D12_COMPARISON_FUNC_ALWAYS};
  pso.DepthStencilState.DepthEnable = FALSE;
  pso.DepthStencilState.DepthWriteMask = D3D12_DEPTH_WRITE_MASK_ZERO;
  pso.DepthStencilState.DepthFunc = D3D12_COMPARISON_FUNC_ALWAYS;
  pso.DepthStencilState.StencilEnable = FALSE;
  pso.DepthStencilState.FrontFace = keep;
  pso.DepthStencilState.BackFace = keep;
  pso.InputLayout.pInputElementDescs = elements.data();
  pso.InputLayout.NumElements = UINT(elements.size());
  pso.IBStripCutValue = D3D12_INDEX_BUFFER_STRIP_CUT_VALUE_DISABLED;
  pso.PrimitiveTopologyType = D3D12_PRIMITIVE_TOPOLOGY_TYPE_TRIANGLE;
  pso.NumRenderTargets = 1;
  pso.RTVFormats[0] = toDxgiFormat(desc.renderTargetFormat);
  pso.DSVFormat = DXGI_FORMAT_UNKNOWN;
  pso.SampleDesc.Count = 1;
  pso.SampleDesc.Quality = 0;
  device.checkDevice(device.handle()->CreateGraphicsPipelineState(&pso, IID_PPV_ARGS(&pipeline_)),
                     "CreateGraphicsPipelineState (run with --validation for the reason)");
  setName(pipeline_.Get(), desc.debugName);
}

namespace {

// The subobjects of a ray-tracing state object and everything they point
// at: every pointer in a subobject must stay valid until CreateStateObject,
// so each piece lives in a std::list (stable element addresses) and the
// subobject array is reserved up front (associations point into it).
class StateObjectParts {
 public:
  explicit StateObjectParts(size_t maxSubobjects) { subobjects_.reserve(maxSubobjects); }

  // A DXIL library with one entry point, exported as `name`.
  void addLibrary(const D3D12_SHADER_BYTECODE& bytecode, const std::wstring& name,
                  const std::wstring& entryPoint) {
    auto& e = exports_.emplace_back();
    e.Name = wide(name);
    e.ExportToRename = wide(entryPoint);
    e.Flags = D3D12_EXPORT_FLAG_NONE;
    auto& lib = libraries_.emplace_back();
    lib.DXILLibrary = bytecode;
    lib.NumExports = 1;
    lib.pExports = &e;
    add(D3D12_STATE_SUBOBJECT_TYPE_DXIL_LIBRARY, &lib);
  }
  void addHitGroup(const std::wstring& name, D3D12_HIT_GROUP_TYPE type, LPCWSTR closestHit,
                   LPCWSTR anyHit, LPCWSTR intersection) {
    auto& hg = hitGroups_.emplace_back();
    hg.HitGroupExport = wide(name);
    hg.Type = type;
    hg.ClosestHitShaderImport = closestHit;
    hg.AnyHitShaderImport = anyHit;
    hg.IntersectionShaderImport = intersection;
    add(D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP, &hg);
  }
  // A local root signature and its association with the exports it serves.
  void addLocalRootSignature(ID3D12RootSignature* signature, const std::vector<LPCWSTR>& names) {
    auto& local = locals_.emplace_back();
    local.pLocalRootSignature = signature;
    add(D3D12_STATE_SUBOBJECT_TYPE_LOCAL_ROOT_SIGNATURE, &local);
    auto& list = exportLists_.emplace_back(names);
    auto& association = associations_.emplace_back();
    association.pSubobjectToAssociate = &subobjects_.back();
    association.NumExports = UINT(list.size());
    association.pExports = list.data();
    add(D3D12_STATE_SUBOBJECT_TYPE_SUBOBJECT_TO_EXPORTS_ASSOCIATION, &association);
  }
  void add(D3D12_STATE_SUBOBJECT_TYPE type, const void* desc) {
    if (subobjects_.size() == subobjects_.capacity())
      throw Error("d3d12: internal error: state subobjects outgrew their reservation");
    subobjects_.push_back({type, desc});
  }
  D3D12_STATE_OBJECT_DESC desc() const {
    D3D12_STATE_OBJECT_DESC stateObject{};
    stateObject.Type = D3D12_STATE_OBJECT_TYPE_RAYTRACING_PIPELINE;
    stateObject.NumSubobjects = UINT(subobjects_.size());
    stateObject.pSubobjects = subobjects_.data();
    return stateObject;
  }

 private:
  LPCWSTR wide(const std::wstring& s) { return strings_.emplace_back(s).c_str(); }

  std::list<D3D12_EXPORT_DESC> exports_;
  std::list<D3D12_DXIL_LIBRARY_DESC> libraries_;
  std::list<D3D12_HIT_GROUP_DESC> hitGroups_;
  std::list<std::wstring> strings_;
  std::list<std::vector<LPCWSTR>> exportLists_;
  std::list<D3D12_SUBOBJECT_TO_EXPORTS_ASSOCIATION> associations_;
  std::list<D3D12_LOCAL_ROOT_SIGNATURE> locals_;
  std::vector<D3D12_STATE_SUBOBJECT> subobjects_;
};

// A local root signature of `bytes` of shader-record constants.
ComPtr<ID3D12RootSignature> localRootSignature(D3D12Device& device, uint32_t bytes,
                                               const std::string& pipelineName) {
  const rhi::RootConstantsLayout constants =
      rhi::computeShaderRecordConstants(bytes, device.bindingOffsets());
  D3D12_ROOT_PARAMETER1 parameter{};
  parameter.ParameterType = D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS;
  parameter.Constants.ShaderRegister = constants.shaderRegister;
  parameter.Constants.RegisterSpace = constants.registerSpace;
  parameter.Constants.Num32BitValues = constants.num32BitValues;
  parameter.ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
  D3D12_VERSIONED_ROOT_SIGNATURE_DESC rs{};
  rs.Version = D3D_ROOT_SIGNATURE_VERSION_1_1;
  rs.Desc_1_1.NumParameters = 1;
  rs.Desc_1_1.pParameters = &parameter;
  rs.Desc_1_1.Flags = D3D12_ROOT_SIGNATURE_FLAG_LOCAL_ROOT_SIGNATURE;
  return createRootSignature(
      device, rs, fmt::format("{} local root signature ({} bytes)", pipelineName, bytes));
}

}  // namespace

// D3D12: CreateStateObject(RAYTRACING_PIPELINE) with one DXIL library per
// shader (its entry point exported under the RHI export name), hit groups,
// the shader config (payload/attribute sizes), the pipeline config (max
// recursion), the global root signature, and local root signatures with
// their export associations for shaders that read shader-record data.
D3D12RayTracingPipeline::D3D12RayTracingPipeline(D3D12Device& device, const rhi::RayTracingPipelineDesc& desc)
    : device_(device), desc_(desc) {
  // A library per shader, a subobject per hit group, three configurations, and
  // at most a local root signature and its association per export.
  const size_t exportCount = desc.shaders.size() + desc.hitGroups.size();
  StateObjectParts parts(exportCount + 3 + 2 * exportCount);
  // Each export's D3D12 name; two RHI names must not map to one.
  auto claim = [&](const std::string& exportName) {
    const std::wstring name = exportIdentifier(exportName);
    for (const auto& [other, otherName] : d3dNames_)
      if (otherName == name)
        throw Error(fmt::format("d3d12: pipeline '{}': export names '{}' and '{}' collide",
                                desc.debugName, other, exportName));
    d3dNames_[exportName] = name;
    return name;
  };

  rhi::PipelineBindingLayout layout;
  std::map<std::string, uint32_t> shaderRecordBytes;
  for (const auto& shader : desc.shaders) {
    const D3D12_SHADER_BYTECODE bytecode = dxilOf(shader);
    const std::wstring name = claim(shader.exportName);
    shaderRecordBytes[shader.exportName] = shader.shaderRecordBytes;
    rhi::mergeBindingLayout(layout, shader.bindingLayout, shader.exportName);
    parts.addLibrary(bytecode, name, toWide(shader.entryPoint));
    if (shader.stage == rhi::ShaderStage::RayGeneration || shader.stage == rhi::ShaderStage::Miss)
      localRootBytes_[shader.exportName] = shader.shaderRecordBytes;
  }

  // The validation layer checked that every name is a shader of the right stage.
  auto import = [&](const std::string& shader) -> LPCWSTR {
    return shader.empty() ? nullptr : d3dNames_.at(shader).c_str();
  };
  for (const auto& group : desc.hitGroups) {
    const std::wstring name = claim(group.exportName);
    parts.addHitGroup(name,
                      group.isProcedural ? D3D12_HIT_GROUP_TYPE_PROCEDURAL_PRIMITIVE
                                         : D3D12_HIT_GROUP_TYPE_TRIANGLES,
                      import(group.closestHit), import(group.anyHit), import(group.intersection));
    // A hit group's record serves all its shaders: the largest of theirs.
    uint32_t bytes = 0;
    for (const auto* s : {&group.closestHit, &group.anyHit, &group.intersection})
      if (!s->empty()) bytes = std::max(bytes, shaderRecordBytes[*s]);
    localRootBytes_[group.exportName] = bytes;
  }

  D3D12_RAYTRACING_SHADER_CONFIG shaderConfig{desc.maxPayloadBytes, desc.maxAttributeBytes};
  parts.add(D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_SHADER_CONFIG, &shaderConfig);
  D3D12_RAYTRACING_PIPELINE_CONFIG pipelineConfig{desc.maxRecursionDepth};
  parts.add(D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_PIPELINE_CONFIG, &pipelineConfig);

  rootSignature_ = std::make_unique<D3D12RootSignature>(device_, std::move(layout), desc.debugName);
  D3D12_GLOBAL_ROOT_SIGNATURE global{rootSignature_->handle()};
  parts.add(D3D12_STATE_SUBOBJECT_TYPE_GLOBAL_ROOT_SIGNATURE, &global);

  // Local root signatures: one per distinct record size, associated with the
  // raygen/miss shaders and hit groups whose records carry that much data.
  std::map<uint32_t, std::vector<LPCWSTR>> exportsBySize;
  for (const auto& [exportName, bytes] : localRootBytes_)
    if (bytes > 0) exportsBySize[bytes].push_back(d3dNames_.at(exportName).c_str());
  for (auto& [bytes, names] : exportsBySize) {
    localRootSignatures_.push_back(localRootSignature(device_, bytes, desc.debugName));
    parts.addLocalRootSignature(localRootSignatures_.back().Get(), names);
  }

  const D3D12_STATE_OBJECT_DESC stateObject = parts.desc();
  device_.checkDevice(device_.handle()->CreateStateObject(&stateObject, IID_PPV_ARGS(&stateObject_)),
                      "CreateStateObject (ray-tracing pipeline; run with --validation for the reason)");
  setName(stateObject_.Get(), desc.debugName);
  check(stateObject_.As(&properties_), "QueryInterface(ID3D12StateObjectProperties)");
}

const void* D3D12RayTracingPipeline::shaderIdentifier(const std::string& exportName) const {
  auto it = d3dNames_.find(exportName);
  const void* id = it == d3dNames_.end() ? nullptr : properties_->GetShaderIdentifier(it->second.c_str());
  if (!id || !localRootBytes_.count(exportName))
    throw Error(fmt::format("d3d12: pipeline '{}' has no raygen/miss shader or hit group '{}'", desc_.debugName,
                            exportName));
  return id;
}

uint32_t D3D12RayTracingPipeline::localRootBytes(const std::string& exportName) const {
  auto it = localRootBytes_.find(exportName);
  return it == localRootBytes_.end() ? 0 : it->second;
}

rhi::ShaderTableHandle D3D12RayTracingPipeline::createShaderTable(const std::string& debugName) {
  return std::make_shared<D3D12ShaderTable>(device_, shared_from_this(), debugName);
}

// D3D12: per descriptor table of the space, a range of the shader-visible
// CBV/SRV/UAV or sampler heap; one descriptor per layout item (per element
// for texture and sampler arrays) at the offset the root signature's table
// gives it (CreateShaderResourceView / CreateUnorderedAccessView /
// CreateConstantBufferView / CreateSampler). An unbounded array's table gets
// exactly as many descriptors as the set binds there.
D3D12BindingSet::D3D12BindingSet(D3D12Device& device, const rhi::BindingSetDesc& desc,
                                 const D3D12RootSignature& rootSignature)
    : desc_(desc) {
  const auto& root = rootSignature.rootLayout();
  for (const auto& table : root.tables) {
    if (table.space != desc.space) continue;
    uint32_t count = table.descriptorCount;
    if (table.unbounded)
      for (const auto& item : desc.items)
        if (item.slot == table.ranges[0].slot) count = uint32_t(item.elementCount());
    auto& heap = table.heap == rhi::DescriptorHeapKind::Sampler ? device.samplerHeap() : device.shaderVisibleHeap();
    tables_[table.rootParameterIndex] = heap.allocate(count);
  }
  if (tables_.empty()) return;
  const auto& items = rootSignature.bindingLayout().spaces[desc.space].items;
  ID3D12Device5* d = device.handle();
  for (const auto& item : desc.items) {
    const rhi::DescriptorTableLayout* table = root.tableForSlot(desc.space, item.slot);
    const rhi::DescriptorRangeLayout* range = table->rangeForSlot(item.slot);
    const auto layoutItem = std::find_if(items.begin(), items.end(),
                                         [&](const rhi::BindingLayoutItem& i) { return i.slot == item.slot; });
    rangeTypes_[item.slot] = range->type;
    const DescriptorAllocation& descriptors = *tables_.at(table->rootParameterIndex);
    const D3D12_CPU_DESCRIPTOR_HANDLE handle = descriptors.cpu(range->offsetInTable);
    switch (item.type) {
      case rhi::ResourceType::AccelStruct: {
        D3D12_SHADER_RESOURCE_VIEW_DESC srv{};
        srv.ViewDimension = D3D12_SRV_DIMENSION_RAYTRACING_ACCELERATION_STRUCTURE;
        srv.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
        srv.RaytracingAccelerationStructure.Location = item.accelStruct->deviceAddress();
        d->CreateShaderResourceView(nullptr, &srv, handle);
        break;
      }
      case rhi::ResourceType::StorageBuffer: {
        auto* buffer = static_cast<D3D12Buffer*>(item.buffer.get());
        const uint32_t stride = layoutItem->structureStride;  // > 0: checked by the validation layer
        const UINT elements = UINT(buffer->desc().byteSize / stride);
        if (range->type == rhi::DescriptorRangeType::UAV) {
          D3D12_UNORDERED_ACCESS_VIEW_DESC uav{};
          uav.ViewDimension = D3D12_UAV_DIMENSION_BUFFER;
          uav.Buffer.NumElements = elements;
          uav.Buffer.StructureByteStride = stride;
          d->CreateUnorderedAccessView(buffer->resource(), nullptr, &uav, handle);
        } else {
          D3D12_SHADER_RESOURCE_VIEW_DESC srv{};
          srv.ViewDimension = D3D12_SRV_DIMENSION_BUFFER;
          srv.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
          srv.Buffer.NumElements = elements;
          srv.Buffer.StructureByteStride = stride;
          d->CreateShaderResourceView(buffer->resource(), &srv, handle);
        }
        break;
      }
      case rhi::ResourceType::ConstantBuffer: {
        auto* buffer = static_cast<D3D12Buffer*>(item.buffer.get());
        D3D12_CONSTANT_BUFFER_VIEW_DESC cbv{};
        cbv.BufferLocation = buffer->deviceAddress();
        cbv.SizeInBytes = UINT(buffer->resourceBytes());
        d->CreateConstantBufferView(&cbv, handle);
        break;
      }
      case rhi::ResourceType::StorageTexture: {
        auto* texture = static_cast<D3D12Texture*>(item.texture.get());
        if (range->type == rhi::DescriptorRangeType::UAV) {
          D3D12_UNORDERED_ACCESS_VIEW_DESC uav{};
          uav.Format = texture->format();
          uav.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2D;
          d->CreateUnorderedAccessView(texture->resource(), nullptr, &uav, handle);
        } else {
          D3D12_SHADER_RESOURCE_VIEW_DESC srv{};
          srv.Format = texture->format();
          srv.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2D;
          srv.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
          srv.Texture2D.MipLevels = texture->desc().mipLevels;
          d->CreateShaderResourceView(texture->resource(), &srv, handle);
        }
        break;
      }
      // Texture2D SRVs in the texture's own format, so sRGB textures decode
      // on reads; one per array element, back to back.
      case rhi::ResourceType::SampledTexture:
        for (uint32_t i = 0; i < item.textures.size(); ++i) {
          auto* texture = static_cast<D3D12Texture*>(item.textures[i].get());
          D3D12_SHADER_RESOURCE_VIEW_DESC srv{};
          srv.Format = texture->format();
          srv.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2D;
          srv.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
          srv.Texture2D.MipLevels = texture->desc().mipLevels;
          d->CreateShaderResourceView(texture->resource(), &srv, descriptors.cpu(range->offsetInTable + i));
        }
        break;
      case rhi::ResourceType::Sampler:
        for (uint32_t i = 0; i < item.samplerHandles.size(); ++i) {
          auto* sampler = static_cast<D3D12Sampler*>(item.samplerHandles[i].get());
          d->CreateSampler(&sampler->samplerDesc(), descriptors.cpu(range->offsetInTable + i));
        }
        break;
    }
  }
}

D3D12_GPU_DESCRIPTOR_HANDLE D3D12BindingSet::tableStart(uint32_t rootParameterIndex) const {
  auto it = tables_.find(rootParameterIndex);
  if (it == tables_.end())
    throw Error(fmt::format("d3d12: binding set '{}' has no descriptor table for root parameter {}",
                            desc_.debugName, rootParameterIndex));
  return it->second->gpu(0);
}


rhi::ResourceState D3D12BindingSet::requiredState(const rhi::BindingSetItem& item) const {
  if (item.type == rhi::ResourceType::AccelStruct) return rhi::ResourceState::AccelStructRead;
  switch (rangeTypes_.at(item.slot)) {
    case rhi::DescriptorRangeType::UAV: return rhi::ResourceState::UnorderedAccess;
    case rhi::DescriptorRangeType::CBV: return rhi::ResourceState::ConstantBuffer;
    case rhi::DescriptorRangeType::SRV:
    case rhi::DescriptorRangeType::Sampler: break;  // samplers need no state; the caller skips them
  }
  return rhi::ResourceState::ShaderResource;
}

}  // namespace penumbra::d3d12
