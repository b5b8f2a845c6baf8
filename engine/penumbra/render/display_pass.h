#pragma once
// The viewer's display pass: the path tracer's HDR accumulation, scaled to
// the window (nearest texel) and tone-mapped into an RGBA8 texture that is
// then copied into the back buffer (display.comp). Recorded into the caller's
// command list, so it rides in the frame that presents it.
#include "penumbra/render/tone_mapping.h"
#include "penumbra/rhi/rhi.h"

namespace penumbra::render {

// Which channels of the texture the display pass shows (the viewer's guide
// buffer views).
enum class DisplayChannels : uint32_t {
  Color = 0,   // rgb
  Signed = 1,  // xyz in [-1, 1] as 0.5 + 0.5 v
  Alpha = 2,   // w as grey
};

class DisplayPass {
 public:
  explicit DisplayPass(rhi::IDevice& device);
  // `hdr`: RGBA32F storage texture (any size); `target`: RGBA8 storage texture.
  void record(rhi::ICommandList& commandList, const rhi::TextureHandle& hdr,
              const rhi::TextureHandle& target, const ToneMapping& toneMapping,
              DisplayChannels channels = DisplayChannels::Color);

 private:
  rhi::IDevice& device_;
  rhi::ComputePipelineHandle pipeline_;
  // Rebuilt only when the textures change (resize, scene change).
  rhi::BindingSetHandle bindings_;
  rhi::ITexture* boundHdr_ = nullptr;
  rhi::ITexture* boundTarget_ = nullptr;
};

}  // namespace penumbra::render
