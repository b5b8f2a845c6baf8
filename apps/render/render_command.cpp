#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <regex>
#include <tuple>

#include "backend_factory.h"
#include "cli_options.h"
#include "commands.h"
#include "penumbra/batch/partial_render.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/batch/render_loop.h"
#include "penumbra/batch/render_output.h"
#include "penumbra/batch/sample_split.h"
#include "penumbra/image/image_io.h"
#include "penumbra/render/denoiser.h"
#include "penumbra/render/effect_set.h"
#include "penumbra/render/gpu_scene.h"
#include "penumbra/render/image_size.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/scene/material_row.h"
#include "penumbra/scene/scene_hash.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"
#include "penumbra_commit.h"
#include "progress.h"

namespace penumbra::app {
namespace {

struct RenderOptions {
  SceneOptions scene;
  DeviceOptions device;
  SettingOptions settings;  // --max-depth, --strategy, ... (batch/render_settings.h)
  CameraOptions camera;     // --camera, --camera-position, --look-at, --fov
  AnimationOptions animation;  // --animation, --time
  uint32_t spp = 64;
  std::string out = "render.png";
  float aperture = 0.0f;
  float fNumber = 0.0f;
  float focusDistance = 1.0f;
  uint32_t apertureBlades = 0;
  EnvironmentOptions environment;
  std::string vary;
  std::string set;
  std::string variant;
  bool allowExternalFiles = false;
  bool printEffects = false;
  std::string settingsFile;
  std::string aov;
  std::string samples;  // "A:B": a piece of a split render
  uint32_t totalSpp = 0;
  bool checkOnly = false;  // everything but rendering (`penumbra farm` before it submits)
};

// The auxiliary outputs --aov can write as EXR layers.
const std::vector<std::string> kAovNames = {"albedo",   "normal", "depth",
                                            "emission", "motion", "variance"};

std::vector<std::string> parseAovs(const std::string& list, const std::string& out) {
  std::vector<std::string> aovs;
  if (list.empty()) return aovs;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    if (std::find(kAovNames.begin(), kAovNames.end(), name) == kAovNames.end())
      throw Error(fmt::format(
          "--aov '{}': unknown output '{}' (albedo, normal, depth, emission, motion, variance)",
          list, name));
    if (std::find(aovs.begin(), aovs.end(), name) == aovs.end()) aovs.push_back(name);
    start = comma + 1;
  }
  if (image::formatFromPath(out) != image::FileFormat::Exr)
    throw Error(
        fmt::format("--aov: '{}' is not an .exr file; auxiliary outputs are EXR layers", out));
  return aovs;
}

// The layers --aov asks for, from the tracer's guide buffers (running means
// over all samples) and the denoiser's motion vectors (zero without it: one
// camera, nothing moves).
std::vector<image::ExrLayer> aovLayers(const std::vector<std::string>& aovs,
                                       render::PathTracer& tracer, const render::Denoiser* denoiser,
                                       uint32_t samples) {
  std::vector<image::ExrLayer> layers;
  const auto& g = tracer.guides();
  for (const auto& name : aovs) {
    image::ExrLayer layer;
    layer.name = name;
    if (name == "albedo" || name == "emission") {
      layer.channels = {"R", "G", "B"};
      layer.image = tracer.readback(name == "albedo" ? g.albedo : g.emission);
    } else if (name == "normal" || name == "depth") {
      image::Image nd = tracer.readback(g.normalDepth);
      layer.image = nd;
      if (name == "normal") {
        layer.channels = {"X", "Y", "Z"};
        for (size_t i = 0; i < nd.rgba.size(); i += 4) {
          const float* n = &nd.rgba[i];
          const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
          for (int k = 0; k < 3; ++k) layer.image.rgba[i + k] = len > 0.0f ? n[k] / len : 0.0f;
        }
      } else {
        layer.channels = {"Z"};
        for (size_t i = 0; i < nd.rgba.size(); i += 4) layer.image.rgba[i] = nd.rgba[i + 3];
      }
    } else if (name == "motion") {
      layer.channels = {"X", "Y"};
      layer.image = denoiser ? tracer.readback(denoiser->motion())
                             : image::Image(tracer.width(), tracer.height());
    } else {  // variance of the pixel's mean luminance (radiance minus emission)
      layer.channels = {"Y"};
      image::Image m = tracer.readback(g.moments);
      layer.image = image::Image(tracer.width(), tracer.height());
      for (size_t i = 0; i < m.rgba.size(); i += 4)
        layer.image.rgba[i] =
            std::max(0.0f, m.rgba[i + 1] - m.rgba[i] * m.rgba[i]) / float(samples);
    }
    layers.push_back(std::move(layer));
  }
  return layers;
}

}  // namespace

