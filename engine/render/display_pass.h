#pragma once
// The viewer's display pass: the path tracer's HDR accumulation, scaled to
// the window (nearest texel) and tone-mapped into an RGBA8 texture that is
// then copied into the back buffer (display.comp). Recorded into the caller's
// command list, so it rides in the frame that presents it.
#include "render/tone_mapping.h"
#include "rhi/rhi.h"

namespace penumbra::render {

class DisplayPass {
 public:
  explicit DisplayPass(rhi::IDevice& device);
  // `hdr`: RGBA32F storage texture (any size); `target`: RGBA8 storage texture.
  void record(rhi::ICommandList& commandList, const rhi::TextureHandle& hdr,
              const rhi::TextureHandle& target, const ToneMapping& toneMapping);

 private:
  rhi::IDevice& device_;
  rhi::ComputePipelineHandle pipeline_;
  // Rebuilt only when the textures change (resize, scene change).
  rhi::BindingSetHandle bindings_;
  rhi::ITexture* boundHdr_ = nullptr;
  rhi::ITexture* boundTarget_ = nullptr;
};

}  // namespace penumbra::render
