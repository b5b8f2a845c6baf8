#include "penumbra/render/display_pass.h"

#include "display_shared.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"

namespace penumbra::render {

DisplayPass::DisplayPass(rhi::IDevice& device) : device_(device) {
  rhi::ComputePipelineDesc desc;
  desc.shader = shaders::shaderDesc("display.comp");
  desc.debugName = "display";
  pipeline_ = device_.createComputePipeline(desc);
}

void DisplayPass::record(rhi::ICommandList& commandList, const rhi::TextureHandle& hdr,
                         const rhi::TextureHandle& target, const ToneMapping& toneMapping,
                         DisplayChannels channels) {
  if (target->desc().format != rhi::Format::RGBA8_UNORM)
    throw Error("display pass: the target must be an RGBA8 storage texture");
  if (!bindings_ || boundHdr_ != hdr.get() || boundTarget_ != target.get()) {
    // Frames still in flight read the old set (command lists hold binding
    // sets by pointer): they finish first. The shown texture changes only on
    // a user's action (a view, the denoiser, a resize), so this never stalls
    // a steady stream of frames.
    if (bindings_) device_.waitForIdle();
    rhi::BindingSetDesc set;
    set.debugName = "display bindings";
    set.items = {rhi::BindingSetItem::storageTexture(PENUMBRA_T(TM_T_INPUT), hdr),
                 rhi::BindingSetItem::storageTexture(PENUMBRA_U(TM_U_OUTPUT), target)};
    bindings_ = device_.createBindingSet(set, *pipeline_);
    boundHdr_ = hdr.get();
    boundTarget_ = target.get();
  }
  const gpu::DisplayPush push{hdr->desc().width,    hdr->desc().height,
                              target->desc().width, target->desc().height,
                              toneMapping.exposure, uint32_t(toneMapping.toneOperator),
                              uint32_t(channels)};
  commandList.setComputeState({pipeline_.get(), {bindings_.get()}});
  commandList.setPushConstants(&push, sizeof(push));
  commandList.dispatch((push.targetWidth + 7) / 8, (push.targetHeight + 7) / 8);
}

}  // namespace penumbra::render
