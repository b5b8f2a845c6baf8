#pragma once
// Dear ImGui drawn through the RHI's raster subset (rhi/pipeline.h), the
// same on every backend: the font atlas uploaded once with writeTexture,
// each frame's vertices and indices written into upload buffers, one draw
// per ImGui command with its clip rectangle as the scissor. Shaders:
// shaders/stages/imgui.vert and imgui.frag.
#include <memory>
#include <vector>

#include "penumbra/rhi/rhi.h"

namespace penumbra::viewer {

class ImGuiRenderer {
 public:
  // Call after ImGui::CreateContext. Up to `framesInFlight` frames may be
  // recorded before the first of them finishes (each has its own buffers).
  ImGuiRenderer(rhi::IDevice& device, uint32_t framesInFlight);
  ~ImGuiRenderer();
  ImGuiRenderer(const ImGuiRenderer&) = delete;
  ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

  // Draws ImGui::GetDrawData() over `target`, an RGBA8_UNORM texture with
  // RenderTarget usage, keeping what it holds (the tone-mapped image). The
  // same target whether the frame is then presented or read back, so a
  // capture shows exactly what the window does.
  void render(rhi::ICommandList& commandList, rhi::ITexture& target);

 private:
  // One frame's geometry, in upload memory the GPU reads directly.
  struct FrameGeometry {
    rhi::BufferHandle vertices;
    rhi::BufferHandle indices;
  };
  void reserve(FrameGeometry& frame, size_t vertexBytes, size_t indexBytes);

  rhi::IDevice& device_;
  rhi::GraphicsPipelineHandle pipeline_;
  rhi::TextureHandle font_;
  rhi::SamplerHandle sampler_;
  rhi::BindingSetHandle bindings_;
  std::vector<FrameGeometry> frames_;
  size_t nextFrame_ = 0;
};

}  // namespace penumbra::viewer
