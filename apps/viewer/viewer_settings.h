#pragma once
#include <optional>
#include <string_view>
#include <vector>
// What the viewer's menus and scripts change, and how it maps onto the
// renderer: PathTracerSettings for each frame, the display's tone mapping, and
// the RenderJob recorded beside a screenshot (for `penumbra render --settings`).
#include <string>

#include "penumbra/batch/render_job.h"
#include "penumbra/batch/render_settings.h"
#include "penumbra/render/denoiser.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/render/tone_mapping.h"

namespace penumbra::viewer {

// What the viewer shows: the (denoised) image, or one of the denoiser's
// guide buffers as it is (tone mapped like the image).
enum class ViewBuffer { Image, Albedo, Normal, Depth, Emission, Motion };
const char* viewBufferName(ViewBuffer view);
std::optional<ViewBuffer> parseViewBuffer(std::string_view name);
const std::vector<ViewBuffer>& allViewBuffers();

struct ViewerSettings {
  // The settings table's (batch/render_settings.h); one sample per pixel
  // per frame by default: each frame must stay interactive.
  render::RenderSettings render = defaultRenderSettings();
  float renderScale = 1.0f;
  bool autoRenderScale = true;
  bool vsync = true;
  uint32_t maxSamples = 0;  // accumulation stops here; 0 = never
  bool showUi = true;       // the menus and the stats overlay (F1)
  ViewBuffer view = ViewBuffer::Image;
  // The denoise setting in the viewer: Svgf runs the temporal denoiser while
  // the camera moves, then the a-trous filter on the accumulation once it
  // holds more than the temporal history would; Atrous runs the a-trous
  // filter on the accumulation always.

  static render::RenderSettings defaultRenderSettings() {
    render::RenderSettings s;
    s.sppPerFrame = 1;
    return s;
  }
};

// What a change calls for (a table setting's: its SettingChange).
enum class SettingEffect {
  None,               // display only (exposure, tone curve, vsync, render scale mode)
  ResetAccumulation,  // the image changes: start the running mean again
  RebuildRenderer,    // the pipeline changes (all effects on/off): a new PathTracer
  Resize,             // the render resolution changes
};

// Sets one setting by its script name: a settings-table setting by its
// command-line name ("max-depth", "spp-per-frame", "denoise", ...; on/off for
// flags), or one of the viewer's own: "render-scale", "auto-scale", "vsync",
// "max-samples", "ui", "view". Throws penumbra::Error naming the setting on a
// bad name or value.
SettingEffect applySetting(ViewerSettings& settings, const std::string& name,
                           const std::string& value);
// What changing a table setting calls for in the viewer.
SettingEffect settingEffect(render::SettingChange change);

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
