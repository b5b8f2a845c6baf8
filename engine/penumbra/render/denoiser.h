#pragma once
// The denoiser: spatio-temporal variance-guided filtering (SVGF family) of a
// path tracer's image with its guide buffers, as compute passes through the
// RHI (shaders/stages/denoise.comp; kernels in shaders/shared/denoiser.hlsli).
//
// Two modes:
//  - Svgf (temporal): each frame holds only its own samples (the caller
//    resets the tracer's accumulation every frame); the denoiser reprojects
//    its history with the camera motion, integrates illumination and its
//    moments over a capped history, then filters spatially. For moving
//    cameras (the viewer).
//  - Atrous (single frame): the same spatial filter on the tracer's running
//    mean, guided by the per-pixel variance of the mean of its samples. For
//    headless renders; the filter fades out as the sample count grows.
#include <cstdint>
#include <optional>
#include <string_view>

#include "penumbra/render/path_tracer.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// Names: the denoise setting's choices (batch/render_settings.h).
enum class DenoiseMode { Off, Atrous, Svgf };

struct DenoiserSettings {
  DenoiseMode mode = DenoiseMode::Atrous;
  uint32_t iterations = 5;   // a-trous iterations: 5 reach 2^5 + ... = 62 pixels out
  // Clamp a pixel brighter than all 8 neighbours to the brightest. Off by
  // default: the light of the spikes it clamps is gone (a 1 spp Cornell box
  // lost 9 % of its light, docs/results.md "The denoiser keeps the light").
  bool fireflyClamp = false;
  // Svgf: frames of history at most (then an exponential mean, alpha 1/32).
  uint32_t maxHistory = 32;
  // Edge stopping; 0 turns a test off (to measure what each one does).
  float depthSigma = 1.0f;        // scale on the depth gradient (SVGF's sigma_z)
  float normalExponent = 128.0f;  // (n . n_q)^exponent (SVGF's sigma_n)
  float luminanceSigma = 4.0f;    // luminance difference in standard deviations (SVGF's sigma_l)
  float albedoFloor = 1e-3f;      // demodulation never divides by less
};

class Denoiser {
 public:
  Denoiser(rhi::IDevice& device, uint32_t width, uint32_t height);
  ~Denoiser();
  Denoiser(const Denoiser&) = delete;
  Denoiser& operator=(const Denoiser&) = delete;

  // Records the passes that denoise `tracer`'s current image (its
  // accumulation and guide buffers, `samples` samples per pixel behind them)
  // seen from `camera` into `cmd`, timed by `timer` if given. Svgf: the
  // history is that of the last call, unless resetHistory() came between.
  void record(rhi::ICommandList& cmd, const PathTracer& tracer, const scene::Camera& camera,
              uint32_t samples, const DenoiserSettings& settings,
              rhi::ITimerQuery* timer = nullptr);
  // Records, submits and waits; returns the passes' GPU seconds.
  double run(const PathTracer& tracer, const scene::Camera& camera, uint32_t samples,
             const DenoiserSettings& settings);
  // The next Svgf frame starts without history (a scene or image change).
  void resetHistory() { historyValid_ = false; }

  const rhi::TextureHandle& output() const { return output_; }
  // Screen-space motion of the last frame: xy = previous film position minus
  // this one, in pixels (written by both modes; zero where no surface).
  const rhi::TextureHandle& motion() const { return motion_; }
  // The last frame's integrated moments: x, y the illumination luminance's
  // first two moments, z the history length in frames (1: no history, a
  // disocclusion or a single frame), w the samples behind the pixel.
  const rhi::TextureHandle& moments() const { return historyMoments_[momentsWritten_]; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  void createBindings(const PathTracer& tracer);
  void dispatch(rhi::ICommandList& cmd, uint32_t pass, uint32_t stepWidth, uint32_t flags,
                int parity, int direction);

  rhi::IDevice& device_;
  uint32_t width_, height_;
  rhi::ComputePipelineHandle pipeline_;
  rhi::CommandListHandle commandList_;
  rhi::TimerQueryHandle timer_;
  rhi::BufferHandle frame_;  // DenoiseFrame
  rhi::TextureHandle illumination_[2], historyIllumination_[2], historyMoments_[2],
      historyNormalDepth_[2];
  rhi::TextureHandle historyAlbedo_[2], historyEmission_[2];
  rhi::TextureHandle output_, motion_;
  // [parity][direction]: history read from `parity`, written to the other;
  // illumination read from `direction`, written to the other.
  rhi::BindingSetHandle bindings_[2][2];
  const rhi::ITexture* boundBeauty_ = nullptr;  // the tracer images the sets hold
  int parity_ = 0;
  int momentsWritten_ = 0;
  bool historyValid_ = false;
  scene::Camera previousCamera_;
};

}  // namespace penumbra::render