namespace {

// The job the options describe: a --settings file (a viewer screenshot's
// record) with the options given explicitly on top, or the options alone.
render::RenderJob makeJob(const RenderOptions& o, const CLI::App& cmd) {
  const bool fromFile = !o.settingsFile.empty();
  render::RenderJob job = fromFile ? render::loadRenderJob(o.settingsFile) : render::RenderJob{};
  auto given = [&](const char* flag) { return !fromFile || cmd.count(flag) > 0; };
  if (given("--scene")) job.scene = o.scene.scene;
  if (given("--vary")) job.vary = o.vary;
  if (given("--set")) job.set = o.set;
  if (given("--variant")) job.variant = o.variant;
  o.animation.apply(cmd, job.animation);
  if (given("--size")) std::tie(job.width, job.height) = parseImageSize(o.scene.size);
  if (given("--spp")) job.spp = o.spp;
  o.settings.apply(cmd, job.settings);
  // The environment options only where given: what they leave out stays
  // the record's (or the scene's). A new map starts from its own defaults,
  // as the viewer's does.
  o.environment.apply(cmd, job.environment);
  // A scene camera named on the command line wins over the record's camera;
  // a position, look-at point, field of view or orthographic height changes
  // the record's.
  if (fromFile && cmd.count("--camera") > 0) job.camera.reset();
  return job;
}

// The scene the job renders: loaded, the camera named on the command line
// chosen and given its lens options, the material row, the viewer's
// material edits and the environment applied.
scene::Scene loadJobScene(const RenderOptions& o, const CLI::App& cmd, render::RenderJob& job) {
  scene::Scene scene = scene::loadScene(job.scene, {o.allowExternalFiles}, {}, job.animation);
  // The view and the thin lens given on the command line, on whichever
  // camera renders (a record's, or the scene's after --camera picked one).
  const scene::CameraPlacement placement = o.camera.placement(cmd);
  scene::placeCamera(scene, placement);
  if (job.camera) scene::placeCamera(*job.camera, placement);
  const scene::Camera* rendering = job.camera ? &*job.camera : &scene.camera;
  for (scene::Camera* c : {&scene.camera, job.camera ? &*job.camera : nullptr}) {
    if (!c) continue;
    if (cmd.count("--aperture") > 0) c->apertureRadius = o.aperture;
    // An f-number needs a focal length; only the camera that renders must
    // have one (an orthographic scene camera behind a record's keeps its lens).
    if (cmd.count("--f-number") > 0 && !c->orthographic())
      c->apertureRadius = scene::apertureRadiusForFNumber(o.fNumber, c->verticalFovDegrees);
    else if (cmd.count("--f-number") > 0 && c == rendering)
      throw Error(
          "camera: --f-number needs a focal length, which an orthographic camera has "
          "not; give --aperture");
    if (cmd.count("--focus-distance") > 0) c->focusDistance = o.focusDistance;
    if (cmd.count("--aperture-blades") > 0) c->apertureBlades = o.apertureBlades;
    scene::validateCamera(*c);
  }
  if (!job.variant.empty()) scene::selectMaterialVariant(scene, job.variant);
  if (!job.vary.empty() || !job.set.empty()) scene::changeMaterialRow(scene, job.vary, job.set);
  // The viewer's Material-menu edits, on top of the row as the viewer had it.
  render::applyMaterialOverrides(scene, job.materials, o.settingsFile);
  render::applyEnvironmentChoice(scene, job.environment);
  return scene;
}

// A piece of a split render (--samples A:B --total-spp N).
struct Piece {
  render::SampleTree tree;
  render::SampleRange range;
  render::SplitRenderIdentity identity;  // the device-independent part of what it renders
};

// The piece the options ask for, if any, checked against the whole render
// before any device is made; sets job.spp to the whole render's.
std::optional<Piece> planPiece(const RenderOptions& o, const CLI::App& cmd, render::RenderJob& job,
                               const scene::Scene& scene, bool aovs) {
  if (o.samples.empty() && cmd.count("--total-spp") == 0) return std::nullopt;
  if (o.samples.empty() || cmd.count("--total-spp") == 0)
    throw Error(
        "--samples A:B and --total-spp N go together (samples A to B-1 of an N-sample "
        "render)");
  if (cmd.count("--spp") > 0 && o.spp != o.totalSpp)
    throw Error(
        fmt::format("--spp {} and --total-spp {}: a piece renders --samples of the "
                    "--total-spp render; give --total-spp only",
                    o.spp, o.totalSpp));
  if (job.settings.denoiser.mode != render::DenoiseMode::Off || aovs)
    throw Error(
        "--samples: a piece holds sums of samples only; --denoise and --aov apply to "
        "whole images");
  if (image::formatFromPath(o.out) != image::FileFormat::Exr)
    throw Error(
        fmt::format("--samples: the piece '{}' must be an .exr file (`penumbra merge` "
                    "makes the final image)",
                    o.out));
  job.spp = o.totalSpp;
  render::SampleTree tree(o.totalSpp, job.settings.sppPerFrame);
  const render::SampleRange range = render::parseSampleRange(o.samples, "--samples");
  tree.checkRange(range, "--samples");
  const scene::Camera rendered = job.camera ? *job.camera : scene.camera;
  const render::SplitRenderIdentity identity{
      scene::contentHash(scene),
      render::splitSettingsHash(job.settings, rendered, job.width, job.height),
      job.width,
      job.height,
      job.settings.tracer.seed,
      job.spp,
      job.settings.sppPerFrame,
      PENUMBRA_COMMIT};
  return Piece{std::move(tree), range, identity};
}

// Fails the run when the validation layer spoke (--validation).
int validationStatus(const RenderOptions& o, rhi::IDevice& device, const char* what) {
  if (!o.device.validation || device.validationMessageCount() == 0) return 0;
  fmt::print(stderr, "error: {} validation message(s){}\n", device.validationMessageCount(), what);
  return 1;
}

int renderPiece(const RenderOptions& o, rhi::IDevice& device, render::PathTracer& tracer,
                const render::PathTracerSettings& settings, const Piece& plan,
                const render::RenderJob& job, const scene::Scene& scene) {
  Progress progress(plan.range.count());
  render::FrameStats stats;
  render::PartialRender piece;
  piece.sums = render::renderSampleRange(
      tracer, settings, plan.tree, plan.range, [&](uint32_t done) { progress.update(done); },
      &stats);
  progress.finish();
  // A piece rendered with validation messages is not written: a rerun of
  // the farm would take it as done.
  if (int status = validationStatus(o, device, "; the piece is not written")) return status;
  piece.identity = plan.identity;
  piece.sceneName = scene.name;
  piece.toneMapping = job.settings.toneMapping;
  piece.range = plan.range;
  // The driver too: two drivers of one GPU may round differently.
  const auto& adapter = device.adapter();
  piece.device =
      fmt::format("{} ({}, driver {})", adapter.name, device.backendName(), adapter.driver);
  render::savePartialRender(o.out, piece);
  fmt::print("GPU time: {:.3f} ms for samples {} of {}\n", stats.gpuSeconds * 1e3,
             render::formatSampleRange(plan.range), job.spp);
  fmt::print("wrote {} (a piece: `penumbra merge` combines the pieces)\n", o.out);
  return 0;
}

int renderWhole(const RenderOptions& o, rhi::IDevice& device, render::PathTracer& tracer,
                const render::PathTracerSettings& settings, const render::RenderJob& job,
                const std::vector<std::string>& aovs) {
  const render::DenoiserSettings& denoise = job.settings.denoiser;
  std::unique_ptr<render::Denoiser> denoiser;
  if (denoise.mode != render::DenoiseMode::Off)
    denoiser = std::make_unique<render::Denoiser>(device, job.width, job.height);
  Progress progress(job.spp);
  const render::RenderLoopResult loop = render::renderSamples(
      tracer, denoiser.get(), settings, denoise, job.spp, job.settings.sppPerFrame,
      [&](uint32_t done) { progress.update(done); });
  progress.finish();
  const rhi::TextureHandle& result = denoiser ? denoiser->output() : tracer.accumulation();
  std::vector<image::ExrLayer> layers;
  if (image::formatFromPath(o.out) == image::FileFormat::Exr) {
    layers = aovLayers(aovs, tracer, denoiser.get(), std::max(1u, tracer.accumulatedSamples()));
    if (denoiser && !aovs.empty()) layers.push_back({"noisy", {"R", "G", "B"}, tracer.readback()});
  }
  render::saveRender(tracer, result, o.out, job.settings.toneMapping, layers);
  fmt::print("GPU time: {:.3f} ms total, {:.3f} ms per sample per pixel of the whole image\n",
             loop.gpuSeconds * 1e3, loop.gpuSeconds * 1e3 / job.spp);
  if (denoiser)
    fmt::print("denoiser ({}): {:.3f} ms GPU time\n", render::denoiseModeName(denoise.mode),
               loop.denoiseSeconds * 1e3);
  fmt::print("rays: {} ({:.2f} Mrays/s)\n", loop.rays,
             loop.gpuSeconds > 0 ? loop.rays / loop.gpuSeconds * 1e-6 : 0.0);
  fmt::print("wrote {}\n", o.out);
  return validationStatus(o, device, "");
}

// Parse, check, hand over, report: everything that can fail on bad input
// fails before any device is made.
int renderScene(const RenderOptions& o, const CLI::App& cmd, render::RenderJob& job,
                const scene::Scene& scene);

// Out of memory is a property of the scene and the machine: said in one
// line with what the scene needs, not as an internal error.
int runRender(const RenderOptions& o, const CLI::App& cmd) {
  render::RenderJob job = makeJob(o, cmd);
  std::optional<scene::Scene> scene;
  try {
    scene = loadJobScene(o, cmd, job);
  } catch (const std::bad_alloc&) {
    throw Error(fmt::format("scene '{}': out of memory while loading it", job.scene));
  }
  try {
    return renderScene(o, cmd, job, *scene);
  } catch (const std::bad_alloc&) {
    const double gib = double(1ull << 30);
    throw Error(fmt::format(
        "scene '{}': out of memory rendering it at {}x{}; its {} triangles need {:.1f} GiB of "
        "vertex and index data to upload (held on the host and again on the device) and {:.1f} "
        "GiB as loaded, before acceleration structures and the image's buffers",
        scene->name, job.width, job.height, scene->triangleCount(),
        double(render::GpuScene::uploadBytes(*scene)) / gib, double(scene->meshBytes()) / gib));
  }
}

int renderScene(const RenderOptions& o, const CLI::App& cmd, render::RenderJob& job,
                const scene::Scene& scene) {
  if (o.printEffects) {
    for (const auto& name : render::effectNames(render::deriveEffects(scene, job.camera)))
      fmt::print("{}\n", name);
    for (const auto& name : render::featureNames(render::deriveFeatures(scene, job.camera)))
      fmt::print("{} (branch)\n", name);
    return 0;
  }
  const std::vector<std::string> aovs = parseAovs(o.aov, o.out);
  const std::optional<Piece> piece = planPiece(o, cmd, job, scene, !aovs.empty());
  if (job.settings.denoiser.mode != render::DenoiseMode::Off &&
      job.settings.tracer.integrator != render::Integrator::Path)
    throw Error("--denoise: the denoiser filters the path tracer's image (--integrator path)");
  image::checkWritable(o.out);
  if (o.checkOnly) {
    if (piece)
      fmt::print("identity: {} {} {}\n", piece->identity.sceneHash, piece->identity.settingsHash,
                 piece->identity.build);
    fmt::print("checked: nothing refused\n");
    return 0;
  }

  auto device = backends::createDevice(o.device.backend, o.device.createInfo());
  const auto& adapter = device->adapter();
  fmt::print("device: {} ({}, {}) via {}\n", adapter.name, rhi::adapterTypeName(adapter.type),
             adapter.apiVersion, device->backendName());
  fmt::print("scene: {} ({} triangles, {} implicit objects), {}x{}, {} spp, seed {}\n", scene.name,
             scene.triangleCount(), scene.implicits.size(), job.width, job.height, job.spp,
             job.settings.tracer.seed);
  if (job.settings.tracer.radianceClamp > 0.0f)
    fmt::print("radiance clamp: {} per sample (biased: energy above it is discarded)\n",
               job.settings.tracer.radianceClamp);
  std::fflush(stdout);  // before the progress lines on stderr

  render::PipelineOptions pipeline;
  pipeline.allEffects = job.settings.allEffects;
  render::PathTracer tracer(*device, scene, job.width, job.height, pipeline, job.camera);
  std::string effects;
  for (const auto& name : render::effectNames(tracer.pipelineEffects()))
    effects += (effects.empty() ? "" : ", ") + name;
  fmt::print("pipeline effects: {}{}\n", effects.empty() ? "none" : effects,
             job.settings.allEffects ? " (--all-effects)" : "");
  // The guide buffers are what the denoiser and the AOVs read; a record of
  // frames that wrote them (a viewer screenshot taken while denoising) asks
  // for them too, to render those frames again exactly.
  render::PathTracerSettings settings = render::frameSettings(job.settings);
  if (!aovs.empty()) settings.writeGuides = true;
  return piece ? renderPiece(o, *device, tracer, settings, *piece, job, scene)
               : renderWhole(o, *device, tracer, settings, job, aovs);
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd =
      app.add_subcommand("render", "Path-trace a scene to an image (.exr linear, .png sRGB)");
  addSceneOptions(*cmd, o->scene,
                  "Built-in scene name, scene file (.json) or glTF file (.gltf, .glb)");
  addCameraOptions(*cmd, o->camera);
  cmd->add_option("--aperture", o->aperture,
                  "Thin-lens aperture radius in metres (0: pinhole, everything sharp)")
      ->check(CLI::Range(0.0f, 1000.0f));
  cmd->add_option("--f-number", o->fNumber,
                  "Thin-lens aperture as an f-number on a 35 mm camera at the view's field of "
                  "view (instead of --aperture)")
      ->check(CLI::Range(0.5f, 1000.0f))
      ->excludes("--aperture");
  cmd->add_option(
         "--aperture-blades", o->apertureBlades,
         "Aperture blades: 0 round, 3..32 a polygon (the shape of out-of-focus highlights)")
      ->check(CLI::Range(0u, 32u));
  addEnvironmentOptions(*cmd, o->environment);
  cmd->add_option("--variant", o->variant,
                  "Draw the glTF file's material variant of this name, or index (0 is the first; "
                  "KHR_materials_variants; default: the file's own materials)");
  addAnimationOptions(*cmd, o->animation);
  cmd->add_option("--focus-distance", o->focusDistance,
                  "Distance in metres along the view to the plane in focus (with --aperture)")
      ->check(CLI::Range(1e-6f, 1e9f));
  cmd->add_option("--spp", o->spp, "Samples per pixel")
      ->check(CLI::Range(1u, render::kMaxSamplesPerPixel))
      ->capture_default_str();
  cmd->add_option("--samples", o->samples,
                  "Render samples A to B-1 of a --total-spp render into an .exr piece for "
                  "`penumbra merge` (A and B multiples of --spp-per-frame, or B the total)");
  cmd->add_option("--total-spp", o->totalSpp, "The whole render's samples per pixel (--samples)")
      ->check(CLI::Range(1u, render::kMaxSamplesPerPixel));
  cmd->add_option("--out", o->out, "Output image: .exr (linear float) or .png (tone-mapped sRGB)")
      ->capture_default_str();
  addDeviceOptions(*cmd, o->device);
  o->settings.add(*cmd, render::RenderSettings{});
  cmd->add_option("--settings", o->settingsFile,
                  "Render settings JSON (written beside each viewer screenshot); options given "
                  "explicitly override its values");
  cmd->add_option("--vary", o->vary,
                  "material-test: the Disney parameter that goes from 0 to 1 along the row");
  cmd->add_option(
      "--set", o->set,
      "material-test: the shared material's constants, e.g. metallic=1,baseColor=0.9,0.6,0.2");
  cmd->add_flag("--allow-external-files", o->allowExternalFiles,
                "Let glTF files read buffers and images outside their own folder");
  cmd->add_flag("--check-only", o->checkOnly,
                "Check the options and the scene (and print a piece's identity), render nothing")
      ->group("");
  cmd->add_flag("--print-effects", o->printEffects,
                "List the effects the scene calls for, one per line, and exit");
  cmd->add_option(
      "--aov", o->aov,
      "Auxiliary outputs as EXR layers, comma separated: albedo, normal, depth, emission, "
      "motion, variance");
  return [o, cmd] { return runRender(*o, *cmd); };
}

}  // namespace penumbra::app
