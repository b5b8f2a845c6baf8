#include "viewer_settings.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "penumbra/util/error.h"

namespace penumbra::viewer {
namespace {

[[noreturn]] void badValue(const std::string& name, const std::string& value,
                           const char* expected) {
  throw Error(fmt::format("setting '{}': '{}' is not {}", name, value, expected));
}

uint32_t parseUint(const std::string& name, const std::string& value, uint32_t lo, uint32_t hi) {
  uint32_t out = 0;
  auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), out);
  if (ec != std::errc() || end != value.data() + value.size() || out < lo || out > hi)
    badValue(name, value, fmt::format("an integer in {}..{}", lo, hi).c_str());
  return out;
}

float parseFloat(const std::string& name, const std::string& value, float lo, float hi) {
  size_t used = 0;
  float out = 0;
  try {
    out = std::stof(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !std::isfinite(out) || out < lo || out > hi)
    badValue(name, value, fmt::format("a number in {}..{}", lo, hi).c_str());
  return out;
}

bool parseBool(const std::string& name, const std::string& value) {
  if (value == "on" || value == "true" || value == "1") return true;
  if (value == "off" || value == "false" || value == "0") return false;
  badValue(name, value, "on or off");
}

template <class T>
SettingEffect assign(T& field, T value, SettingEffect effect) {
  if (field == value) return SettingEffect::None;
  field = value;
  return effect;
}

}  // namespace

SettingEffect settingEffect(render::SettingChange change) {
  switch (change) {
    case render::SettingChange::Image:
      return SettingEffect::ResetAccumulation;
    case render::SettingChange::Pipeline:
      return SettingEffect::RebuildRenderer;
    case render::SettingChange::Display:
      return SettingEffect::None;
  }
  return SettingEffect::None;
}

SettingEffect applySetting(ViewerSettings& s, const std::string& name, const std::string& value) {
  using E = SettingEffect;
  // The table's settings by their command-line names; `guides` follows the
  // denoiser and the view (Viewer::recordFrame), so it is not set by hand.
  const render::Setting* setting = render::findSetting(name);
  if (setting && setting->name == name && setting->commandLine) {
    const auto v = setting->parse(value);
    if (!v) badValue(name, value, setting->expected().c_str());
    if (setting->get(s.render) == *v) return E::None;
    setting->set(s.render, *v);
    return settingEffect(setting->change);
  }
  if (name == "render-scale") {
    // A fixed scale: the automatic one would move it again.
    s.autoRenderScale = false;
    return assign(s.renderScale, parseFloat(name, value, 0.125f, 1.0f), E::Resize);
  }
  if (name == "auto-scale") return assign(s.autoRenderScale, parseBool(name, value), E::None);
  if (name == "vsync") return assign(s.vsync, parseBool(name, value), E::None);
  if (name == "max-samples")
    return assign(s.maxSamples, parseUint(name, value, 0, 1u << 24), E::None);
  if (name == "ui") return assign(s.showUi, parseBool(name, value), E::None);
  if (name == "view") {
    auto v = parseViewBuffer(value);
    if (!v) badValue(name, value, "image, albedo, normal, depth, emission or motion");
    return assign(s.view, *v, E::None);
  }
  throw Error(fmt::format("unknown setting '{}'", name));
}

const std::vector<ViewBuffer>& allViewBuffers() {
  static const std::vector<ViewBuffer> all = {ViewBuffer::Image,    ViewBuffer::Albedo,
                                              ViewBuffer::Normal,   ViewBuffer::Depth,
                                              ViewBuffer::Emission, ViewBuffer::Motion};
  return all;
}

const char* viewBufferName(ViewBuffer view) {
  switch (view) {
    case ViewBuffer::Image:
      return "image";
    case ViewBuffer::Albedo:
      return "albedo";
    case ViewBuffer::Normal:
      return "normal";
    case ViewBuffer::Depth:
      return "depth";
    case ViewBuffer::Emission:
      return "emission";
    case ViewBuffer::Motion:
      return "motion";
  }
  return "?";
}

std::optional<ViewBuffer> parseViewBuffer(std::string_view name) {
  for (ViewBuffer v : allViewBuffers())
    if (name == viewBufferName(v)) return v;
  return std::nullopt;
}

RenderSize renderSize(uint32_t framebufferWidth, uint32_t framebufferHeight, float scale) {
  auto scaled = [&](uint32_t n) { return std::max(1u, uint32_t(std::lround(double(n) * scale))); };
  return {scaled(framebufferWidth), scaled(framebufferHeight)};
}

render::RenderJob makeRenderJob(const ViewerSettings& settings, const std::string& scene,
                                const std::string& vary, const std::string& set,
                                const scene::Camera& camera, RenderSize size,
                                uint32_t accumulatedSamples) {
  render::RenderJob job;
  job.scene = scene;
  job.vary = vary;
  job.set = set;
  job.camera = camera;
  job.width = size.width;
  job.height = size.height;
  job.spp = accumulatedSamples;
  // The same frames in the same order: samples are stratified per frame.
  job.settings = settings.render;
  return job;
}

}  // namespace penumbra::viewer
