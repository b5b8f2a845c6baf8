#pragma once
#include <optional>
#include <string_view>
#include <vector>
// What the viewer's menus and scripts change, and how it maps onto the
// renderer: PathTracerSettings for each frame, the display's tone mapping, and
// the RenderJob recorded beside a screenshot (for `penumbra render --settings`).
#include <string>

#include "render/denoiser.h"
#include "render/path_tracer.h"
#include "render/render_job.h"
#include "render/tone_mapping.h"

namespace penumbra::viewer {

// What the viewer shows: the (denoised) image, or one of the denoiser's
// guide buffers as it is (tone mapped like the image).
enum class ViewBuffer { Image, Albedo, Normal, Depth, Emission, Motion };
const char* viewBufferName(ViewBuffer view);
std::optional<ViewBuffer> parseViewBuffer(std::string_view name);
const std::vector<ViewBuffer>& allViewBuffers();

struct ViewerSettings {
  render::PathTracerSettings tracer;
  uint32_t samplesPerFrame = 1;  // low by default: each frame must stay interactive
  render::ToneMapping toneMapping;
  bool allEffects = false;
  float renderScale = 1.0f;
  bool autoRenderScale = true;
  bool vsync = true;
  uint32_t maxSamples = 0;  // accumulation stops here; 0 = never
  bool showUi = true;       // the menus and the stats overlay (F1)
  // Svgf: the temporal denoiser while the camera moves, then the a-trous
  // filter on the accumulation once it holds more than the temporal
  // history would. Atrous: the a-trous filter on the accumulation always.
  render::DenoiseMode denoise = render::DenoiseMode::Off;
  bool fireflyClamp = true;
  ViewBuffer view = ViewBuffer::Image;
};

// What a change calls for.
enum class SettingEffect {
  None,               // display only (exposure, tone curve, vsync, render scale mode)
  ResetAccumulation,  // the image changes: start the running mean again
  RebuildRenderer,    // the pipeline changes (all effects on/off): a new PathTracer
  Resize,             // the render resolution changes
};

// Sets one setting by its script name ("spp-per-frame", "max-depth",
// "integrator", "strategy", "mis-heuristic", "sampler", "russian-roulette", "clamp",
// "seed", "exposure", "tonemap", "all-effects", "render-scale", "auto-scale",
// "vsync", "max-samples", "ui", "denoise", "firefly-clamp", "view"). Throws penumbra::Error naming
// the setting on a bad name or value.
SettingEffect applySetting(ViewerSettings& settings, const std::string& name,
                           const std::string& value);

// The render resolution for a framebuffer of this size at this scale (>= 1x1).
struct RenderSize {
  uint32_t width = 1, height = 1;
};
RenderSize renderSize(uint32_t framebufferWidth, uint32_t framebufferHeight, float scale);

// The job that reproduces the current image: what was rendered so far
// (`accumulatedSamples` at `size`) from `camera` with these settings.
render::RenderJob makeRenderJob(const ViewerSettings& settings, const std::string& scene,
                                const std::string& vary, const std::string& set,
                                const scene::Camera& camera, RenderSize size,
                                uint32_t accumulatedSamples);

}  // namespace penumbra::viewer
