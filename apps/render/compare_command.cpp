// `penumbra compare a.exr b.exr`: per-pixel statistics of two linear images
// and a false-colour difference image.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "backend_factory.h"
#include "commands.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/image/image_compare.h"
#include "penumbra/image/image_io.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/render/shader_binding_offsets.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

namespace penumbra::app {
namespace {

struct CompareOptions {
  std::string a, b;              // image files
  std::string deviceA, deviceB;  // or BACKEND:INDEX render targets
  SceneOptions scene{"cornell-box", "128x128"};  // with --a/--b
  uint32_t spp = 16;
  SettingOptions settingOptions;  // the path tracer's settings with --a/--b
  render::RenderSettings settings;
  double tolerance = 1e-3;
  double allowedFraction = 0.0;
  double maxBiasSigmas = 0.0;  // 0: no test of the mean difference
  std::string layer;           // an EXR layer (AOV) instead of the beauty image
  std::string diffOut;
};

// Black where equal; blue -> green -> red as |a - b| (max over RGB) grows,
// saturating at `scale`.
image::Image8 falseColourDifference(const image::Image& a, const image::Image& b, double scale) {
  image::Image8 out;
  out.width = a.width;
  out.height = a.height;
  out.rgba.resize(size_t(a.width) * a.height * 4);
  for (size_t i = 0; i < size_t(a.width) * a.height; ++i) {
    double d = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, double(std::abs(a.rgba[i * 4 + c] - b.rgba[i * 4 + c])));
    const double t = scale > 0 ? std::min(d / scale, 1.0) : 0.0;
    const double r = std::clamp(2.0 * t - 1.0, 0.0, 1.0);
    const double g = 1.0 - std::abs(2.0 * t - 1.0);
    const double bl = std::clamp(1.0 - 2.0 * t, 0.0, 1.0) * (d > 0 ? 1.0 : 0.0);
    out.rgba[i * 4 + 0] = uint8_t(r * 255.0 + 0.5);
    out.rgba[i * 4 + 1] = uint8_t(d > 0 ? g * 255.0 + 0.5 : 0.0);
    out.rgba[i * 4 + 2] = uint8_t(bl * 255.0 + 0.5);
    out.rgba[i * 4 + 3] = 255;
  }
  return out;
}

// "vulkan:1" -> ("vulkan", 1); "vulkan" -> ("vulkan", -1 = default device).
std::pair<std::string, int> parseDeviceSpec(const std::string& spec) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) return {spec, -1};
  const std::string index = spec.substr(colon + 1);
  if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos)
    throw Error(fmt::format("compare: '{}' is not BACKEND:INDEX (e.g. vulkan:0)", spec));
  return {spec.substr(0, colon), std::stoi(index)};
}

// The channels "<layer>.*" of a layered EXR (render --aov) as an image: the
// first three in the file's (sorted) order, a single one repeated in R, G, B.
image::Image loadLayer(const std::string& path, const std::string& layer) {
  const image::ExrChannels exr = image::loadExrChannels(path);
  std::vector<const std::vector<float>*> channels;
  for (const auto& [name, values] : exr.channels)
    if (name.size() > layer.size() + 1 && name.compare(0, layer.size() + 1, layer + ".") == 0)
      channels.push_back(&values);
  if (channels.empty() || channels.size() > 4)
    throw Error(
        fmt::format("compare: {} has no layer '{}' (render --aov writes them)", path, layer));
  image::Image out{exr.width, exr.height};
  for (size_t i = 0; i < size_t(exr.width) * exr.height; ++i)
    for (int c = 0; c < 3; ++c)
      out.rgba[i * 4 + c] = (*channels[std::min<size_t>(c, channels.size() - 1)])[i];
  return out;
}

image::Image renderOn(const std::string& spec, const scene::Scene& scene, uint32_t w, uint32_t h,
                      const CompareOptions& o) {
  auto [backend, index] = parseDeviceSpec(spec);
  rhi::DeviceCreateInfo info;
  info.adapterIndex = index;
  info.bindingOffsets = render::kShaderBindingOffsets;
  auto device = backends::createDevice(backend, info);
  fmt::print("{}: {} via {}\n", spec, device->adapter().name, device->backendName());
  std::fflush(stdout);
  return render::renderImage(*device, scene, w, h, o.spp, o.settings.tracer);
}

