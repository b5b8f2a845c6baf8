#pragma once
// Shaders, binding layouts, binding sets, pipelines and shader tables.
#include <cstddef>
#include <span>
#include <vector>

#include "penumbra/rhi/resources.h"

namespace penumbra::rhi {

// ---- Binding model -------------------------------------------------------
// A pipeline's binding layout is derived from its shaders' SPIR-V by
// reflection, never written by hand: at build time, tools/shader_layout
// reflects every compiled shader (engine/penumbra/rhi/shader_reflection.h) and the
// generated shader table hands the result to ShaderDesc::bindingLayout, so
// neither backend needs SPIR-V tooling at run time.
// space N = Vulkan descriptor set N = D3D12 register space N; the slot is the
// Vulkan binding number, which encodes the D3D12 register through the shift
// offsets the device was created with (binding_offsets.h).

enum class ResourceType : uint8_t {
  AccelStruct,  // D3D12: SRV (RaytracingAccelerationStructure). Vulkan: ACCELERATION_STRUCTURE_KHR
  StorageBuffer,   // D3D12: (RW)StructuredBuffer SRV/UAV. Vulkan: STORAGE_BUFFER
  ConstantBuffer,  // D3D12: CBV. Vulkan: UNIFORM_BUFFER
  StorageTexture,  // D3D12: RWTexture2D UAV. Vulkan: STORAGE_IMAGE
  SampledTexture,  // D3D12: Texture2D SRV. Vulkan: SAMPLED_IMAGE (GLSL texture2D)
  Sampler,         // D3D12: SamplerState (sampler heap). Vulkan: SAMPLER (GLSL sampler)
};
const char* resourceTypeName(ResourceType type);

// The most elements a binding set may put in an unbounded ("bindless") array.
// Vulkan has no unbounded descriptor-set-layout bindings: such a binding gets
// min(kMaxBindlessDescriptors, the device's per-stage limit) descriptors,
// partially bound, so this bounds the layout's size and the descriptor pool.
// D3D12's shader-visible sampler heap holds 2048 samplers in all, so sampler
// arrays should stay well below this.
constexpr uint32_t kMaxBindlessDescriptors = 4096;

struct BindingLayoutItem {
  uint32_t slot = 0;
  ResourceType type = ResourceType::StorageBuffer;
  // Elements of the array; 0 = an unbounded (runtime-sized, "bindless") array,
  // `Texture2D t[]` / `uniform texture2D t[]`: a binding set fills 1 ..
  // kMaxBindlessDescriptors of them. D3D12: a range of NumDescriptors = UINT_MAX
  // in a descriptor table of its own. Vulkan: a PARTIALLY_BOUND binding.
  uint32_t arraySize = 1;
  bool writable = false;  // UAV rather than SRV on D3D12
  // Storage buffers: bytes per element of the (RW)StructuredBuffer the shader
  // sees (the runtime array's stride, else the block's size). D3D12 structured
  // views need it; Vulkan ignores it.
  uint32_t structureStride = 0;
  std::string name;  // the shader's variable/block name, for error messages
};

struct BindingLayout {
  uint32_t space = 0;
  std::vector<BindingLayoutItem> items;  // sorted by slot
};

struct PipelineBindingLayout {
  std::vector<BindingLayout> spaces;  // index = space number (may have empty spaces)
  uint32_t pushConstantBytes = 0;     // D3D12: root constants. Vulkan: push constant range
};

struct BindingSetItem {
  uint32_t slot = 0;
  ResourceType type = ResourceType::StorageBuffer;
  BufferHandle buffer;
  TextureHandle texture;
  rt::AccelStructHandle accelStruct;
  // SampledTexture items: one texture per array element, element i at index i
  // (a single Texture2D takes exactly one). Textures need TextureUsage::Sampled.
  std::vector<TextureHandle> textures;
  // Sampler items, likewise. (Not called `samplers`: C++ does not allow a data
  // member and the factory below to share a name.)
  std::vector<SamplerHandle> samplerHandles;

