#include "imgui_renderer.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstring>

#include "imgui_shared.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"

namespace penumbra::viewer {

static_assert(sizeof(ImDrawIdx) == 2, "the index format below is R16_UINT");

ImGuiRenderer::ImGuiRenderer(rhi::IDevice& device, uint32_t framesInFlight) : device_(device) {
  ImGuiIO& io = ImGui::GetIO();
  io.BackendRendererName = "penumbra_rhi";
  // Draw commands may start anywhere in the vertex buffer (large windows
  // pass 64K vertices with 16-bit indices).
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;

  rhi::GraphicsPipelineDesc desc;
  desc.vertexShader = shaders::shaderDesc("imgui.vert");
  desc.pixelShader = shaders::shaderDesc("imgui.frag");
  desc.vertexLayout.stride = sizeof(ImDrawVert);
  desc.vertexLayout.attributes = {
      {0, rhi::Format::RG32_FLOAT, uint32_t(offsetof(ImDrawVert, pos))},
      {1, rhi::Format::RG32_FLOAT, uint32_t(offsetof(ImDrawVert, uv))},
      // IM_COL32 packs R in the lowest byte: bytes R, G, B, A in memory.
      {2, rhi::Format::RGBA8_UNORM, uint32_t(offsetof(ImDrawVert, col))}};
  desc.blend = rhi::BlendMode::AlphaBlend;
  desc.renderTargetFormat = rhi::Format::RGBA8_UNORM;
  desc.debugName = "ImGui";
  pipeline_ = device_.createGraphicsPipeline(desc);

  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  rhi::TextureDesc font;
  font.width = uint32_t(width);
  font.height = uint32_t(height);
  font.format = rhi::Format::RGBA8_UNORM;
  font.usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::CopyDest;
  font.debugName = "ImGui font atlas";
  font_ = device_.createTexture(font);
  auto upload = device_.createCommandList("ImGui font upload");
  upload->open();
  upload->writeTexture(font_.get(), pixels, size_t(width) * height * 4);
  upload->setTextureState(font_.get(), rhi::ResourceState::ShaderResource);
  upload->close();
  device_.submit(upload.get());
  device_.waitForIdle();
  io.Fonts->SetTexID(static_cast<ImTextureID>(font_.get()));

  rhi::SamplerDesc sampler;
  sampler.addressU = sampler.addressV = rhi::AddressMode::ClampToEdge;
  sampler.debugName = "ImGui font sampler";
  sampler_ = device_.createSampler(sampler);
  rhi::BindingSetDesc set;
  set.debugName = "ImGui bindings";
  set.items = {rhi::BindingSetItem::sampledTextures(PENUMBRA_T(IMGUI_T_FONT), {font_}),
               rhi::BindingSetItem::samplers(PENUMBRA_S(IMGUI_S_FONT), {sampler_})};
  bindings_ = device_.createBindingSet(set, *pipeline_);
  frames_.resize(std::max(1u, framesInFlight));
}

ImGuiRenderer::~ImGuiRenderer() {
  device_.waitForIdle();
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->SetTexID(nullptr);
  io.BackendRendererName = nullptr;
}

void ImGuiRenderer::reserve(FrameGeometry& frame, size_t vertexBytes, size_t indexBytes) {
  // Grown by half again, so a window that gains a few widgets does not
  // reallocate every frame. The frame that used these buffers last (this
  // slot, framesInFlight frames ago) has finished: its command list was
  // waited for before this frame's was opened.
  auto grow = [&](rhi::BufferHandle& buffer, size_t bytes, rhi::BufferUsage usage,
                  const char* name) {
    if (buffer && buffer->desc().byteSize >= bytes) return;
    rhi::BufferDesc desc;
    desc.byteSize = std::max<uint64_t>(bytes + bytes / 2, 4096);
    desc.usage = usage;
    desc.memory = rhi::MemoryLocation::Upload;
    desc.debugName = name;
    buffer = device_.createBuffer(desc);
  };
  grow(frame.vertices, vertexBytes, rhi::BufferUsage::VertexBuffer, "ImGui vertices");
  grow(frame.indices, indexBytes, rhi::BufferUsage::IndexBuffer, "ImGui indices");
}

void ImGuiRenderer::render(rhi::ICommandList& commandList, rhi::ITexture& target) {
  const ImDrawData* draw = ImGui::GetDrawData();
  if (!draw || draw->CmdListsCount == 0 || draw->TotalVtxCount == 0) return;
  const auto& d = target.desc();
  if (d.format != rhi::Format::RGBA8_UNORM ||
      !rhi::hasFlag(d.usage, rhi::TextureUsage::RenderTarget))
    throw Error(
        fmt::format("ImGui renderer: '{}' is not an RGBA8_UNORM render target", d.debugName));

  FrameGeometry& frame = frames_[nextFrame_];
  nextFrame_ = (nextFrame_ + 1) % frames_.size();
  reserve(frame, size_t(draw->TotalVtxCount) * sizeof(ImDrawVert),
          size_t(draw->TotalIdxCount) * sizeof(ImDrawIdx));
  auto* vertices = static_cast<ImDrawVert*>(frame.vertices->mappedData());
  auto* indices = static_cast<ImDrawIdx*>(frame.indices->mappedData());
  for (int i = 0; i < draw->CmdListsCount; ++i) {
    const ImDrawList* list = draw->CmdLists[i];
    std::memcpy(vertices, list->VtxBuffer.Data, size_t(list->VtxBuffer.Size) * sizeof(ImDrawVert));
    std::memcpy(indices, list->IdxBuffer.Data, size_t(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
    vertices += list->VtxBuffer.Size;
    indices += list->IdxBuffer.Size;
  }

  // ImGui's coordinates (DisplayPos .. DisplayPos + DisplaySize, y down) to
  // clip space (+y up on every backend).
  const ImVec2 pos = draw->DisplayPos, size = draw->DisplaySize, scale = draw->FramebufferScale;
  const gpu::ImGuiPush push{2.0f / size.x, -2.0f / size.y, -1.0f - pos.x * 2.0f / size.x,
                            1.0f + pos.y * 2.0f / size.y};
  rhi::GraphicsState state;
  state.pipeline = pipeline_.get();
  state.bindingSets = {bindings_.get()};
  state.vertexBuffer = frame.vertices.get();
  state.indexBuffer = frame.indices.get();
  state.indexFormat = rhi::Format::R16_UINT;
  auto bindState = [&] {
    commandList.setGraphicsState(state);
    commandList.setPushConstants(&push, sizeof(push));
  };
  bindState();  // before the pass: the buffers' and font's barriers go here
  commandList.beginRendering(&target);
  commandList.setViewport({0, 0, size.x * scale.x, size.y * scale.y});
  uint32_t vertexBase = 0, indexBase = 0;
  for (int i = 0; i < draw->CmdListsCount; ++i) {
    const ImDrawList* list = draw->CmdLists[i];
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) {
        if (cmd.UserCallback == ImDrawCallback_ResetRenderState)
          bindState();
        else
          cmd.UserCallback(list, &cmd);
        continue;
      }
      if (cmd.TextureId != static_cast<ImTextureID>(font_.get()))
        throw Error("ImGui renderer: a draw names a texture other than the font atlas");
      // The clip rectangle in target pixels, clamped to the target.
      const float x0 = std::clamp((cmd.ClipRect.x - pos.x) * scale.x, 0.0f, float(d.width));
      const float y0 = std::clamp((cmd.ClipRect.y - pos.y) * scale.y, 0.0f, float(d.height));
      const float x1 = std::clamp((cmd.ClipRect.z - pos.x) * scale.x, 0.0f, float(d.width));
      const float y1 = std::clamp((cmd.ClipRect.w - pos.y) * scale.y, 0.0f, float(d.height));
      if (x1 <= x0 || y1 <= y0) continue;
      commandList.setScissor(
          {int32_t(x0), int32_t(y0), uint32_t(x1) - uint32_t(x0), uint32_t(y1) - uint32_t(y0)});
      commandList.drawIndexed(cmd.ElemCount, indexBase + cmd.IdxOffset,
                              int32_t(vertexBase + cmd.VtxOffset));
    }
    vertexBase += uint32_t(list->VtxBuffer.Size);
    indexBase += uint32_t(list->IdxBuffer.Size);
  }
  commandList.endRendering();
}

}  // namespace penumbra::viewer
