#pragma once
// Recording of GPU work. A command list is recorded between open() and
// close(), then handed to IDevice::submit. It keeps every resource it
// references (and its own scratch/staging buffers) alive until the device has
// finished with it.
#include <vector>

#include "penumbra/rhi/pipeline.h"

namespace penumbra::rhi {

// D3D12: ID3D12QueryHeap of type TIMESTAMP (two queries) + resolve buffer.
// Vulkan: VkQueryPool of type TIMESTAMP (two queries).
class ITimerQuery {
 public:
  virtual ~ITimerQuery() = default;
};
using TimerQueryHandle = std::shared_ptr<ITimerQuery>;

struct RayTracingState {
  IRayTracingPipeline* pipeline = nullptr;
  IShaderTable* shaderTable = nullptr;
  std::vector<IBindingSet*> bindingSets;  // index = space
};

struct ComputeState {
  IComputePipeline* pipeline = nullptr;
  std::vector<IBindingSet*> bindingSets;
};

// The raster subset's state (pipeline.h). The vertex buffer holds
// `pipeline->desc().vertexLayout.stride`-byte vertices from vertexOffset on;
// the index buffer R16_UINT or R32_UINT indices from indexOffset on.
struct GraphicsState {
  IGraphicsPipeline* pipeline = nullptr;
  std::vector<IBindingSet*> bindingSets;  // index = space; graphics pipelines only read resources
  IBuffer* vertexBuffer = nullptr;        // BufferUsage::VertexBuffer
  uint64_t vertexOffset = 0;
  IBuffer* indexBuffer = nullptr;  // BufferUsage::IndexBuffer
  uint64_t indexOffset = 0;
  Format indexFormat = Format::R16_UINT;
};

// Pixels, origin at the target's top-left corner.
struct Viewport {
  float x = 0, y = 0, width = 0, height = 0;
};
struct ScissorRect {
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
};

// D3D12: ID3D12GraphicsCommandList4 + allocator. Vulkan: VkCommandBuffer + pool.
class ICommandList {
 public:
  virtual ~ICommandList() = default;

  // D3D12: allocator Reset + list Reset. Vulkan: vkResetCommandPool + vkBeginCommandBuffer.
  virtual void open() = 0;
  // D3D12: Close. Vulkan: vkEndCommandBuffer.
  virtual void close() = 0;

  // Copies CPU data into a buffer through a staging buffer the list owns.
  // D3D12: upload heap + CopyBufferRegion. Vulkan: staging buffer + vkCmdCopyBuffer.
  virtual void writeBuffer(IBuffer* buffer, const void* data, size_t bytes,
                           uint64_t offset = 0) = 0;
  // Copies tightly packed rows (width * texel size bytes each) of every mip
  // level, largest first (`bytes` must be textureByteSize(desc)), into a
  // texture through a staging buffer the list owns; moves the texture to
  // CopyDest first. Move it to ShaderResource before shaders sample it
  // (binding sets do that when bound).
  // D3D12: upload heap + one CopyTextureRegion per level (rows padded to 256 bytes).
  // Vulkan: staging buffer + vkCmdCopyBufferToImage, one region per level.
  virtual void writeTexture(ITexture* texture, const void* data, size_t bytes) = 0;
  // D3D12: CopyBufferRegion. Vulkan: vkCmdCopyBuffer.
  virtual void copyBuffer(IBuffer* dst, uint64_t dstOffset, IBuffer* src, uint64_t srcOffset,
                          uint64_t bytes) = 0;
  // Tightly packed rows (width * texel size). D3D12: CopyTextureRegion with a
  // placed footprint (rows padded to 256 bytes, repacked by the backend).
  // Vulkan: vkCmdCopyImageToBuffer.
  virtual void copyTextureToBuffer(ITexture* src, IBuffer* dst, uint64_t dstOffset = 0) = 0;
  // Copies a whole texture into one of the same size; formats may differ in
  // channel order only (RGBA8 -> a BGRA8 back buffer).
  // D3D12: CopyTextureRegion (same format), else a format error.
  // Vulkan: vkCmdCopyImage for equal formats, vkCmdBlitImage (NEAREST, 1:1) to swizzle.
  virtual void copyTexture(ITexture* dst, ITexture* src) = 0;
  // D3D12: ClearUnorderedAccessViewFloat. Vulkan: vkCmdClearColorImage.
  virtual void clearTextureFloat(ITexture* texture, float r, float g, float b, float a) = 0;
  // D3D12: ClearUnorderedAccessViewUint on a raw view. Vulkan: vkCmdFillBuffer.
  virtual void clearBufferUint(IBuffer* buffer, uint32_t value) = 0;

  // Explicit state changes; a barrier is recorded from the resource's last
  // recorded state. D3D12: ResourceBarrier (transition, or UAV barrier when
  // both states are UnorderedAccess / AccelStructWrite). Vulkan:
  // vkCmdPipelineBarrier with the states' stage and access masks.
  virtual void setBufferState(IBuffer* buffer, ResourceState state) = 0;
  virtual void setTextureState(ITexture* texture, ResourceState state) = 0;
  virtual void setAccelStructState(rt::IAccelStruct* as, ResourceState state) = 0;

