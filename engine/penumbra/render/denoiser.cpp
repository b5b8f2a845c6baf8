#include "penumbra/render/denoiser.h"

#include <fmt/format.h>

#include "denoiser_shared.h"
#include "penumbra/render/image_size.h"
#include "penumbra/util/error.h"
#include "penumbra_shaders.h"

namespace penumbra::render {

Denoiser::Denoiser(rhi::IDevice& device, uint32_t width, uint32_t height)
    : device_(device), width_(width), height_(height) {
  requireValidImageSize("denoiser", width, height);
  rhi::ComputePipelineDesc desc;
  desc.shader = shaders::shaderDesc("denoise.comp");
  desc.debugName = "denoiser";
  pipeline_ = device_.createComputePipeline(desc);
  commandList_ = device_.createCommandList("denoiser");
  timer_ = device_.createTimerQuery();

  rhi::BufferDesc frame;
  frame.byteSize = sizeof(gpu::DenoiseFrame);
  frame.usage = rhi::BufferUsage::StorageBuffer;
  frame.debugName = "denoiser frame";
  frame_ = device_.createBuffer(frame);

  const auto image = [&](const std::string& name) {
    rhi::TextureDesc tex;
    tex.width = width;
    tex.height = height;
    tex.format = rhi::Format::RGBA32_FLOAT;
    tex.usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource;
    tex.debugName = "denoiser " + name;
    return device_.createTexture(tex);
  };
  const struct {
    rhi::TextureHandle* pair;
    const char* name;
  } pairs[] = {
      {illumination_, "illumination"},      {historyIllumination_, "history illumination"},
      {historyMoments_, "history moments"}, {historyNormalDepth_, "history normal and depth"},
      {historyAlbedo_, "history albedo"},   {historyEmission_, "history emission"}};
  for (const auto& p : pairs)
    for (int i = 0; i < 2; ++i) p.pair[i] = image(fmt::format("{} {}", p.name, i));
  output_ = image("output");
  motion_ = image("motion vectors");
  // Defined contents from the start (the viewer can show the motion vectors
  // before a first temporal frame has written them).
  auto* cmd = commandList_.get();
  cmd->open();
  for (const auto& p : pairs)
    for (int i = 0; i < 2; ++i) cmd->clearTextureFloat(p.pair[i].get(), 0.0f, 0.0f, 0.0f, 0.0f);
  cmd->clearTextureFloat(output_.get(), 0.0f, 0.0f, 0.0f, 0.0f);
  cmd->clearTextureFloat(motion_.get(), 0.0f, 0.0f, 0.0f, 0.0f);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
}

Denoiser::~Denoiser() = default;

void Denoiser::createBindings(const PathTracer& tracer) {
  using Item = rhi::BindingSetItem;
  const GuideBuffers& g = tracer.guides();
  for (int parity = 0; parity < 2; ++parity)
    for (int direction = 0; direction < 2; ++direction) {
      rhi::BindingSetDesc set;
      set.debugName = fmt::format("denoiser bindings {}{}", parity, direction);
      set.items = {
          Item::storageTexture(PENUMBRA_T(DN_T_BEAUTY), tracer.accumulation()),
          Item::storageTexture(PENUMBRA_T(DN_T_ALBEDO), g.albedo),
          Item::storageTexture(PENUMBRA_T(DN_T_NORMAL_DEPTH), g.normalDepth),
          Item::storageTexture(PENUMBRA_T(DN_T_EMISSION), g.emission),
          Item::storageTexture(PENUMBRA_T(DN_T_SAMPLE_MOMENTS), g.moments),
          Item::storageTexture(PENUMBRA_T(DN_T_HISTORY_ILLUMINATION), historyIllumination_[parity]),
          Item::storageTexture(PENUMBRA_T(DN_T_HISTORY_MOMENTS), historyMoments_[parity]),
          Item::storageTexture(PENUMBRA_T(DN_T_HISTORY_NORMAL_DEPTH), historyNormalDepth_[parity]),
          Item::storageTexture(PENUMBRA_T(DN_T_ILLUMINATION), illumination_[direction]),
          Item::storageBuffer(PENUMBRA_T(DN_T_FRAME), frame_),
          Item::storageTexture(PENUMBRA_U(DN_U_ILLUMINATION), illumination_[1 - direction]),
          Item::storageTexture(PENUMBRA_U(DN_U_MOMENTS), historyMoments_[1 - parity]),
          Item::storageTexture(PENUMBRA_U(DN_U_HISTORY_ILLUMINATION),
                               historyIllumination_[1 - parity]),
          Item::storageTexture(PENUMBRA_U(DN_U_HISTORY_NORMAL_DEPTH),
                               historyNormalDepth_[1 - parity]),
          Item::storageTexture(PENUMBRA_U(DN_U_OUTPUT), output_),
          Item::storageTexture(PENUMBRA_U(DN_U_MOTION), motion_),
          Item::storageTexture(PENUMBRA_T(DN_T_HISTORY_ALBEDO), historyAlbedo_[parity]),
          Item::storageTexture(PENUMBRA_T(DN_T_HISTORY_EMISSION), historyEmission_[parity]),
          Item::storageTexture(PENUMBRA_U(DN_U_ALBEDO), historyAlbedo_[1 - parity]),
          Item::storageTexture(PENUMBRA_U(DN_U_EMISSION), historyEmission_[1 - parity])};
      bindings_[parity][direction] = device_.createBindingSet(set, *pipeline_);
    }
  boundBeauty_ = tracer.accumulation().get();
}

void Denoiser::dispatch(rhi::ICommandList& cmd, uint32_t pass, uint32_t stepWidth, uint32_t flags,
                        int parity, int direction) {
  // Binding the set again records the barriers between passes (the images
  // one pass writes, the next reads).
  cmd.setComputeState({pipeline_.get(), {bindings_[parity][direction].get()}});
  const gpu::DenoisePush push{pass, stepWidth, flags, 0};
  cmd.setPushConstants(&push, sizeof(push));
  cmd.dispatch((width_ + 7) / 8, (height_ + 7) / 8);
}

void Denoiser::record(rhi::ICommandList& cmd, const PathTracer& tracer, const scene::Camera& camera,
                      uint32_t samples, const DenoiserSettings& settings, rhi::ITimerQuery* timer) {
  if (tracer.width() != width_ || tracer.height() != height_)
    throw Error(fmt::format("denoiser: the image is {}x{}, the denoiser's {}x{}", tracer.width(),
                            tracer.height(), width_, height_));
  if (settings.mode == DenoiseMode::Off)
    throw Error("denoiser: record called with the denoiser off");
  if (!tracer.guidesWritten())
    throw Error(
        "denoiser: the path tracer did not write its guide buffers for every sample of the image "
        "(PathTracerSettings::writeGuides)");
  if (samples == 0) throw Error("denoiser: the image has no samples yet");
  if (settings.iterations > 12) throw Error("denoiser: at most 12 a-trous iterations");
  if (settings.maxHistory < 1) throw Error("denoiser: the history must hold at least 1 frame");
  if (boundBeauty_ != tracer.accumulation().get()) createBindings(tracer);

  const bool temporal = settings.mode == DenoiseMode::Svgf;
  // Reprojection moves the film, it does not resize it: a new field of view,
  // orthographic height or projection starts a new history.
  const bool continues = historyValid_ && sameFilm(previousCamera_, camera);
  gpu::DenoiseFrame f{};
  f.camera = cameraData(camera, width_, height_, tracer.renderOrigin());
  f.previousCamera =
      cameraData(continues ? previousCamera_ : camera, width_, height_, tracer.renderOrigin());
  f.width = width_;
  f.height = height_;
  f.samplesPerPixel = samples;
  f.maxHistory = settings.maxHistory;
  f.depthSigma = settings.depthSigma;
  f.normalExponent = settings.normalExponent;
  f.luminanceSigma = settings.luminanceSigma;
  f.albedoFloor = settings.albedoFloor;
  f.orthographic = camera.orthographic() ? 1u : 0u;
  cmd.writeBuffer(frame_.get(), &f, sizeof(f));

  uint32_t flags = 0;
  if (temporal) flags |= DN_FLAG_TEMPORAL;
  if (temporal && continues) flags |= DN_FLAG_HISTORY_VALID;
  if (settings.fireflyClamp) flags |= DN_FLAG_FIREFLY_CLAMP;

  const int p = parity_;
  if (timer) cmd.beginTimerQuery(timer);
  dispatch(cmd, DN_PASS_TEMPORAL, 0, flags, p, 1);  // -> illumination[0]
  dispatch(cmd, DN_PASS_VARIANCE, 0, flags, p, 0);  // -> illumination[1]
  int current = 1;
  for (uint32_t i = 0; i < settings.iterations; ++i) {
    // SVGF feeds the first iteration back as history: filtered enough to
    // steady the temporal mean, not so much that detail smears over time.
    const uint32_t iterationFlags = flags | (temporal && i == 0 ? DN_FLAG_WRITE_HISTORY : 0u);
    dispatch(cmd, DN_PASS_ATROUS, 1u << i, iterationFlags, p, current);
    current = 1 - current;
  }
  dispatch(cmd, DN_PASS_COMPOSE, 0, flags, p, current);
  if (timer) cmd.endTimerQuery(timer);

  momentsWritten_ = 1 - p;
  if (temporal) {
    // Without a-trous iterations nothing wrote the history illumination:
    // the temporal mean itself is the history then.
    if (settings.iterations == 0)
      cmd.copyTexture(historyIllumination_[1 - p].get(), illumination_[1].get());
    parity_ = 1 - p;
    historyValid_ = true;
    previousCamera_ = camera;
  } else {
    historyValid_ = false;
  }
}

double Denoiser::run(const PathTracer& tracer, const scene::Camera& camera, uint32_t samples,
                     const DenoiserSettings& settings) {
  auto* cmd = commandList_.get();
  cmd->open();
  record(*cmd, tracer, camera, samples, settings, timer_.get());
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  return device_.timerQuerySeconds(timer_.get());
}

}  // namespace penumbra::render
