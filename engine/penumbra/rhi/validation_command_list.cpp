// The validation layer's command-list rules (rhi/validation.h): recording
// state, copy ranges, barrier states against usage and memory, acceleration
// structure builds, bound state for dispatches, push constants, timer queries.
#include "penumbra/rhi/validation_objects.h"

namespace penumbra::rhi::validation {
namespace {

// Both APIs' limits: D3D12_CS_DISPATCH_MAX_THREAD_GROUPS_PER_DIMENSION and the
// minimum Vulkan guarantees for maxComputeWorkGroupCount; DispatchRays'
// width*height*depth limit and Vulkan's minimum maxRayDispatchInvocationCount.
constexpr uint32_t kMaxThreadGroupsPerDimension = 65535;
constexpr uint64_t kMaxRayDispatchInvocations = uint64_t(1) << 30;

bool fits(uint64_t offset, uint64_t bytes, uint64_t size) {
  return offset <= size && bytes <= size - offset;
}

bool sameItems(const BindingLayout& a, const BindingLayout& b) {
  if (a.items.size() != b.items.size()) return false;
  for (size_t i = 0; i < a.items.size(); ++i) {
    const auto &x = a.items[i], &y = b.items[i];
    if (x.slot != y.slot || x.type != y.type || x.arraySize != y.arraySize ||
        x.writable != y.writable || x.structureStride != y.structureStride)
      return false;
  }
  return true;
}

// What usage or memory a buffer needs to be put in `state`, or "" when it may be.
std::string bufferStateProblem(const BufferDesc& d, ResourceState state) {
  if (hasFlag(d.usage, BufferUsage::AccelStructStorage))
    return "holds an acceleration structure; use setAccelStructState";
  auto needs = [&](BufferUsage usage, const char* name) -> std::string {
    return hasFlag(d.usage, usage) ? "" : fmt::format("lacks {}", name);
  };
  // D3D12 upload heaps stay in GENERIC_READ and readback heaps in COPY_DEST.
  const bool upload = d.memory == MemoryLocation::Upload;
  const bool readback = d.memory == MemoryLocation::Readback;
  switch (state) {
    case ResourceState::ShaderResource:
      if (readback) return "is a readback buffer, which shaders cannot read";
      return needs(BufferUsage::StorageBuffer, "BufferUsage::StorageBuffer");
    case ResourceState::UnorderedAccess:
      if (upload || readback) return "is not device-local, so shaders cannot write it";
      return needs(BufferUsage::StorageBuffer, "BufferUsage::StorageBuffer");
    case ResourceState::ConstantBuffer:
      if (readback) return "is a readback buffer, which shaders cannot read";
      return needs(BufferUsage::ConstantBuffer, "BufferUsage::ConstantBuffer");
    case ResourceState::AccelStructBuildInput:
      if (readback) return "is a readback buffer, which builds cannot read";
      return needs(BufferUsage::AccelStructBuildInput, "BufferUsage::AccelStructBuildInput");
    case ResourceState::ShaderTable:
      return needs(BufferUsage::ShaderTable, "BufferUsage::ShaderTable");
    case ResourceState::CopySource:
      return readback ? "is a readback buffer, which copies cannot read" : "";
    case ResourceState::CopyDest:
      return upload ? "is an upload buffer, which copies cannot write" : "";
    case ResourceState::HostRead:
      return readback ? "" : "is not a readback buffer";
    case ResourceState::VertexInput:
      if (readback) return "is a readback buffer, which draws cannot read";
      return hasFlag(d.usage, BufferUsage::VertexBuffer) ||
                     hasFlag(d.usage, BufferUsage::IndexBuffer)
                 ? ""
                 : "lacks BufferUsage::VertexBuffer and BufferUsage::IndexBuffer";
    case ResourceState::Undefined:
    case ResourceState::AccelStructWrite:
    case ResourceState::AccelStructRead:
    case ResourceState::RenderTarget:
    case ResourceState::Present:
      break;
  }
  return "cannot be put in a texture's or acceleration structure's state";
}

std::string textureStateProblem(const TextureDesc& d, ResourceState state) {
  auto needs = [&](TextureUsage usage, const char* name) -> std::string {
    return hasFlag(d.usage, usage) ? "" : fmt::format("lacks {}", name);
  };
  switch (state) {
    case ResourceState::ShaderResource:
      return needs(TextureUsage::Sampled, "TextureUsage::Sampled");
    case ResourceState::UnorderedAccess:
      return needs(TextureUsage::Storage, "TextureUsage::Storage");
    case ResourceState::RenderTarget:
      return needs(TextureUsage::RenderTarget, "TextureUsage::RenderTarget");
    case ResourceState::CopySource:
    case ResourceState::CopyDest:
    case ResourceState::Present:
      return "";
    default:
      break;
  }
  return "cannot be put in a buffer's or acceleration structure's state";
}

}  // namespace

ValidationCommandList::ValidationCommandList(CommandListHandle backend, std::string debugName,
                                             const IDevice* device)
    : backend_(std::move(backend)), debugName_(std::move(debugName)), device_(device) {}

void ValidationCommandList::requireOpen(const char* call) const {
  if (!open_) fail(call, "command list '{}' is not open", debugName_);
}

void ValidationCommandList::requireOutsideRendering(const char* call) const {
  requireOpen(call);
  if (renderTarget_)
    fail(call, "command list '{}' is rendering into {}; call endRendering first", debugName_,
         nameOf(renderTarget_->desc()));
}

void ValidationCommandList::requireInsideRendering(const char* call) const {
  requireOpen(call);
  if (!renderTarget_) fail(call, "command list '{}': no beginRendering before it", debugName_);
}

void ValidationCommandList::open() {
  if (open_) fail("open", "command list '{}' is already open", debugName_);
  backend_->open();
  open_ = true;
  renderTarget_ = nullptr;
  boundGraphics_ = nullptr;
  bound_ = Bound::Nothing;
  boundPushConstantBytes_ = 0;
  runningQueries_.clear();
}

void ValidationCommandList::close() {
  requireOutsideRendering("close");  // a pass ends in the recording that began it
  if (!runningQueries_.empty())
    fail("close", "command list '{}' has {} timer quer{} begun but not ended", debugName_,
         runningQueries_.size(), runningQueries_.size() == 1 ? "y" : "ies");
  backend_->close();
  open_ = false;
}

void ValidationCommandList::writeBuffer(IBuffer* buffer, const void* data, size_t bytes,
                                        uint64_t offset) {
  const char* call = "writeBuffer";
  requireOutsideRendering(call);
  if (!buffer) fail(call, "command list '{}': no buffer", debugName_);
  const BufferDesc& d = buffer->desc();
  if (!fits(offset, bytes, d.byteSize))
    fail(call, "{} bytes at offset {} overflow {} ({} bytes)", bytes, offset, nameOf(d),
         d.byteSize);
  if (bytes > 0 && !data) fail(call, "{} bytes into {} from a null pointer", bytes, nameOf(d));
  backend_->writeBuffer(buffer, data, bytes, offset);
}

void ValidationCommandList::writeTexture(ITexture* texture, const void* data, size_t bytes) {
  const char* call = "writeTexture";
  requireOutsideRendering(call);
  const TextureDesc& d = texture->desc();
  const uint64_t expected = textureByteSize(d);
  if (bytes != expected)
    fail(call, "{} bytes into {} ({}x{}{}, {} bytes)", bytes, nameOf(d), d.width, d.height,
         d.mipLevels > 1 ? fmt::format(" and {} smaller mip levels", d.mipLevels - 1) : "",
         expected);
  if (!data) fail(call, "{} bytes into {} from a null pointer", bytes, nameOf(d));
  backend_->writeTexture(texture, data, bytes);
}

void ValidationCommandList::copyBuffer(IBuffer* dst, uint64_t dstOffset, IBuffer* src,
                                       uint64_t srcOffset, uint64_t bytes) {
  const char* call = "copyBuffer";
  requireOutsideRendering(call);
  const BufferDesc &s = src->desc(), &d = dst->desc();
  if (!fits(srcOffset, bytes, s.byteSize))
    fail(call, "{} bytes at offset {} overflow the source, {} ({} bytes)", bytes, srcOffset,
         nameOf(s), s.byteSize);
  if (!fits(dstOffset, bytes, d.byteSize))
    fail(call, "{} bytes at offset {} overflow the destination, {} ({} bytes)", bytes, dstOffset,
         nameOf(d), d.byteSize);
  if (src == dst && srcOffset < dstOffset + bytes && dstOffset < srcOffset + bytes)
    fail(call, "the source and destination ranges of {} overlap", nameOf(s));
  if (auto problem = bufferStateProblem(s, ResourceState::CopySource); !problem.empty())
    fail(call, "the source, {}, {}", nameOf(s), problem);
  if (auto problem = bufferStateProblem(d, ResourceState::CopyDest); !problem.empty())
    fail(call, "the destination, {}, {}", nameOf(d), problem);
  backend_->copyBuffer(dst, dstOffset, src, srcOffset, bytes);
}

void ValidationCommandList::copyTextureToBuffer(ITexture* src, IBuffer* dst, uint64_t dstOffset) {
  const char* call = "copyTextureToBuffer";
  requireOutsideRendering(call);
  const TextureDesc& s = src->desc();
  const BufferDesc& d = dst->desc();
  const uint64_t bytes = uint64_t(s.width) * s.height * formatByteSize(s.format);
  if (!fits(dstOffset, bytes, d.byteSize))
    fail(call, "{} ({} bytes) does not fit in {} ({} bytes) at offset {}", nameOf(s), bytes,
         nameOf(d), d.byteSize, dstOffset);
  if (auto problem = bufferStateProblem(d, ResourceState::CopyDest); !problem.empty())
    fail(call, "the destination, {}, {}", nameOf(d), problem);
  backend_->copyTextureToBuffer(src, dst, dstOffset);
}

void ValidationCommandList::copyTexture(ITexture* dst, ITexture* src) {
  const char* call = "copyTexture";
  requireOutsideRendering(call);
  const TextureDesc &d = dst->desc(), &s = src->desc();
  if (dst == src) fail(call, "{} onto itself", nameOf(s));
  if (d.width != s.width || d.height != s.height)
    fail(call, "from {} ({}x{}) to {} ({}x{}): sizes differ", nameOf(s), s.width, s.height,
         nameOf(d), d.width, d.height);
  if (formatByteSize(d.format) != formatByteSize(s.format))
    fail(call, "from {} to {}: formats differ in size", nameOf(s), nameOf(d));
  backend_->copyTexture(dst, src);
}

void ValidationCommandList::clearTextureFloat(ITexture* texture, float r, float g, float b,
                                              float a) {
  const char* call = "clearTextureFloat";
  requireOutsideRendering(call);
  // D3D12 clears through an unordered-access view.
  if (!hasFlag(texture->desc().usage, TextureUsage::Storage))
    fail(call, "{} lacks TextureUsage::Storage", nameOf(texture->desc()));
  backend_->clearTextureFloat(texture, r, g, b, a);
}

void ValidationCommandList::clearBufferUint(IBuffer* buffer, uint32_t value) {
  const char* call = "clearBufferUint";
  requireOutsideRendering(call);
  // D3D12 clears through a raw unordered-access view.
  if (auto problem = bufferStateProblem(buffer->desc(), ResourceState::UnorderedAccess);
      !problem.empty())
    fail(call, "{} {}", nameOf(buffer->desc()), problem);
  backend_->clearBufferUint(buffer, value);
}

void ValidationCommandList::setBufferState(IBuffer* buffer, ResourceState state) {
  const char* call = "setBufferState";
  requireOutsideRendering(call);
  if (auto problem = bufferStateProblem(buffer->desc(), state); !problem.empty())
    fail(call, "{} to {}: it {}", nameOf(buffer->desc()), resourceStateName(state), problem);
  backend_->setBufferState(buffer, state);
}

void ValidationCommandList::setTextureState(ITexture* texture, ResourceState state) {
  const char* call = "setTextureState";
  requireOutsideRendering(call);
  if (auto problem = textureStateProblem(texture->desc(), state); !problem.empty())
    fail(call, "{} to {}: it {}", nameOf(texture->desc()), resourceStateName(state), problem);
  backend_->setTextureState(texture, state);
}

void ValidationCommandList::setAccelStructState(rt::IAccelStruct* as, ResourceState state) {
  const char* call = "setAccelStructState";
  requireOutsideRendering(call);
  if (state != ResourceState::AccelStructRead && state != ResourceState::AccelStructWrite)
    fail(call, "'{}' to {}: acceleration structures are only AccelStructRead or AccelStructWrite",
         as->desc().debugName, resourceStateName(state));
  backend_->setAccelStructState(as, state);
}

void ValidationCommandList::buildBottomLevelAccelStruct(rt::IAccelStruct* as) {
  const char* call = "buildBottomLevelAccelStruct";
  requireOutsideRendering(call);
  if (as->desc().isTopLevel)
    fail(call, "'{}' is a top level; use buildTopLevelAccelStruct", as->desc().debugName);
  backend_->buildBottomLevelAccelStruct(as);
}

void ValidationCommandList::buildTopLevelAccelStruct(rt::IAccelStruct* as,
                                                     const rt::InstanceDesc* instances,
                                                     uint32_t count) {
  const char* call = "buildTopLevelAccelStruct";
  requireOutsideRendering(call);
  const rt::AccelStructDesc& d = as->desc();
  if (!d.isTopLevel)
    fail(call, "'{}' is a bottom level; use buildBottomLevelAccelStruct", d.debugName);
  if (count > d.topLevelMaxInstances)
    fail(call, "{} instances exceed '{}' topLevelMaxInstances = {}", count, d.debugName,
         d.topLevelMaxInstances);
  if (count > 0 && !instances)
    fail(call, "{} instances of '{}' from a null pointer", count, d.debugName);
  for (uint32_t i = 0; i < count; ++i)
    if (instances[i].bottomLevelAddress == 0)
      fail(call, "instance {} of '{}' has no bottom level", i, d.debugName);
  backend_->buildTopLevelAccelStruct(as, instances, count);
}

std::vector<IBindingSet*> ValidationCommandList::checkBindingSets(
    const char* call, const PipelineBindingLayout& layout, const std::vector<IBindingSet*>& sets,
    const std::string& pipelineName) const {
  std::vector<IBindingSet*> backendSets;
  for (size_t space = 0; space < sets.size(); ++space) {
    auto* set = dynamic_cast<ValidationBindingSet*>(sets[space]);
    // Vulkan binds the sets as consecutive descriptor sets from set 0.
    if (!set)
      fail(call,
           "pipeline '{}': no binding set at index {} (index = space; fill every index up "
           "to the last)",
           pipelineName, space);
    if (set->desc().space != space)
      fail(call, "pipeline '{}': binding set '{}' of space {} given at index {}", pipelineName,
           set->desc().debugName, set->desc().space, space);
    if (space >= layout.spaces.size() || layout.spaces[space].items.empty())
      fail(call, "pipeline '{}' declares nothing in space {}, but binding set '{}' was given",
           pipelineName, space, set->desc().debugName);
    if (!sameItems(set->layout(), layout.spaces[space]))
      fail(call,
           "binding set '{}' was created for a pipeline whose space {} differs from "
           "pipeline '{}'s",
           set->desc().debugName, space, pipelineName);
    backendSets.push_back(set->backend());
  }
  for (size_t space = sets.size(); space < layout.spaces.size(); ++space)
    if (!layout.spaces[space].items.empty())
      fail(call, "pipeline '{}' uses space {} ('{}') but no binding set for it was given",
           pipelineName, space, layout.spaces[space].items.front().name);
  return backendSets;
}

void ValidationCommandList::setRayTracingState(const RayTracingState& state) {
  const char* call = "setRayTracingState";
  requireOutsideRendering(call);
  auto* pipeline = dynamic_cast<ValidationRayTracingPipeline*>(state.pipeline);
  auto* table = dynamic_cast<ValidationShaderTable*>(state.shaderTable);
  if (!pipeline) fail(call, "command list '{}': no ray-tracing pipeline", debugName_);
  const std::string& name = pipeline->desc().debugName;
  if (!table) fail(call, "pipeline '{}': no shader table", name);
  if (table->pipeline() != pipeline)
    fail(call, "shader table '{}' belongs to pipeline '{}', not '{}'", table->debugName(),
         table->pipeline()->desc().debugName, name);
  if (!table->hasRayGeneration())
    fail(call, "shader table '{}' has no ray generation shader", table->debugName());
  RayTracingState backendState;
  backendState.pipeline = pipeline->backend();
  backendState.shaderTable = table->backend();
  backendState.bindingSets =
      checkBindingSets(call, pipeline->bindingLayout(), state.bindingSets, name);
  backend_->setRayTracingState(backendState);
  boundGraphics_ = nullptr;
  bound_ = Bound::RayTracing;
  boundPushConstantBytes_ = pipeline->bindingLayout().pushConstantBytes;
  boundPipelineName_ = name;
}

void ValidationCommandList::setComputeState(const ComputeState& state) {
  const char* call = "setComputeState";
  requireOutsideRendering(call);
  auto* pipeline = dynamic_cast<ValidationComputePipeline*>(state.pipeline);
  if (!pipeline) fail(call, "command list '{}': no compute pipeline", debugName_);
  const std::string& name = pipeline->debugName();
  ComputeState backendState;
  backendState.pipeline = pipeline->backend();
  backendState.bindingSets =
      checkBindingSets(call, pipeline->bindingLayout(), state.bindingSets, name);
  backend_->setComputeState(backendState);
  boundGraphics_ = nullptr;
  bound_ = Bound::Compute;
  boundPushConstantBytes_ = state.pipeline->bindingLayout().pushConstantBytes;
  boundPipelineName_ = name;
}

void ValidationCommandList::setPushConstants(const void* data, size_t bytes) {
  const char* call = "setPushConstants";
  requireOpen(call);
  if (bound_ == Bound::Nothing) fail(call, "command list '{}': no pipeline is bound", debugName_);
  if (boundPushConstantBytes_ == 0)
    fail(call, "pipeline '{}' declares no push constants", boundPipelineName_);
  if (bytes != boundPushConstantBytes_)
    fail(call, "{} bytes, but pipeline '{}' declares {}", bytes, boundPipelineName_,
         boundPushConstantBytes_);
  if (!data) fail(call, "{} bytes from a null pointer", bytes);
  backend_->setPushConstants(data, bytes);
}

// The state a binding set's item needs for a raster stage to read it (the
// pipeline checked at creation that nothing is written).
static ResourceState readState(ResourceType type) {
  return type == ResourceType::ConstantBuffer ? ResourceState::ConstantBuffer
                                              : ResourceState::ShaderResource;
}

void ValidationCommandList::setGraphicsState(const GraphicsState& state) {
  const char* call = "setGraphicsState";
  requireOpen(call);
  auto* pipeline = dynamic_cast<ValidationGraphicsPipeline*>(state.pipeline);
  if (!pipeline) fail(call, "command list '{}': no graphics pipeline", debugName_);
  const GraphicsPipelineDesc& desc = pipeline->desc();
  const std::string& name = desc.debugName;
  if (!state.vertexBuffer) fail(call, "pipeline '{}': no vertex buffer", name);
  if (!state.indexBuffer) fail(call, "pipeline '{}': no index buffer", name);
  const BufferDesc &v = state.vertexBuffer->desc(), &i = state.indexBuffer->desc();
  if (!hasFlag(v.usage, BufferUsage::VertexBuffer) || v.memory == MemoryLocation::Readback)
    fail(call, "{} lacks BufferUsage::VertexBuffer or is a readback buffer", nameOf(v));
  if (!hasFlag(i.usage, BufferUsage::IndexBuffer) || i.memory == MemoryLocation::Readback)
    fail(call, "{} lacks BufferUsage::IndexBuffer or is a readback buffer", nameOf(i));
  if (state.vertexOffset >= v.byteSize)
    fail(call, "vertex offset {} is past the end of {} ({} bytes)", state.vertexOffset, nameOf(v),
         v.byteSize);
  if (state.indexFormat != Format::R16_UINT && state.indexFormat != Format::R32_UINT)
    fail(call, "indices are R16_UINT or R32_UINT");
  const uint32_t indexBytes = formatByteSize(state.indexFormat);
  if (state.indexOffset % indexBytes != 0 || state.indexOffset > i.byteSize)
    fail(call, "index offset {} of {} is not a multiple of {} bytes inside the buffer",
         state.indexOffset, nameOf(i), indexBytes);
  GraphicsState backendState = state;
  backendState.pipeline = pipeline->backend();
  backendState.bindingSets =
      checkBindingSets(call, pipeline->bindingLayout(), state.bindingSets, name);
  if (renderTarget_) {
    // Inside a pass the backend may record no barrier: everything must be in
    // its state already (a setGraphicsState before beginRendering puts it there).
    if (desc.renderTargetFormat != renderTarget_->desc().format)
      fail(call, "pipeline '{}' draws {} pixels, but {} is another format", name,
           desc.renderTargetFormat == Format::BGRA8_UNORM ? "BGRA8" : "RGBA8",
           nameOf(renderTarget_->desc()));
    auto requireState = [&](ResourceState current, ResourceState wanted, const std::string& what) {
      if (current != wanted)
        fail(call,
             "inside beginRendering, {} is in {} but the draw needs {}; set the state before "
             "beginRendering",
             what, resourceStateName(current), resourceStateName(wanted));
    };
    requireState(state.vertexBuffer->state, ResourceState::VertexInput, nameOf(v));
    requireState(state.indexBuffer->state, ResourceState::VertexInput, nameOf(i));
    for (auto* set : state.bindingSets)
      for (const auto& item : set->desc().items) {
        if (item.type == ResourceType::SampledTexture)
          for (const auto& texture : item.textures)
            requireState(texture->state, ResourceState::ShaderResource, nameOf(texture->desc()));
        else if (item.type == ResourceType::StorageBuffer ||
                 item.type == ResourceType::ConstantBuffer)
          requireState(item.buffer->state, readState(item.type), nameOf(item.buffer->desc()));
        else if (item.type == ResourceType::StorageTexture)
          requireState(item.texture->state, ResourceState::ShaderResource,
                       nameOf(item.texture->desc()));
      }
  }
  backend_->setGraphicsState(backendState);
  bound_ = Bound::Graphics;
  boundGraphics_ = &desc;
  boundIndexBuffer_ = &i;
  boundIndexOffset_ = state.indexOffset;
  boundIndexBytes_ = indexBytes;
  boundPushConstantBytes_ = pipeline->bindingLayout().pushConstantBytes;
  boundPipelineName_ = name;
}

void ValidationCommandList::beginRendering(ITexture* target, const float* clearColor) {
  const char* call = "beginRendering";
  requireOutsideRendering(call);
  if (!target) fail(call, "command list '{}': no render target", debugName_);
  const TextureDesc& d = target->desc();
  if (!hasFlag(d.usage, TextureUsage::RenderTarget))
    fail(call, "{} lacks TextureUsage::RenderTarget", nameOf(d));
  if (d.format != Format::RGBA8_UNORM && d.format != Format::BGRA8_UNORM)
    fail(call, "{}: render targets are RGBA8_UNORM or BGRA8_UNORM", nameOf(d));
  backend_->beginRendering(target, clearColor);
  renderTarget_ = target;
}

void ValidationCommandList::endRendering() {
  const char* call = "endRendering";
  requireInsideRendering(call);
  backend_->endRendering();
  renderTarget_ = nullptr;
}

void ValidationCommandList::setViewport(const Viewport& viewport) {
  const char* call = "setViewport";
  requireInsideRendering(call);
  if (!(viewport.width > 0 && viewport.height > 0))
    fail(call, "a {}x{} viewport; width and height must be positive", viewport.width,
         viewport.height);
  backend_->setViewport(viewport);
}

void ValidationCommandList::setScissor(const ScissorRect& rect) {
  const char* call = "setScissor";
  requireInsideRendering(call);
  const TextureDesc& d = renderTarget_->desc();
  if (rect.x < 0 || rect.y < 0 || uint64_t(rect.x) + rect.width > d.width ||
      uint64_t(rect.y) + rect.height > d.height)
    fail(call, "scissor ({}, {}) {}x{} leaves {} ({}x{})", rect.x, rect.y, rect.width, rect.height,
         nameOf(d), d.width, d.height);
  backend_->setScissor(rect);
}

void ValidationCommandList::drawIndexed(uint32_t indexCount, uint32_t firstIndex,
                                        int32_t vertexOffset) {
  const char* call = "drawIndexed";
  requireInsideRendering(call);
  if (bound_ != Bound::Graphics)
    fail(call, "command list '{}': no setGraphicsState since open or the last other state",
         debugName_);
  if (boundGraphics_->renderTargetFormat != renderTarget_->desc().format)
    fail(call, "pipeline '{}' draws another format than {}", boundPipelineName_,
         nameOf(renderTarget_->desc()));
  // The indices' range is checked; the vertices they name are not (that
  // would mean reading the indices).
  const uint64_t end = boundIndexOffset_ + (uint64_t(firstIndex) + indexCount) * boundIndexBytes_;
  if (end > boundIndexBuffer_->byteSize)
    fail(call, "indices {} .. {} overflow {} ({} bytes from offset {})", firstIndex,
         uint64_t(firstIndex) + indexCount, nameOf(*boundIndexBuffer_), boundIndexBuffer_->byteSize,
         boundIndexOffset_);
  backend_->drawIndexed(indexCount, firstIndex, vertexOffset);
}

void ValidationCommandList::dispatchRays(uint32_t width, uint32_t height, uint32_t depth) {
  const char* call = "dispatchRays";
  requireOutsideRendering(call);
  if (bound_ != Bound::RayTracing)
    fail(call, "command list '{}': no setRayTracingState since open or the last setComputeState",
         debugName_);
  if (uint64_t(width) * height * depth > kMaxRayDispatchInvocations)
    fail(call, "{}x{}x{} rays exceed the APIs' 2^30 per dispatch", width, height, depth);
  backend_->dispatchRays(width, height, depth);
}

void ValidationCommandList::dispatch(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
  const char* call = "dispatch";
  requireOutsideRendering(call);
  if (bound_ != Bound::Compute)
    fail(call, "command list '{}': no setComputeState since open or the last setRayTracingState",
         debugName_);
  if (groupsX > kMaxThreadGroupsPerDimension || groupsY > kMaxThreadGroupsPerDimension ||
      groupsZ > kMaxThreadGroupsPerDimension)
    fail(call, "{}x{}x{} thread groups; each dimension takes at most {}", groupsX, groupsY, groupsZ,
         kMaxThreadGroupsPerDimension);
  backend_->dispatch(groupsX, groupsY, groupsZ);
}

void ValidationCommandList::beginTimerQuery(ITimerQuery* query) {
  const char* call = "beginTimerQuery";
  requireOutsideRendering(call);
  if (!runningQueries_.insert(query).second)
    fail(call, "command list '{}': the query was begun already and not ended", debugName_);
  backend_->beginTimerQuery(query);
}

void ValidationCommandList::endTimerQuery(ITimerQuery* query) {
  const char* call = "endTimerQuery";
  requireOutsideRendering(call);
  if (runningQueries_.erase(query) == 0)
    fail(call, "command list '{}': the query was not begun in this recording", debugName_);
  backend_->endTimerQuery(query);
}

}  // namespace penumbra::rhi::validation