  static BindingSetItem storageBuffer(uint32_t slot, BufferHandle b) {
    BindingSetItem item{slot, ResourceType::StorageBuffer};
    item.buffer = std::move(b);
    return item;
  }
  static BindingSetItem constantBuffer(uint32_t slot, BufferHandle b) {
    BindingSetItem item{slot, ResourceType::ConstantBuffer};
    item.buffer = std::move(b);
    return item;
  }
  static BindingSetItem storageTexture(uint32_t slot, TextureHandle t) {
    BindingSetItem item{slot, ResourceType::StorageTexture};
    item.texture = std::move(t);
    return item;
  }
  static BindingSetItem accelStructure(uint32_t slot, rt::AccelStructHandle a) {
    BindingSetItem item{slot, ResourceType::AccelStruct};
    item.accelStruct = std::move(a);
    return item;
  }
  static BindingSetItem sampledTextures(uint32_t slot, std::vector<TextureHandle> t) {
    BindingSetItem item{slot, ResourceType::SampledTexture};
    item.textures = std::move(t);
    return item;
  }
  static BindingSetItem samplers(uint32_t slot, std::vector<SamplerHandle> s) {
    BindingSetItem item{slot, ResourceType::Sampler};
    item.samplerHandles = std::move(s);
    return item;
  }
  // Descriptors this item writes: the elements of a texture or sampler
  // array, else one.
  size_t elementCount() const {
    if (type == ResourceType::SampledTexture) return textures.size();
    if (type == ResourceType::Sampler) return samplerHandles.size();
    return 1;
  }
};

struct BindingSetDesc {
  uint32_t space = 0;
  std::vector<BindingSetItem> items;
  std::string debugName;
};

// D3D12: a range of a shader-visible CBV/SRV/UAV descriptor heap, bound as a
// descriptor table of the global root signature.
// Vulkan: a VkDescriptorSet bound with vkCmdBindDescriptorSets.
class IBindingSet {
 public:
  virtual ~IBindingSet() = default;
  virtual const BindingSetDesc& desc() const = 0;
};
using BindingSetHandle = std::shared_ptr<IBindingSet>;

// ---- Shaders and pipelines ----------------------------------------------

// One entry point in both APIs' forms; each backend takes the one it needs.
// The generated shader tables (cmake/Shaders.cmake: <ns>::shaderDesc(name))
// fill every field. The bytes must outlive pipeline creation only.
struct ShaderDesc {
  ShaderStage stage = ShaderStage::Compute;
  std::span<const uint32_t> spirv;  // Vulkan: SPIR-V words
  // D3D12: DXIL, a library (-T lib_6_3) for ray-tracing stages or a compute
  // object (-T cs_6_3); empty when the build had no DXC.
  std::span<const uint8_t> dxil;
  // What this shader declares (resources, push constants), reflected from its
  // SPIR-V at build time. Backends merge the shaders' layouts into the
  // pipeline's (binding_layout.h).
  PipelineBindingLayout bindingLayout;
  // Bytes of local data the shader reads from its shader-table record
  // (Vulkan shaderRecordEXT; D3D12 local root constants).
  uint32_t shaderRecordBytes = 0;
  std::string entryPoint = "main";  // name inside the module / DXIL library
  std::string exportName;           // name used by hit groups and shader tables
};

// D3D12: D3D12_HIT_GROUP_DESC (TRIANGLES or PROCEDURAL_PRIMITIVE).
// Vulkan: a VkRayTracingShaderGroupCreateInfoKHR of type
// TRIANGLES_HIT_GROUP or PROCEDURAL_HIT_GROUP.
struct HitGroupDesc {
  std::string exportName;
  std::string closestHit;  // export names of shaders in the pipeline ("" = none)
  std::string anyHit;
  std::string intersection;  // required when isProcedural
  bool isProcedural = false;
};

struct RayTracingPipelineDesc {
  std::vector<ShaderDesc> shaders;  // raygen, miss and hit shaders
  std::vector<HitGroupDesc> hitGroups;
  uint32_t maxPayloadBytes = 32;  // D3D12_RAYTRACING_SHADER_CONFIG (Vulkan infers it)
  uint32_t maxAttributeBytes = 8;
  uint32_t maxRecursionDepth = 1;  // D3D12 pipeline config / VkRayTracingPipelineCreateInfoKHR
  std::string debugName;
};

struct ComputePipelineDesc {
  ShaderDesc shader;
  std::string debugName;
};

// ---- The raster subset ----------------------------------------------------
// Enough rasterisation for the viewer's UI and overlays, the same on both
// APIs: indexed triangle lists from one vertex buffer, no depth or stencil,
// no culling, one render target, optional alpha blending. Clip space is
// D3D12's on both backends (+y up; Vulkan flips its viewport), so one vertex
// shader serves both.

// One per-vertex attribute. `location` is GLSL's `layout(location = N) in`
// and HLSL's semantic TEXCOORD<N>, which the shared dialect's
// PT_VERTEX_INPUT(N, ...) declares on both sides.
// D3D12: a D3D12_INPUT_ELEMENT_DESC (TEXCOORD, N, format, slot 0, offset, PER_VERTEX_DATA).
// Vulkan: a VkVertexInputAttributeDescription (location N, binding 0, format, offset).
struct VertexAttribute {
  uint32_t location = 0;
  Format format = Format::RG32_FLOAT;  // RG32_FLOAT, RGB32_FLOAT, RGBA32_FLOAT or RGBA8_UNORM
  uint32_t offset = 0;                 // bytes from the vertex's start
};

// One vertex buffer of `stride`-byte vertices.
// D3D12: D3D12_INPUT_LAYOUT_DESC + the stride of IASetVertexBuffers' view.
// Vulkan: one VkVertexInputBindingDescription (binding 0, INPUT_RATE_VERTEX).
struct VertexLayout {
  uint32_t stride = 0;
  std::vector<VertexAttribute> attributes;
};

enum class BlendMode : uint8_t {
  Opaque,      // the pixel shader's output replaces the target
  AlphaBlend,  // colour = src * src.a + dst * (1 - src.a); alpha = src.a + dst.a * (1 - src.a)
};

struct GraphicsPipelineDesc {
  ShaderDesc vertexShader;  // ShaderStage::Vertex
  ShaderDesc pixelShader;   // ShaderStage::Pixel, writing SV_Target0 / location 0
  VertexLayout vertexLayout;
  BlendMode blend = BlendMode::Opaque;
  Format renderTargetFormat = Format::RGBA8_UNORM;  // RGBA8_UNORM or BGRA8_UNORM
  std::string debugName;
};

class IPipeline {
 public:
  virtual ~IPipeline() = default;
  virtual const PipelineBindingLayout& bindingLayout() const = 0;
};

// D3D12: ID3D12PipelineState from a D3D12_GRAPHICS_PIPELINE_STATE_DESC
// (TRIANGLE topology, CULL_NONE, depth off, one RTV format) + root signature.
// Vulkan: VkPipeline from vkCreateGraphicsPipelines for dynamic rendering
// (VkPipelineRenderingCreateInfo: one colour format), dynamic viewport and
// scissor, CULL_MODE_NONE, no depth.
class IGraphicsPipeline : public IPipeline {
 public:
  virtual const GraphicsPipelineDesc& desc() const = 0;
};
using GraphicsPipelineHandle = std::shared_ptr<IGraphicsPipeline>;

// D3D12: ID3D12PipelineState (compute) + root signature.
// Vulkan: VkPipeline (compute) + VkPipelineLayout.
class IComputePipeline : public IPipeline {};
using ComputePipelineHandle = std::shared_ptr<IComputePipeline>;

class IShaderTable;
using ShaderTableHandle = std::shared_ptr<IShaderTable>;

// D3D12: ID3D12StateObject (DXIL libraries, hit groups, shader/pipeline config).
// Vulkan: VkPipeline from vkCreateRayTracingPipelinesKHR.
class IRayTracingPipeline : public IPipeline {
 public:
  virtual const RayTracingPipelineDesc& desc() const = 0;
  virtual ShaderTableHandle createShaderTable(const std::string& debugName) = 0;
};
using RayTracingPipelineHandle = std::shared_ptr<IRayTracingPipeline>;

// The records DispatchRays / vkCmdTraceRaysKHR read. Each record is a shader
// identifier followed by optional local data (D3D12 local root constants,
// Vulkan shaderRecordEXT). The backend lays records out with its API's
// alignments (shader_table_layout.h) and uploads them when the table changed.
// Miss index i and hit-group index j in TraceRay refer to the order of the
// add* calls.
class IShaderTable {
 public:
  virtual ~IShaderTable() = default;
  virtual void setRayGenerationShader(const std::string& exportName,
                                      const void* localData = nullptr, size_t localBytes = 0) = 0;
  virtual uint32_t addMissShader(const std::string& exportName, const void* localData = nullptr,
                                 size_t localBytes = 0) = 0;
  virtual uint32_t addHitGroup(const std::string& exportName, const void* localData = nullptr,
                               size_t localBytes = 0) = 0;
  virtual void clearMissShaders() = 0;
  virtual void clearHitGroups() = 0;
};

}  // namespace penumbra::rhi
