// `penumbra bench`: the cost of the effect-specialized pipeline against the
// full one, measured side by side in one run on one device. Frames alternate
// between the two so clock and thermal drift hit both alike; the figures are
// GPU timestamps around each dispatch.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <numeric>
#include <vector>

#include "backend_factory.h"
#include "commands.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/image/image_compare.h"
#include "penumbra/render/denoiser.h"
#include "penumbra/render/effect_set.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

namespace penumbra::app {
namespace {

struct BenchOptions {
  SceneOptions scene{"cornell-box", "1920x1080"};
  CameraOptions camera;  // --camera, --camera-position, --look-at, --fov, --orthographic
  DeviceOptions device;
  SettingOptions settingOptions;
  render::RenderSettings settings = defaults();  // the table's, as given (settingOptions)
  uint32_t frames = 16;
  // The denoiser's camera path: scene units per frame along the camera's
  // right vector (0: a still camera).
  double cameraPan = 0;
  uint32_t referenceSpp = 256;  // of the converged reference the moving camera's last frame meets

  static render::RenderSettings defaults() {
    render::RenderSettings s;
    s.sppPerFrame = 1;
    return s;
  }
};

// |luminance(p) - luminance(q)| of two RGB(A) pixels (Rec. 709).
double luminanceDifference(const float* p, const float* q) {
  return std::abs(0.2126 * (p[0] - q[0]) + 0.7152 * (p[1] - q[1]) + 0.0722 * (p[2] - q[2]));
}

// Mean over pixels of |luminance(a) - luminance(b)|.
double meanLuminanceChange(const image::Image& a, const image::Image& b) {
  double sum = 0;
  const size_t pixels = a.rgba.size() / 4;
  for (size_t i = 0; i < pixels; ++i) {
    sum += luminanceDifference(&a.rgba[i * 4], &b.rgba[i * 4]);
  }
  return pixels ? sum / double(pixels) : 0.0;
}

// The same, but each pixel against the previous frame where its surface was
// then (the denoiser's motion vectors: previous film position minus this
// one), over the pixels whose history the denoiser kept (history length in
// moments.z > 1): the flicker of what stays in view while the camera moves.
// `count` receives the number of such pixels.
double meanReprojectedChange(const image::Image& now, const image::Image& before,
                             const image::Image& motion, const image::Image& moments,
                             size_t& count) {
  double sum = 0;
  count = 0;
  for (uint32_t y = 0; y < now.height; ++y)
    for (uint32_t x = 0; x < now.width; ++x) {
      if (moments.pixel(x, y)[2] <= 1.0f) continue;
      const float* m = motion.pixel(x, y);
      const double px = std::floor(x + 0.5 + m[0]), py = std::floor(y + 0.5 + m[1]);
      if (!(px >= 0 && py >= 0 && px < now.width && py < now.height)) continue;
      sum += luminanceDifference(now.pixel(x, y), before.pixel(uint32_t(px), uint32_t(py)));
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

// Which pixels show a surface (depth guide > 0) and have a denoiser history
// length in [lo, hi) (a mean over the reprojection's taps: fractional).
// Pixels that see nothing have no history, and nothing to get wrong.
std::vector<bool> historyMask(const image::Image& moments, const image::Image& normalDepth,
                              float lo, float hi) {
  std::vector<bool> mask(size_t(moments.width) * moments.height);
  for (size_t i = 0; i < mask.size(); ++i) {
    const float history = moments.rgba[i * 4 + 2];
    mask[i] = history >= lo && history < hi && normalDepth.rgba[i * 4 + 3] > 0.0f;
  }
  return mask;
}

struct Timings {
  std::vector<double> frameSeconds;
  uint64_t rays = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

std::string joinNames(uint32_t effects) {
  const auto names = render::effectNames(effects);
  if (names.empty()) return "none";
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

// The last frame of the pan against a converged render from its camera
// (an independent seed), by how long the denoiser's history is at each
// pixel: just disoccluded (1 frame), recent (2-4), settled (5 or more).
void benchPanAgainstReference(rhi::IDevice& device, const scene::Scene& scene,
                              render::PathTracer& tracer, const scene::Camera& camera,
                              const render::PathTracerSettings& settings, const BenchOptions& o,
                              const image::Image& lastRaw, const image::Image& lastDenoised,
                              const image::Image& moments) {
  render::PathTracer reference(device, scene, tracer.width(), tracer.height(), {}, camera);
  render::PathTracerSettings converged = settings;
  converged.writeGuides = false;
  converged.seed = 987654321u;
  while (reference.accumulatedSamples() < o.referenceSpp)
    reference.renderFrame(converged, std::min(render::PathTracer::kMaxSamplesPerFrame,
                                              o.referenceSpp - reference.accumulatedSamples()));
  const image::Image truth = reference.readback();
  const image::Image normalDepth = tracer.readback(tracer.guides().normalDepth);
  size_t surfacePixels = 0;
  for (size_t i = 3; i < normalDepth.rgba.size(); i += 4)
    surfacePixels += normalDepth.rgba[i] > 0.0f;
  fmt::print(
      "last frame of the pan against a {} spp reference, the {} pixels with a surface, relative "
      "MSE "
      "raw / denoised:\n",
      o.referenceSpp, surfacePixels);
  const struct {
    const char* label;
    float lo, hi;
  } buckets[] = {{"just disoccluded (history 1)", 0.0f, 1.5f},
                 {"history 2-4 frames", 1.5f, 4.5f},
                 {"history 5+ frames", 4.5f, 1e30f}};
  for (const auto& b : buckets) {
    const std::vector<bool> mask = historyMask(moments, normalDepth, b.lo, b.hi);
    fmt::print("  {:<30} {:>8} pixels: {:.4g} / {:.4g}\n", b.label,
               std::count(mask.begin(), mask.end(), true),
               image::maskedRelativeMse(lastRaw, truth, mask),
               image::maskedRelativeMse(lastDenoised, truth, mask));
  }
}

// The denoiser on the specialized pipeline's frames, each frame its own
// samples (the real-time case; a still camera): the denoiser's GPU time, the
// frame it makes with the path tracer's, and the temporal stability, the
// mean frame-to-frame change of the raw and the denoised image.
void benchDenoiser(rhi::IDevice& device, const scene::Scene& scene, render::PathTracer& tracer,
                   render::PathTracerSettings settings, const BenchOptions& o) {
  render::Denoiser denoiser(device, tracer.width(), tracer.height());
  render::DenoiserSettings d;
  d.mode = o.settings.denoiser.mode;
  d.fireflyClamp = o.settings.denoiser.fireflyClamp;
  std::vector<double> trace, filter;
  image::Image previousRaw, previousDenoised, moments;
  double rawChange = 0, denoisedChange = 0;
  size_t reprojectedPixels = 0;
  settings.writeGuides = true;  // the denoiser reads them
  const scene::Camera start = tracer.camera();
  scene::Camera camera = start;
  const glm::dvec3 right = glm::normalize(
      glm::cross(glm::dvec3(glm::normalize(start.forward)), glm::dvec3(glm::normalize(start.up))));
  uint32_t nextSample = tracer.nextSampleIndex();
  for (uint32_t f = 0; f <= o.frames; ++f) {  // frame 0 warms up
    settings.seed = 1000 + f;
    if (o.cameraPan != 0) {
      camera.position = start.position + right * (o.cameraPan * f);
      tracer.setCamera(camera);
    }
    tracer.startNewMean(nextSample);
    nextSample += o.settings.sppPerFrame;
    const auto stats = tracer.renderFrame(settings, o.settings.sppPerFrame);
    const double seconds = denoiser.run(tracer, camera, o.settings.sppPerFrame, d);
    image::Image raw = tracer.readback(), denoised = tracer.readback(denoiser.output());
    if (f > 0) {
      trace.push_back(stats.gpuSeconds);
      filter.push_back(seconds);
      if (o.cameraPan != 0) {
        const image::Image motion = tracer.readback(denoiser.motion());
        moments = tracer.readback(denoiser.moments());
        size_t pixels = 0;
        rawChange += meanReprojectedChange(raw, previousRaw, motion, moments, pixels);
        denoisedChange +=
            meanReprojectedChange(denoised, previousDenoised, motion, moments, pixels);
        reprojectedPixels += pixels;
      } else {
        rawChange += meanLuminanceChange(raw, previousRaw);
        denoisedChange += meanLuminanceChange(denoised, previousDenoised);
      }
    }
    previousRaw = std::move(raw);
    previousDenoised = std::move(denoised);
  }
  std::vector<double> frame;
  for (size_t i = 0; i < trace.size(); ++i) frame.push_back(trace[i] + filter[i]);
  // Along a pan the host reads four images back between frames, the GPU
  // idles and its clocks may drop: a still camera times the denoiser.
  if (o.cameraPan == 0) {
    fmt::print("denoiser ({}) GPU ms/frame median {:.3f}, mean {:.3f}\n",
               render::denoiseModeName(o.settings.denoiser.mode), median(filter) * 1e3,
               mean(filter) * 1e3);
    fmt::print("path tracing + denoiser GPU ms/frame median {:.3f}\n", median(frame) * 1e3);
  }
  fmt::print(
      "frame-to-frame mean |luminance change|{}: raw {:.4g}, denoised {:.4g} ({:.1f}x steadier)\n",
      o.cameraPan != 0 ? fmt::format(" along the pan, reprojected, over the {:.0f} % of pixels "
                                     "kept in history",
                                     100.0 * double(reprojectedPixels) /
                                         (double(o.frames) * tracer.width() * tracer.height()))
                       : std::string(),
      rawChange / o.frames, denoisedChange / o.frames,
      denoisedChange > 0 ? rawChange / denoisedChange : 0.0);
  if (o.cameraPan == 0 || d.mode != render::DenoiseMode::Svgf) return;
  benchPanAgainstReference(device, scene, tracer, camera, settings, o, previousRaw,
                           previousDenoised, moments);
}

int runBench(const BenchOptions& o, const CLI::App& cmd) {
  auto [width, height] = parseImageSize(o.scene.size);
  // A scene without light is lit as `render` lights it (the default environment).
  const scene::Scene scene = [&] {
    scene::Scene loaded = scene::loadScene(o.scene.scene);
    scene::placeCamera(loaded, o.camera.placement(cmd));
    scene::validateCamera(loaded.camera);
    render::applyEnvironmentChoice(loaded, {});
    return loaded;
  }();
  auto device = backends::createDevice(o.device.backend, o.device.createInfo());
  const auto& adapter = device->adapter();
  fmt::print("device: {} ({}) via {}\n", adapter.name, rhi::adapterTypeName(adapter.type),
             device->backendName());
  fmt::print("scene: {} ({} triangles), {}x{}, {} spp per frame, {} frames each, {} integrator\n",
             scene.name, scene.triangleCount(), width, height, o.settings.sppPerFrame, o.frames,
             render::integratorName(o.settings.tracer.integrator));

  render::PipelineOptions full;
  full.allEffects = true;
  render::PathTracer specialized(*device, scene, width, height);
  render::PathTracer everything(*device, scene, width, height, full);
  render::PathTracerSettings settings = o.settings.tracer;

  // One warm-up frame each (first-dispatch costs), then a fresh mean.
  specialized.renderFrame(settings, o.settings.sppPerFrame);
  everything.renderFrame(settings, o.settings.sppPerFrame);
  specialized.resetAccumulation();
  everything.resetAccumulation();

  Timings tSpecialized, tFull;
  for (uint32_t f = 0; f < o.frames; ++f) {
    settings.seed = f;  // both pipelines trace the same paths frame by frame
    auto a = specialized.renderFrame(settings, o.settings.sppPerFrame);
    auto b = everything.renderFrame(settings, o.settings.sppPerFrame);
    tSpecialized.frameSeconds.push_back(a.gpuSeconds);
    tSpecialized.rays += a.rays;
    tFull.frameSeconds.push_back(b.gpuSeconds);
    tFull.rays += b.rays;
  }

  const auto stats = image::compareImages(specialized.readback(), everything.readback(), 1e-4);
  auto report = [&](const char* label, const render::PathTracer& t, const Timings& timings) {
    const double total =
        std::accumulate(timings.frameSeconds.begin(), timings.frameSeconds.end(), 0.0);
    fmt::print("{:<12} effects [{}]\n", label, joinNames(t.pipelineEffects()));
    fmt::print(
        "{:<12} GPU ms/frame median {:.3f}, mean {:.3f}; {:.2f} Mrays/s; pipeline creation {:.1f} "
        "ms\n",
        "", median(timings.frameSeconds) * 1e3, mean(timings.frameSeconds) * 1e3,
        total > 0 ? double(timings.rays) / total * 1e-6 : 0.0, t.pipelineCreationSeconds() * 1e3);
  };
  const render::AccelStructBuildTimes& builds = specialized.accelStructBuildTimes();
  fmt::print("acceleration structures: BLAS builds {:.3f} ms, TLAS build {:.3f} ms (GPU)\n",
             builds.bottomLevelSeconds * 1e3, builds.topLevelSeconds * 1e3);
  report("specialized", specialized, tSpecialized);
  report("full", everything, tFull);
  fmt::print("full / specialized GPU time (medians): {:.3f}\n",
             median(tFull.frameSeconds) / median(tSpecialized.frameSeconds));
  fmt::print("images: max |difference| {:.3g}, mean {:.3g}, rays traced {} vs {}\n",
             stats.maxAbsoluteDifference, stats.meanAbsoluteDifference, tSpecialized.rays,
             tFull.rays);
  if (o.settings.denoiser.mode != render::DenoiseMode::Off)
    benchDenoiser(*device, scene, specialized, settings, o);
  if (o.device.validation && device->validationMessageCount() > 0) {
    fmt::print(stderr, "error: {} validation message(s)\n", device->validationMessageCount());
    return 1;
  }
  return 0;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand(
      "bench",
      "Time the effect-specialized pipeline against the full one on one scene (GPU timestamps)");
  addSceneOptions(*cmd, o->scene, "Built-in scene name or scene file (.json)");
  addCameraOptions(*cmd, o->camera);
  cmd->add_option("--frames", o->frames, "Timed frames per pipeline")
      ->check(CLI::Range(1u, 100000u))
      ->capture_default_str();
  addDeviceOptions(*cmd, o->device);
  // Bench times both pipelines and writes no image: no --all-effects, no
  // tone mapping.
  o->settingOptions.add(*cmd, BenchOptions::defaults(), [](const render::Setting& s) {
    if (s.change == render::SettingChange::Display) return s.key == "fireflyClamp";
    return s.change != render::SettingChange::Pipeline;
  });
  cmd->add_option("--camera-pan", o->cameraPan,
                  "With --denoise: move the camera this far (scene units) along its right vector "
                  "every frame, and report the flicker of what stays in view and, for svgf, the "
                  "last frame's error where it was just disoccluded (0: a still camera)")
      ->capture_default_str();
  cmd->add_option("--reference-spp", o->referenceSpp,
                  "Samples per pixel of the converged render the panned camera's last frame is "
                  "compared with")
      ->check(CLI::Range(1u, render::kMaxSamplesPerPixel))
      ->capture_default_str();
  return [o, cmd] {
    o->settingOptions.apply(*cmd, o->settings);
    const render::DenoiseMode denoise = o->settings.denoiser.mode;
    if (o->cameraPan != 0 && denoise == render::DenoiseMode::Off)
      throw Error("--camera-pan: the camera path measures the denoiser (--denoise atrous|svgf)");
    if (!std::isfinite(o->cameraPan))
      throw Error("--camera-pan: the step must be a finite number of scene units");
    if (denoise != render::DenoiseMode::Off &&
        o->settings.tracer.integrator != render::Integrator::Path)
      throw Error("--denoise: the denoiser filters the path tracer's image (--integrator path)");
    return runBench(*o, *cmd);
  };
}

}  // namespace penumbra::app
