#pragma once
// Linear HDR -> 8-bit sRGB on the GPU (compute shader tonemap.comp), for PNG
// output. The viewer's back buffer goes through render/display_pass.h.
#include "penumbra/image/image.h"
#include "penumbra/render/tone_mapping.h"
#include "penumbra/rhi/rhi.h"

namespace penumbra::render {

class Tonemapper {
 public:
  explicit Tonemapper(rhi::IDevice& device);
  // `hdr` is an RGBA32F storage texture; exposure multiplies before the tone curve.
  image::Image8 run(const rhi::TextureHandle& hdr, float exposure,
                    ToneMapOperator toneOperator = ToneMapOperator::Clamp);

 private:
  rhi::IDevice& device_;
  rhi::ComputePipelineHandle pipeline_;
  rhi::CommandListHandle commandList_;
};

}  // namespace penumbra::render