  // Builds a bottom level from its desc's geometries (scratch owned by the list).
  // D3D12: BuildRaytracingAccelerationStructure (BOTTOM_LEVEL).
  // Vulkan: vkCmdBuildAccelerationStructuresKHR (BOTTOM_LEVEL).
  virtual void buildBottomLevelAccelStruct(rt::IAccelStruct* as) = 0;
  // Builds a top level over `count` instances (copied to an instance buffer
  // the list owns). The referenced bottom levels must be in AccelStructRead.
  // D3D12: BuildRaytracingAccelerationStructure (TOP_LEVEL, InstanceDescs).
  // Vulkan: vkCmdBuildAccelerationStructuresKHR (TOP_LEVEL, instances data).
  virtual void buildTopLevelAccelStruct(rt::IAccelStruct* as, const rt::InstanceDesc* instances,
                                        uint32_t count) = 0;

  // D3D12: SetPipelineState1 + SetComputeRootSignature + descriptor tables.
  // Vulkan: vkCmdBindPipeline(RAY_TRACING) + vkCmdBindDescriptorSets.
  virtual void setRayTracingState(const RayTracingState& state) = 0;
  // D3D12: SetPipelineState + SetComputeRootSignature + descriptor tables.
  // Vulkan: vkCmdBindPipeline(COMPUTE) + vkCmdBindDescriptorSets.
  virtual void setComputeState(const ComputeState& state) = 0;
  // Applies to the pipeline bound last. D3D12: SetComputeRoot32BitConstants.
  // Vulkan: vkCmdPushConstants.
  virtual void setPushConstants(const void* data, size_t bytes) = 0;
  // Moves the vertex and index buffers to VertexInput and the binding sets'
  // resources to their shader states (the barriers go before the rendering
  // pass, so between beginRendering and endRendering the state may only
  // change pipelines, sets and buffers already in those states).
  // D3D12: SetPipelineState + SetGraphicsRootSignature + descriptor tables +
  // IASetPrimitiveTopology(TRIANGLELIST) + IASetVertexBuffers + IASetIndexBuffer.
  // Vulkan: vkCmdBindPipeline(GRAPHICS) + vkCmdBindDescriptorSets +
  // vkCmdBindVertexBuffers + vkCmdBindIndexBuffer.
  virtual void setGraphicsState(const GraphicsState& state) = 0;
  // Starts drawing into `target` (TextureUsage::RenderTarget, moved to
  // RenderTarget first), keeping its contents, or clearing them to
  // `clearColor` when given; viewport and scissor start as the whole target.
  // No copies, barriers, dispatches or queries until endRendering.
  // D3D12: ResourceBarrier + OMSetRenderTargets (an RTV in the list's own
  // descriptor heap) + ClearRenderTargetView + RSSetViewports + RSSetScissorRects.
  // Vulkan: vkCmdPipelineBarrier + vkCmdBeginRendering (LOAD_OP_LOAD or CLEAR,
  // STORE_OP_STORE) + vkCmdSetViewport + vkCmdSetScissor.
  virtual void beginRendering(ITexture* target, const float* clearColor = nullptr) = 0;
  // D3D12: nothing to record. Vulkan: vkCmdEndRendering.
  virtual void endRendering() = 0;
  // Depth range [0, 1]. D3D12: RSSetViewports. Vulkan: vkCmdSetViewport with
  // y = y + height and a negative height, so clip space is +y up as on D3D12.
  virtual void setViewport(const Viewport& viewport) = 0;
  // D3D12: RSSetScissorRects. Vulkan: vkCmdSetScissor.
  virtual void setScissor(const ScissorRect& rect) = 0;
  // Draws indexCount indices from firstIndex on, each added to vertexOffset.
  // D3D12: DrawIndexedInstanced(indexCount, 1, firstIndex, vertexOffset, 0).
  // Vulkan: vkCmdDrawIndexed(indexCount, 1, firstIndex, vertexOffset, 0).
  virtual void drawIndexed(uint32_t indexCount, uint32_t firstIndex = 0,
                           int32_t vertexOffset = 0) = 0;

  // D3D12: DispatchRays with the shader table's ranges.
  // Vulkan: vkCmdTraceRaysKHR with the shader table's strided regions.
  virtual void dispatchRays(uint32_t width, uint32_t height, uint32_t depth = 1) = 0;
  // D3D12: Dispatch. Vulkan: vkCmdDispatch.
  virtual void dispatch(uint32_t groupsX, uint32_t groupsY = 1, uint32_t groupsZ = 1) = 0;

  // D3D12: EndQuery(TIMESTAMP) + ResolveQueryData. Vulkan: vkCmdResetQueryPool +
  // vkCmdWriteTimestamp (TOP_OF_PIPE / BOTTOM_OF_PIPE).
  virtual void beginTimerQuery(ITimerQuery* query) = 0;
  virtual void endTimerQuery(ITimerQuery* query) = 0;
};
using CommandListHandle = std::shared_ptr<ICommandList>;

}  // namespace penumbra::rhi
