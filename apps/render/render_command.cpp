#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <regex>

#include "backend_factory.h"
#include "commands.h"
#include "image/image_io.h"
#include "progress.h"
#include "render/effect_set.h"
#include "render/path_tracer.h"
#include "render/tonemapper.h"
#include "scene/material_row.h"
#include "scene/scene_loader.h"
#include "util/error.h"

namespace penumbra::app {
namespace {

struct RenderOptions {
  std::string scene = "cornell-box";
  std::string camera;
  std::string size = "512x512";
  uint32_t spp = 64;
  uint32_t sppPerFrame = 16;
  std::string out = "render.png";
  std::string backend = "vulkan";
  int device = -1;
  uint32_t seed = 0;
  uint32_t maxDepth = 8;
  render::Integrator integrator = render::Integrator::Path;
  render::SamplingStrategy strategy = render::SamplingStrategy::Mis;
  render::MisHeuristic heuristic = render::MisHeuristic::Power;
  float clamp = 0.0f;
  bool noRoulette = false;
  bool validation = false;
  std::string vary;
  std::string set;
  bool allEffects = false;
  bool printEffects = false;
  float exposure = 1.0f;
};

}  // namespace

std::pair<uint32_t, uint32_t> parseImageSize(const std::string& text) {
  static const std::regex pattern("([0-9]{1,5})x([0-9]{1,5})");
  std::smatch m;
  if (!std::regex_match(text, m, pattern))
    throw Error(fmt::format("--size '{}': expected WIDTHxHEIGHT, e.g. 512x512", text));
  uint32_t w = std::stoul(m[1]), h = std::stoul(m[2]);
  if (w == 0 || h == 0 || w > 16384 || h > 16384)
    throw Error(fmt::format("--size '{}': width and height must be 1..16384", text));
  return {w, h};
}

namespace {

int runRender(const RenderOptions& o) {
  auto [width, height] = parseImageSize(o.size);
  // Everything that can fail on bad input fails before any rendering starts.
  scene::Scene scene = scene::loadScene(o.scene);
  if (!o.camera.empty()) scene::selectCamera(scene, o.camera);
  if (!o.vary.empty() || !o.set.empty()) scene::changeMaterialRow(scene, o.vary, o.set);
  if (o.printEffects) {
    for (const auto& name : render::effectNames(render::deriveEffects(scene))) fmt::print("{}\n", name);
    return 0;
  }
  image::checkWritable(o.out);

  rhi::DeviceCreateInfo info;
  info.adapterIndex = o.device;
  info.validation = o.validation;
  auto device = backends::createDevice(o.backend, info);
  const auto& adapter = device->adapter();
  fmt::print("device: {} ({}, {}) via {}\n", adapter.name, rhi::adapterTypeName(adapter.type),
             adapter.apiVersion, device->backendName());
  fmt::print("scene: {} ({} triangles, {} implicit objects), {}x{}, {} spp, seed {}\n", scene.name,
             scene.triangleCount(), scene.implicits.size(), width, height, o.spp, o.seed);
  if (o.clamp > 0.0f)
    fmt::print("radiance clamp: {} per sample (biased: energy above it is discarded)\n", o.clamp);
  std::fflush(stdout);  // before the progress lines on stderr

  render::PipelineOptions pipeline;
  pipeline.allEffects = o.allEffects;
  render::PathTracer tracer(*device, scene, width, height, pipeline);
  std::string effects;
  for (const auto& name : render::effectNames(tracer.pipelineEffects()))
    effects += (effects.empty() ? "" : ", ") + name;
  fmt::print("pipeline effects: {}{}\n", effects.empty() ? "none" : effects,
             o.allEffects ? " (--all-effects)" : "");
  render::PathTracerSettings settings;
  settings.seed = o.seed;
  settings.maxDepth = o.maxDepth;
  settings.integrator = o.integrator;
  settings.strategy = o.strategy;
  settings.misHeuristic = o.heuristic;
  settings.radianceClamp = o.clamp;
  settings.russianRoulette = !o.noRoulette;

  Progress progress(o.spp);
  double gpuSeconds = 0;
  uint64_t rays = 0;
  while (tracer.accumulatedSamples() < o.spp) {
    const uint32_t n = std::min(o.sppPerFrame, o.spp - tracer.accumulatedSamples());
    auto stats = tracer.renderFrame(settings, n);
    gpuSeconds += stats.gpuSeconds;
    rays += stats.rays;
    progress.update(tracer.accumulatedSamples());
  }
  progress.finish();

  if (image::formatFromPath(o.out) == image::FileFormat::Exr) {
    image::saveExr(o.out, tracer.readback());
  } else {
    render::Tonemapper tonemapper(*device);
    image::savePng(o.out, tonemapper.run(tracer.accumulation(), o.exposure));
  }
  fmt::print("GPU time: {:.3f} ms total, {:.3f} ms per sample per pixel of the whole image\n",
             gpuSeconds * 1e3, gpuSeconds * 1e3 / o.spp);
  fmt::print("rays: {} ({:.2f} Mrays/s)\n", rays, gpuSeconds > 0 ? rays / gpuSeconds * 1e-6 : 0.0);
  fmt::print("wrote {}\n", o.out);
  if (o.validation && device->validationMessageCount() > 0) {
    fmt::print(stderr, "error: {} validation message(s)\n", device->validationMessageCount());
    return 1;
  }
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand("render", "Path-trace a scene to an image (.exr linear, .png sRGB)");
  cmd->add_option("--scene", o->scene,
                  "Built-in scene name, scene file (.json) or glTF file (.gltf, .glb)")
      ->capture_default_str();
  cmd->add_option("--camera", o->camera,
                  "Render from the scene's camera of this name (glTF camera or node name; "
                  "default: the first camera in node order)");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--spp", o->spp, "Samples per pixel")->check(CLI::Range(1u, 1u << 20))->capture_default_str();
  cmd->add_option("--spp-per-frame", o->sppPerFrame, "Samples per pixel in each GPU frame")
      ->check(CLI::Range(1u, 16u))->capture_default_str();
  cmd->add_option("--out", o->out, "Output image: .exr (linear float) or .png (tone-mapped sRGB)")
      ->capture_default_str();
  cmd->add_option("--backend", o->backend, "Backend: vulkan | d3d12")->capture_default_str();
  cmd->add_option("--device", o->device, "Device index from 'penumbra devices' (default: best with ray tracing)");
  cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
  cmd->add_option("--max-depth", o->maxDepth, "Maximum bounces")->check(CLI::Range(0u, 1024u))->capture_default_str();
  const std::map<std::string, render::Integrator> integrators{{"path", render::Integrator::Path},
                                                              {"whitted", render::Integrator::Whitted}};
  cmd->add_option("--integrator", o->integrator, "Integrator: path | whitted")
      ->transform(CLI::CheckedTransformer(integrators))->default_str("path");
  const std::map<std::string, render::SamplingStrategy> strategies{
      {"uniform", render::SamplingStrategy::Uniform}, {"cosine", render::SamplingStrategy::Cosine},
      {"bsdf", render::SamplingStrategy::Bsdf}, {"nee", render::SamplingStrategy::Nee},
      {"mis", render::SamplingStrategy::Mis}};
  cmd->add_option("--strategy", o->strategy,
                  "Path sampling: uniform | cosine | bsdf (no light sampling) | nee | mis")
      ->transform(CLI::CheckedTransformer(strategies))->default_str("mis");
  const std::map<std::string, render::MisHeuristic> heuristics{
      {"power", render::MisHeuristic::Power}, {"balance", render::MisHeuristic::Balance}};
  cmd->add_option("--mis-heuristic", o->heuristic, "MIS weights: power | balance")
      ->transform(CLI::CheckedTransformer(heuristics))->default_str("power");
  cmd->add_option("--clamp", o->clamp, "Clamp each sample's radiance to this value (0 = off)")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  cmd->add_flag("--no-russian-roulette", o->noRoulette, "Disable Russian roulette");
  cmd->add_option("--exposure", o->exposure, "Exposure multiplier for PNG output")->capture_default_str();
  cmd->add_option("--vary", o->vary,
                  "material-test: the Disney parameter that goes from 0 to 1 along the row");
  cmd->add_option("--set", o->set,
                  "material-test: the shared material's constants, e.g. metallic=1,baseColor=0.9,0.6,0.2");
  cmd->add_flag("--all-effects", o->allEffects,
                "Build the full pipeline instead of only the effects the scene calls for");
  cmd->add_flag("--print-effects", o->printEffects,
                "List the effects the scene calls for, one per line, and exit");
  cmd->add_flag("--validation", o->validation, "Enable the API validation layer; fail on any message");
  return [o] { return runRender(*o); };
}

}  // namespace penumbra::app
