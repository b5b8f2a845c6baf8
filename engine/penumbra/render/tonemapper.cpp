#include "penumbra/render/tonemapper.h"

#include <cstring>

#include "display_shared.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"

namespace penumbra::render {

Tonemapper::Tonemapper(rhi::IDevice& device) : device_(device) {
  rhi::ComputePipelineDesc desc;
  desc.shader = shaders::shaderDesc("tonemap.comp");
  desc.debugName = "tonemap";
  pipeline_ = device_.createComputePipeline(desc);
  commandList_ = device_.createCommandList("tone map");
}

image::Image8 Tonemapper::run(const rhi::TextureHandle& hdr, float exposure,
                              ToneMapOperator toneOperator) {
  const uint32_t w = hdr->desc().width, h = hdr->desc().height;
  rhi::BufferDesc out;
  out.byteSize = uint64_t(w) * h * 4;
  out.usage = rhi::BufferUsage::StorageBuffer;
  out.debugName = "tonemapped";
  auto pixels = device_.createBuffer(out);
  out.usage = rhi::BufferUsage::CopyDest;
  out.memory = rhi::MemoryLocation::Readback;
  out.debugName = "tonemapped readback";
  auto readback = device_.createBuffer(out);

  rhi::BindingSetDesc set;
  set.debugName = "tonemap bindings";
  set.items = {rhi::BindingSetItem::storageTexture(PENUMBRA_T(TM_T_INPUT), hdr),
               rhi::BindingSetItem::storageBuffer(PENUMBRA_U(TM_U_OUTPUT), pixels)};
  auto bindings = device_.createBindingSet(set, *pipeline_);

  const gpu::TonemapPush push{w, h, exposure, uint32_t(toneOperator)};
  auto* cmd = commandList_.get();
  cmd->open();
  cmd->setComputeState({pipeline_.get(), {bindings.get()}});
  cmd->setPushConstants(&push, sizeof(push));
  cmd->dispatch((w + 7) / 8, (h + 7) / 8);
  cmd->copyBuffer(readback.get(), 0, pixels.get(), 0, out.byteSize);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();

  image::Image8 img;
  img.width = w;
  img.height = h;
  img.rgba.resize(out.byteSize);
  std::memcpy(img.rgba.data(), readback->mappedData(), out.byteSize);
  return img;
}

}  // namespace penumbra::render
