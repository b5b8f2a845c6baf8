// The validation layer's device-level rules (rhi/validation.h): resource and
// acceleration-structure descriptions, pipeline composition, shader-table
// records, binding sets, submission and presentation.
#include <algorithm>
#include <map>

#include "penumbra/rhi/binding_layout.h"
#include "penumbra/rhi/validation_objects.h"

namespace penumbra::rhi::validation {
namespace {

// D3D12_RAYTRACING_MAX_ATTRIBUTE_SIZE_IN_BYTES; Vulkan's maxRayHitAttributeSize
// is 32 on every driver that reports it.
constexpr uint32_t kMaxAttributeBytes = 32;

void checkRange(const char* call, const std::string& as, const char* what, const IBuffer* buffer,
                uint64_t offset, uint64_t bytes) {
  if (!buffer) fail(call, "'{}' has a {} without a buffer", as, what);
  const BufferDesc& d = buffer->desc();
  if (!hasFlag(d.usage, BufferUsage::AccelStructBuildInput))
    fail(call, "'{}': the {} {} lacks BufferUsage::AccelStructBuildInput", as, what, nameOf(d));
  if (offset + bytes > d.byteSize)
    fail(call, "'{}': the {} ({} bytes at offset {}) overflows {} ({} bytes)", as, what, bytes,
         offset, nameOf(d), d.byteSize);
}

void checkTriangles(const char* call, const std::string& as, const rt::GeometryTriangles& t) {
  if (!t.vertexBuffer) fail(call, "'{}' has a triangle geometry without vertices", as);
  if (t.vertexFormat != Format::RGB32_FLOAT)
    fail(call, "'{}': vertex positions must be RGB32_FLOAT", as);
  if (t.vertexStride < 12 || t.vertexStride % 4 != 0)
    fail(call, "'{}': a vertex stride of {} bytes (needs a multiple of 4, at least 12)", as,
         t.vertexStride);
  if (t.vertexCount == 0) fail(call, "'{}' has a triangle geometry of 0 vertices", as);
  checkRange(call, as, "vertex data", t.vertexBuffer, t.vertexOffset,
             uint64_t(t.vertexCount - 1) * t.vertexStride + 12);
  if (t.indexBuffer) {
    if (t.indexFormat != Format::R32_UINT && t.indexFormat != Format::R16_UINT)
      fail(call, "'{}': indices must be R32_UINT or R16_UINT", as);
    if (t.indexCount == 0 || t.indexCount % 3 != 0)
      fail(call, "'{}': {} indices are not whole triangles", as, t.indexCount);
    const uint32_t indexBytes = formatByteSize(t.indexFormat);
    if (t.indexOffset % indexBytes != 0)
      fail(call, "'{}': index offset {} is not a multiple of the index size", as, t.indexOffset);
    checkRange(call, as, "index data", t.indexBuffer, t.indexOffset,
               uint64_t(t.indexCount) * indexBytes);
  } else if (t.vertexCount % 3 != 0) {
    fail(call, "'{}': {} non-indexed vertices are not whole triangles", as, t.vertexCount);
  }
  if (t.transformBuffer) {
    if (t.transformOffset % 16 != 0)
      fail(call, "'{}': transform offset {} is not 16-byte aligned", as, t.transformOffset);
    checkRange(call, as, "transform", t.transformBuffer, t.transformOffset,
               sizeof(rt::AffineTransform));
  }
}

void checkAABBs(const char* call, const std::string& as, const rt::GeometryAABBs& a) {
  if (!a.buffer) fail(call, "'{}' has an AABB geometry without a buffer", as);
  if (a.count == 0) fail(call, "'{}' has an AABB geometry of 0 boxes", as);
  if (a.stride < 24 || a.stride % 8 != 0)
    fail(call, "'{}': an AABB stride of {} bytes (needs a multiple of 8, at least 24)", as,
         a.stride);
  if (a.offset % 8 != 0) fail(call, "'{}': AABB offset {} is not 8-byte aligned", as, a.offset);
  checkRange(call, as, "AABB data", a.buffer, a.offset, uint64_t(a.count - 1) * a.stride + 24);
}

const ShaderDesc* findShader(const RayTracingPipelineDesc& desc, const std::string& name) {
  for (const auto& s : desc.shaders)
    if (s.exportName == name) return &s;
  return nullptr;
}

const HitGroupDesc* findHitGroup(const RayTracingPipelineDesc& desc, const std::string& name) {
  for (const auto& g : desc.hitGroups)
    if (g.exportName == name) return &g;
  return nullptr;
}

void checkHitGroupShader(const RayTracingPipelineDesc& desc, const HitGroupDesc& group,
                         const std::string& name, ShaderStage stage) {
  if (name.empty()) return;
  const ShaderDesc* shader = findShader(desc, name);
  if (!shader)
    fail("createRayTracingPipeline", "pipeline '{}': hit group '{}' names unknown shader '{}'",
         desc.debugName, group.exportName, name);
  if (shader->stage != stage)
    fail("createRayTracingPipeline",
         "pipeline '{}': hit group '{}' uses '{}', a {} shader, as its {}", desc.debugName,
         group.exportName, name, shaderStageName(shader->stage), shaderStageName(stage));
}

}  // namespace

// ---- Device ----------------------------------------------------------------

BufferHandle ValidationDevice::createBuffer(const BufferDesc& desc) {
  if (desc.byteSize == 0) fail("createBuffer", "{} has zero size", nameOf(desc));
  if (desc.memory != MemoryLocation::DeviceLocal &&
      hasFlag(desc.usage, BufferUsage::AccelStructStorage))
    fail("createBuffer", "{}: acceleration-structure storage must be device-local", nameOf(desc));
  return backend_->createBuffer(desc);
}

TextureHandle ValidationDevice::createTexture(const TextureDesc& desc) {
  if (desc.width == 0 || desc.height == 0)
    fail("createTexture", "{} is {}x{}", nameOf(desc), desc.width, desc.height);
  // Neither API can write sRGB textures from shaders (no storage sRGB formats).
  if (desc.format == Format::RGBA8_SRGB && hasFlag(desc.usage, TextureUsage::Storage))
    fail("createTexture", "{}: RGBA8_SRGB cannot have TextureUsage::Storage", nameOf(desc));
  if (desc.mipLevels == 0 || desc.mipLevels > mipLevelCount(desc.width, desc.height))
    fail("createTexture", "{} ({}x{}) has {} mip levels; it can have 1 to {}", nameOf(desc),
         desc.width, desc.height, desc.mipLevels, mipLevelCount(desc.width, desc.height));
  // Storage and render-target views, copies and readbacks address level 0.
  if (desc.mipLevels > 1 && (hasFlag(desc.usage, TextureUsage::Storage) ||
                             hasFlag(desc.usage, TextureUsage::RenderTarget)))
    fail("createTexture",
         "{}: a texture with mip levels is sampled only, not storage or a render target",
         nameOf(desc));
  return backend_->createTexture(desc);
}

rt::AccelStructHandle ValidationDevice::createAccelStruct(const rt::AccelStructDesc& desc) {
  const char* call = "createAccelStruct";
  if (desc.isTopLevel) {
    if (desc.topLevelMaxInstances == 0)
      fail(call, "top level '{}' has topLevelMaxInstances = 0", desc.debugName);
    if (!desc.bottomLevelGeometries.empty())
      fail(call, "top level '{}' has bottom-level geometries", desc.debugName);
  } else {
    if (desc.bottomLevelGeometries.empty())
      fail(call, "bottom level '{}' has no geometry", desc.debugName);
    for (const auto& g : desc.bottomLevelGeometries) {
      if (g.type == rt::GeometryType::Triangles)
        checkTriangles(call, desc.debugName, g.triangles);
      else
        checkAABBs(call, desc.debugName, g.aabbs);
    }
  }
  return backend_->createAccelStruct(desc);
}

RayTracingPipelineHandle ValidationDevice::createRayTracingPipeline(
    const RayTracingPipelineDesc& desc) {
  const char* call = "createRayTracingPipeline";
  const AdapterInfo& adapter = backend_->adapter();
  if (desc.maxRecursionDepth < 1 || desc.maxRecursionDepth > adapter.maxRecursionDepth)
    fail(call, "pipeline '{}' asks for recursion depth {}; {} allows 1 to {}", desc.debugName,
         desc.maxRecursionDepth, adapter.name, adapter.maxRecursionDepth);
  if (desc.maxAttributeBytes > kMaxAttributeBytes)
    fail(call, "pipeline '{}': {} attribute bytes exceed the APIs' {}", desc.debugName,
         desc.maxAttributeBytes, kMaxAttributeBytes);
  std::map<std::string, std::string> exports;  // name -> what it names, for the error
  bool hasRayGeneration = false;
  for (const auto& shader : desc.shaders) {
    if (shader.stage == ShaderStage::Compute)
      fail(call, "pipeline '{}': '{}' is a compute shader", desc.debugName, shader.exportName);
    if (!exports.emplace(shader.exportName, "a shader").second)
      fail(call, "pipeline '{}': export name '{}' used twice", desc.debugName, shader.exportName);
    hasRayGeneration |= shader.stage == ShaderStage::RayGeneration;
  }
  if (!hasRayGeneration) fail(call, "pipeline '{}' has no ray generation shader", desc.debugName);
  for (const auto& group : desc.hitGroups) {
    if (!exports.emplace(group.exportName, "a hit group").second)
      fail(call, "pipeline '{}': export name '{}' used twice (already {})", desc.debugName,
           group.exportName, exports[group.exportName]);
    checkHitGroupShader(desc, group, group.closestHit, ShaderStage::ClosestHit);
    checkHitGroupShader(desc, group, group.anyHit, ShaderStage::AnyHit);
    checkHitGroupShader(desc, group, group.intersection, ShaderStage::Intersection);
    if (group.isProcedural && group.intersection.empty())
      fail(call, "pipeline '{}': procedural hit group '{}' has no intersection shader",
           desc.debugName, group.exportName);
    if (!group.isProcedural && !group.intersection.empty())
      fail(call, "pipeline '{}': triangle hit group '{}' has an intersection shader",
           desc.debugName, group.exportName);
  }
  return std::make_shared<ValidationRayTracingPipeline>(backend_->createRayTracingPipeline(desc));
}

ComputePipelineHandle ValidationDevice::createComputePipeline(const ComputePipelineDesc& desc) {
  if (desc.shader.stage != ShaderStage::Compute)
    fail("createComputePipeline", "pipeline '{}': '{}' is a {} shader, not a compute shader",
         desc.debugName, desc.shader.exportName, shaderStageName(desc.shader.stage));
  return std::make_shared<ValidationComputePipeline>(backend_->createComputePipeline(desc),
                                                     desc.debugName);
}

GraphicsPipelineHandle ValidationDevice::createGraphicsPipeline(const GraphicsPipelineDesc& desc) {
  const char* call = "createGraphicsPipeline";
  if (desc.vertexShader.stage != ShaderStage::Vertex)
    fail(call, "pipeline '{}': the vertex shader '{}' is a {} shader", desc.debugName,
         desc.vertexShader.exportName, shaderStageName(desc.vertexShader.stage));
  if (desc.pixelShader.stage != ShaderStage::Pixel)
    fail(call, "pipeline '{}': the pixel shader '{}' is a {} shader", desc.debugName,
         desc.pixelShader.exportName, shaderStageName(desc.pixelShader.stage));
  if (desc.renderTargetFormat != Format::RGBA8_UNORM &&
      desc.renderTargetFormat != Format::BGRA8_UNORM)
    fail(call, "pipeline '{}': render targets are RGBA8_UNORM or BGRA8_UNORM", desc.debugName);
  const VertexLayout& v = desc.vertexLayout;
  if (v.stride == 0 || v.stride > 2048)
    fail(call, "pipeline '{}': a vertex stride of {} bytes (1 to 2048)", desc.debugName, v.stride);
  std::set<uint32_t> locations;
  for (const auto& a : v.attributes) {
    if (a.format != Format::RG32_FLOAT && a.format != Format::RGB32_FLOAT &&
        a.format != Format::RGBA32_FLOAT && a.format != Format::RGBA8_UNORM)
      fail(call, "pipeline '{}': attribute {} has a format vertex input does not take",
           desc.debugName, a.location);
    if (uint64_t(a.offset) + formatByteSize(a.format) > v.stride)
      fail(call, "pipeline '{}': attribute {} ({} bytes at offset {}) overflows the {}-byte vertex",
           desc.debugName, a.location, formatByteSize(a.format), a.offset, v.stride);
    if (!locations.insert(a.location).second)
      fail(call, "pipeline '{}': two attributes at location {}", desc.debugName, a.location);
  }
  // The raster subset reads resources only: a draw's barriers go before
  // beginRendering, and nothing orders a pixel shader's writes.
  PipelineBindingLayout merged;
  mergeBindingLayout(merged, desc.vertexShader.bindingLayout, desc.vertexShader.exportName);
  mergeBindingLayout(merged, desc.pixelShader.bindingLayout, desc.pixelShader.exportName);
  for (const auto& space : merged.spaces)
    for (const auto& item : space.items)
      if (item.writable)
        fail(call, "pipeline '{}': '{}' is written by a raster stage; graphics pipelines only read",
             desc.debugName, item.name);
  return std::make_shared<ValidationGraphicsPipeline>(backend_->createGraphicsPipeline(desc));
}

BindingSetHandle ValidationDevice::createBindingSet(const BindingSetDesc& desc,
                                                    const IPipeline& pipeline) {
  const char* call = "createBindingSet";
  const PipelineBindingLayout& layout = pipeline.bindingLayout();
  const std::string setName = fmt::format("binding set '{}'", desc.debugName);
  try {
    validateBindingSet(desc, layout);
  } catch (const Error& e) {
    fail(call, "{}", e.what());
  }
  static const BindingLayout kNothing;
  const BindingLayout& space =
      desc.space < layout.spaces.size() ? layout.spaces[desc.space] : kNothing;
  for (const auto& item : desc.items) {
    const auto declared =
        std::find_if(space.items.begin(), space.items.end(),
                     [&](const BindingLayoutItem& i) { return i.slot == item.slot; });
    if (item.type == ResourceType::StorageBuffer) {
      const BufferDesc& b = item.buffer->desc();
      if (!hasFlag(b.usage, BufferUsage::StorageBuffer))
        fail(call, "{}: {} at slot {} ('{}') lacks BufferUsage::StorageBuffer", setName, nameOf(b),
             item.slot, declared->name);
      // D3D12 structured views count whole elements.
      if (declared->structureStride == 0 || b.byteSize < declared->structureStride)
        fail(call, "{}: {} ({} bytes) at slot {} ('{}') holds no whole {}-byte element", setName,
             nameOf(b), b.byteSize, item.slot, declared->name, declared->structureStride);
      if (declared->writable && b.memory != MemoryLocation::DeviceLocal)
        fail(call, "{}: {} at slot {} ('{}') is written by shaders but is not device-local",
             setName, nameOf(b), item.slot, declared->name);
    } else if (item.type == ResourceType::ConstantBuffer) {
      const BufferDesc& b = item.buffer->desc();
      if (!hasFlag(b.usage, BufferUsage::ConstantBuffer))
        fail(call, "{}: {} at slot {} ('{}') lacks BufferUsage::ConstantBuffer", setName, nameOf(b),
             item.slot, declared->name);
    } else if (item.type == ResourceType::StorageTexture) {
      const TextureDesc& t = item.texture->desc();
      if (!hasFlag(t.usage, TextureUsage::Storage))
        fail(call, "{}: {} at slot {} ('{}') lacks TextureUsage::Storage", setName, nameOf(t),
             item.slot, declared->name);
    } else if (item.type == ResourceType::AccelStruct && !item.accelStruct->desc().isTopLevel) {
      fail(call, "{}: slot {} ('{}') takes a top level; '{}' is a bottom level", setName, item.slot,
           declared->name, item.accelStruct->desc().debugName);
    }
  }
  BindingSetHandle backendSet = backend_->createBindingSet(desc, backendObject(pipeline));
  return std::make_shared<ValidationBindingSet>(std::move(backendSet), space);
}

CommandListHandle ValidationDevice::createCommandList(const std::string& debugName) {
  return std::make_shared<ValidationCommandList>(backend_->createCommandList(debugName), debugName,
                                                 this);
}

SwapchainHandle ValidationDevice::createSwapchain(const SwapchainDesc& desc) {
  if (desc.framesInFlight < 1 || desc.framesInFlight > 4)
    fail("createSwapchain", "swapchain '{}': {} frames in flight (1 to 4)", desc.debugName,
         desc.framesInFlight);
  return std::make_shared<ValidationSwapchain>(backend_->createSwapchain(desc));
}

void ValidationDevice::submit(ICommandList* commandList) {
  auto* list = dynamic_cast<ValidationCommandList*>(commandList);
  if (!list || list->device() != this)
    fail("submit", "the command list was not created by this device");
  if (list->isOpen())
    fail("submit", "command list '{}' is still open; close() it first", list->debugName());
  backend_->submit(list->backend());
}

// ---- Ray-tracing pipelines and shader tables ----------------------------------

ValidationRayTracingPipeline::ValidationRayTracingPipeline(RayTracingPipelineHandle backend)
    : backend_(std::move(backend)) {}

ShaderTableHandle ValidationRayTracingPipeline::createShaderTable(const std::string& debugName) {
  return std::make_shared<ValidationShaderTable>(shared_from_this(),
                                                 backend_->createShaderTable(debugName), debugName);
}

std::optional<ShaderStage> ValidationRayTracingPipeline::shaderStage(
    const std::string& exportName) const {
  if (const ShaderDesc* s = findShader(desc(), exportName)) return s->stage;
  return std::nullopt;
}

bool ValidationRayTracingPipeline::isHitGroup(const std::string& exportName) const {
  return findHitGroup(desc(), exportName) != nullptr;
}

uint32_t ValidationRayTracingPipeline::recordCapacity(const std::string& exportName) const {
  uint32_t bytes = 0;
  if (const ShaderDesc* s = findShader(desc(), exportName)) bytes = s->shaderRecordBytes;
  if (const HitGroupDesc* g = findHitGroup(desc(), exportName))
    for (const std::string* name : {&g->closestHit, &g->anyHit, &g->intersection})
      if (const ShaderDesc* s = findShader(desc(), *name))
        bytes = std::max(bytes, s->shaderRecordBytes);
  return (bytes + 3) / 4 * 4;
}

ValidationShaderTable::ValidationShaderTable(std::shared_ptr<ValidationRayTracingPipeline> pipeline,
                                             ShaderTableHandle backend, std::string debugName)
    : pipeline_(std::move(pipeline)),
      backend_(std::move(backend)),
      debugName_(std::move(debugName)) {}

void ValidationShaderTable::checkRecord(const char* call, const std::string& exportName,
                                        const void* localData, size_t localBytes) const {
  if (localBytes > 0 && !localData)
    fail(call, "shader table '{}': {} bytes of local data for '{}' from a null pointer", debugName_,
         localBytes, exportName);
  const uint32_t capacity = pipeline_->recordCapacity(exportName);
  // More data than the shaders declare would be dropped by D3D12's local root
  // signature and read by nothing on Vulkan: the caller and shader disagree.
  if (localBytes > capacity)
    fail(call, "shader table '{}': {} bytes of local data for '{}', whose shaders read {}",
         debugName_, localBytes, exportName, capacity);
}

void ValidationShaderTable::setRayGenerationShader(const std::string& exportName,
                                                   const void* localData, size_t localBytes) {
  const char* call = "setRayGenerationShader";
  if (pipeline_->shaderStage(exportName) != ShaderStage::RayGeneration)
    fail(call, "shader table '{}': pipeline '{}' has no ray generation shader '{}'", debugName_,
         pipeline_->desc().debugName, exportName);
  checkRecord(call, exportName, localData, localBytes);
  backend_->setRayGenerationShader(exportName, localData, localBytes);
  hasRayGeneration_ = true;
}

uint32_t ValidationShaderTable::addMissShader(const std::string& exportName, const void* localData,
                                              size_t localBytes) {
  const char* call = "addMissShader";
  if (pipeline_->shaderStage(exportName) != ShaderStage::Miss)
    fail(call, "shader table '{}': pipeline '{}' has no miss shader '{}'", debugName_,
         pipeline_->desc().debugName, exportName);
  checkRecord(call, exportName, localData, localBytes);
  return backend_->addMissShader(exportName, localData, localBytes);
}

uint32_t ValidationShaderTable::addHitGroup(const std::string& exportName, const void* localData,
                                            size_t localBytes) {
  const char* call = "addHitGroup";
  if (!pipeline_->isHitGroup(exportName))
    fail(call, "shader table '{}': pipeline '{}' has no hit group '{}'", debugName_,
         pipeline_->desc().debugName, exportName);
  checkRecord(call, exportName, localData, localBytes);
  return backend_->addHitGroup(exportName, localData, localBytes);
}

void ValidationShaderTable::clearMissShaders() {
  backend_->clearMissShaders();
}
void ValidationShaderTable::clearHitGroups() {
  backend_->clearHitGroups();
}

// ---- Swapchains ------------------------------------------------------------

ITexture* ValidationSwapchain::acquireNextImage() {
  acquired_ = backend_->acquireNextImage();
  return acquired_;
}

bool ValidationSwapchain::present(ICommandList* commandList) {
  const char* call = "present";
  auto* list = dynamic_cast<ValidationCommandList*>(commandList);
  if (!list) fail(call, "swapchain '{}': the command list is not a device's", desc().debugName);
  if (!acquired_)
    fail(call, "swapchain '{}': no back buffer was acquired (acquireNextImage)", desc().debugName);
  if (list->isOpen())
    fail(call, "command list '{}' is still open; close() it first", list->debugName());
  if (acquired_->state != ResourceState::Present)
    fail(call, "swapchain '{}': the list leaves back buffer '{}' in {}, not Present",
         desc().debugName, acquired_->desc().debugName, resourceStateName(acquired_->state));
  acquired_ = nullptr;
  return backend_->present(list->backend());
}

// ---- Wrapping -------------------------------------------------------------

DeviceHandle wrapDevice(DeviceHandle backendDevice) {
  return std::make_shared<ValidationDevice>(std::move(backendDevice));
}

const IPipeline& backendObject(const IPipeline& pipeline) {
  if (auto* rt = dynamic_cast<const ValidationRayTracingPipeline*>(&pipeline))
    return *rt->backend();
  if (auto* cs = dynamic_cast<const ValidationComputePipeline*>(&pipeline)) return *cs->backend();
  if (auto* gp = dynamic_cast<const ValidationGraphicsPipeline*>(&pipeline)) return *gp->backend();
  return pipeline;
}

}  // namespace penumbra::rhi::validation
