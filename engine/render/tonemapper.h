#pragma once
// Linear HDR -> 8-bit sRGB on the GPU (compute shader tonemap.comp), for PNG
// output and, later, the viewer's back buffer.
#include "image/image.h"
#include "rhi/rhi.h"

namespace penumbra::render {

class Tonemapper {
 public:
  explicit Tonemapper(rhi::IDevice& device);
  // `hdr` is an RGBA32F storage texture; exposure multiplies before encoding.
  image::Image8 run(const rhi::TextureHandle& hdr, float exposure);

 private:
  rhi::IDevice& device_;
  rhi::ComputePipelineHandle pipeline_;
  rhi::CommandListHandle commandList_;
};

}  // namespace penumbra::render