int runCompare(const CompareOptions& o) {
  if (!o.diffOut.empty()) image::checkWritable(o.diffOut);
  const bool renderMode = !o.deviceA.empty() || !o.deviceB.empty();
  if (renderMode && (o.deviceA.empty() || o.deviceB.empty() || !o.a.empty()))
    throw Error("compare: give two image files, or --a and --b (BACKEND:INDEX) to render both");
  if (!renderMode && (o.a.empty() || o.b.empty()))
    throw Error("compare: give two image files, or --a and --b (BACKEND:INDEX) to render both");
  if (renderMode && !o.layer.empty())
    throw Error("compare: --layer compares image files, not --a/--b renders");
  image::Image a, b;
  std::string nameA = o.a, nameB = o.b;
  if (renderMode) {
    const auto [w, h] = parseImageSize(o.scene.size);
    scene::Scene scene = scene::loadScene(o.scene.scene);
    render::applyEnvironmentChoice(scene, {});  // as `render` lights a scene without light
    fmt::print("scene: {}, {}x{}, {} spp, seed {}\n", scene.name, w, h, o.spp,
               o.settings.tracer.seed);
    a = renderOn(o.deviceA, scene, w, h, o);
    b = renderOn(o.deviceB, scene, w, h, o);
    nameA = o.deviceA;
    nameB = o.deviceB;
  } else if (!o.layer.empty()) {
    a = loadLayer(o.a, o.layer);
    b = loadLayer(o.b, o.layer);
  } else {
    a = image::loadExr(o.a);
    b = image::loadExr(o.b);
  }
  const auto s = image::compareImages(a, b, o.tolerance);
  fmt::print("images: {} vs {} ({}x{})\n", nameA, nameB, a.width, a.height);
  const auto ma = image::meanRgb(a), mb = image::meanRgb(b);
  fmt::print("mean RGB: a ({:.6g}, {:.6g}, {:.6g})  b ({:.6g}, {:.6g}, {:.6g})\n", ma.r, ma.g, ma.b,
             mb.r, mb.g, mb.b);
  fmt::print("mean absolute difference: {:.6g}\n", s.meanAbsoluteDifference);
  fmt::print("max absolute difference: {:.6g}\n", s.maxAbsoluteDifference);
  fmt::print("pixels beyond relative tolerance {:g}: {} ({:.4f}%)\n", o.tolerance,
             s.pixelsBeyondTolerance, s.fractionBeyondTolerance * 100.0);
  fmt::print("PSNR: {:.2f} dB (peak: b's brightest value)\n", s.psnr);
  fmt::print("relative MSE (b as reference): {:.6g}\n", s.relativeMse);
  fmt::print("SSIM: {:.6f}\n", image::ssim(a, b));
  fmt::print(
      "mean difference b - a: ({:.3g}, {:.3g}, {:.3g}), standard error ({:.3g}, {:.3g}, {:.3g})\n",
      s.meanDifference[0], s.meanDifference[1], s.meanDifference[2],
      s.meanDifferenceStandardError[0], s.meanDifferenceStandardError[1],
      s.meanDifferenceStandardError[2]);
  // Below 1e-5 of the mean, a difference is float rounding, whatever its sign.
  const bool biased =
      o.maxBiasSigmas > 0 && image::meanDifferenceIsSystematic(s, o.maxBiasSigmas, 1e-5);
  if (biased)
    fmt::print("the mean difference is systematic: beyond {:g} standard errors\n", o.maxBiasSigmas);
  if (s.nonFiniteA || s.nonFiniteB)
    fmt::print("non-finite pixels: {} in a, {} in b\n", s.nonFiniteA, s.nonFiniteB);
  if (!o.diffOut.empty()) {
    image::savePng(o.diffOut,
                   falseColourDifference(a, b, std::max(s.maxAbsoluteDifference, 1e-12)));
    fmt::print("wrote {} (false colour, red = max difference {:.6g})\n", o.diffOut,
               s.maxAbsoluteDifference);
  }
  const bool within = s.fractionBeyondTolerance <= o.allowedFraction && s.nonFiniteA == 0 &&
                      s.nonFiniteB == 0 && !biased;
  fmt::print("{}\n", within ? "within tolerance" : "NOT within tolerance");
  return within ? 0 : 1;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand(
      "compare",
      "Compare two linear EXR images, or renders on two backends/devices, pixel for pixel");
  auto* compare = cmd;
  compare->add_option("a", o->a, "First image (.exr)")->check(CLI::ExistingFile);
  compare->add_option("b", o->b, "Second image (.exr)")->check(CLI::ExistingFile);
  compare->add_option("--a", o->deviceA,
                      "Render on BACKEND:INDEX (e.g. vulkan:0) instead of reading a file");
  compare->add_option("--b", o->deviceB,
                      "Render on BACKEND:INDEX (e.g. d3d12:0) instead of reading a file");
  addSceneOptions(*compare, o->scene, "Scene to render with --a/--b");
  compare->add_option("--spp", o->spp, "Samples per pixel with --a/--b")
      ->check(CLI::Range(1u, 1u << 16))
      ->capture_default_str();
  // The path tracer's settings, the same on both sides.
  o->settingOptions.add(*compare, o->settings, [](const render::Setting& s) {
    return s.identity && s.change == render::SettingChange::Image && s.key != "sppPerFrame";
  });
  cmd->add_option("--tolerance", o->tolerance,
                  "Relative per-channel tolerance: |a-b| <= tol * max(|a|, |b|, 1e-3)")
      ->capture_default_str();
  cmd->add_option("--allowed-fraction", o->allowedFraction,
                  "Fraction of pixels allowed beyond the tolerance for exit code 0")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option(
         "--max-bias-sigmas", o->maxBiasSigmas,
         "Fail when a channel's mean difference exceeds this many standard errors (and 1e-5 of "
         "its mean): a systematic difference, not paths parted by rounding (0 = off)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option(
      "--layer", o->layer,
      "Compare this layer of two layered EXRs (render --aov: albedo, normal, depth, ...)");
  cmd->add_option("--diff", o->diffOut, "Write a false-colour difference image (.png)");
  return [o, cmd] {
    o->settingOptions.apply(*cmd, o->settings);
    return runCompare(*o);
  };
}

}  // namespace penumbra::app
