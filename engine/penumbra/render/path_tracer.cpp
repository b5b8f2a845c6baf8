#include "penumbra/render/path_tracer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "effects.h"
#include "path_tracer_shared.h"
#include "penumbra/render/camera_model.h"
#include "penumbra/render/effect_set.h"
#include "penumbra/render/image_size.h"
#include "penumbra/util/error.h"

namespace penumbra::render {
namespace {

// How far the camera may move from render space's origin before the origin
// follows it (PathTracer::setCamera): within 64 m floats still resolve 4 um,
// and the new origin, the grid point nearest the camera, is at most 55 m
// from it, so a camera has to travel at least 9 m before it moves again.
constexpr double kRebaseDistance = 64.0;

}  // namespace

PathTracer::PathTracer(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                       uint32_t height, const PipelineOptions& options,
                       const std::optional<scene::Camera>& camera)
    : device_(device),
      width_(width),
      height_(height),
      options_(options),
      camera_(camera ? *camera : scene.camera),
      environment_(scene.environment),
      ambient_(scene.ambient),
      materials_(scene.materials) {
  requireValidImageSize("path tracer", width, height);
  scene::validate(scene);
  scene::validateCamera(camera_);
  sceneEffects_ = deriveEffects(scene, camera_);
  pipelineEffects_ = wantedPipelineEffects();
  commandList_ = device_.createCommandList("path tracer");
  createAccumulation();

  rhi::BufferDesc counter;
  counter.byteSize = 4;
  counter.usage = rhi::BufferUsage::StorageBuffer;
  counter.debugName = "ray counter";
  rayCounter_ = device_.createBuffer(counter);
  ownFrame_ = createFrameQueries();

  for (const auto& inst : scene.instances) {
    drawnMaterials_.push_back(scene.meshes[inst.mesh].material);
    meshEffects_ |= meshEffects(scene.meshes[inst.mesh]);
    if (hasVertexAlpha(scene.meshes[inst.mesh]))
      vertexAlphaMaterials_.push_back(scene.meshes[inst.mesh].material);
  }
  for (const auto& object : scene.implicits) drawnMaterials_.push_back(object.material);
  scene_ = std::make_unique<GpuScene>(device_, scene, renderOriginNear(camera_.position),
                                      pipelineEffects_ == uint32_t(PT_EFFECTS_ALL));
  // The path-tracing pipeline now, so bad shaders fail at construction; the
  // others when first used.
  pipelineFor(RayGeneration::Path);
}

PathTracer::~PathTracer() = default;

void PathTracer::createAccumulation() {
  rhi::TextureDesc tex;
  tex.width = width_;
  tex.height = height_;
  tex.format = rhi::Format::RGBA32_FLOAT;
  tex.usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource;
  tex.debugName = "accumulation";
  accumulation_ = device_.createTexture(tex);
  tex.debugName = "guide albedo";
  guides_.albedo = device_.createTexture(tex);
  tex.debugName = "guide normal and depth";
  guides_.normalDepth = device_.createTexture(tex);
  tex.debugName = "guide emission";
  guides_.emission = device_.createTexture(tex);
  tex.debugName = "guide moments";
  guides_.moments = device_.createTexture(tex);
}

void PathTracer::resize(uint32_t width, uint32_t height) {
  requireValidImageSize("path tracer", width, height);
  if (width == width_ && height == height_) return;
  // The binding sets hold the old image; frames still reading it finish first.
  device_.waitForIdle();
  width_ = width;
  height_ = height;
  createAccumulation();
  rebuildBindings();
  resetAccumulation();
}

void PathTracer::rebuildBindings() {
  for (int i = 0; i < int(RayGeneration::Probe); ++i)
    if (pipelines_[i].pipeline)
      bindings_[i] =
          createBindings(*pipelines_[i].pipeline, nullptr, nullptr, "path tracer bindings");
}

void PathTracer::setEnvironment(scene::Environment environment) {
  scene::validateEnvironment(environment);
  // Frames in flight still read the buffers replaced here.
  device_.waitForIdle();
  const bool wasPresent = sceneEffects_ & PT_EFFECT_ENVIRONMENT;
  scene::Environment previous = std::move(environment_);
  environment_ = std::move(environment);
  try {
    scene_->uploadEnvironment(environment_);
  } catch (...) {
    environment_ = std::move(previous);
    throw;
  }
  rebuildBindings();
  resetAccumulation();
  // Turned on or off: the pipelines hold the environment's code only when
  // the scene has one (PT_EFFECT_ENVIRONMENT).
  if (wasPresent != environment_.present()) {
    sceneEffects_ ^= PT_EFFECT_ENVIRONMENT;
    rebuildPipelines();
  }
}

void PathTracer::setEnvironmentPlacement(float rotationDegrees, float intensity,
                                         bool visibleBackground) {
  if (!environment_.present())
    throw Error("environment: there is none to turn, scale or hide (environment map FILE)");
  scene::Environment placed;  // the map stays; only these are validated
  placed.width = placed.height = 1;
  placed.radiance = {glm::vec3(0.0f)};
  placed.source = environment_.source;
  placed.rotationDegrees = rotationDegrees;
  placed.intensity = intensity;
  scene::validateEnvironment(placed);
  device_.waitForIdle();  // frames in flight read the placement written here
  environment_.rotationDegrees = rotationDegrees;
  environment_.intensity = intensity;
  environment_.visibleBackground = visibleBackground;
  scene_->writeEnvironmentPlacement(environment_);
  resetAccumulation();
}

const RayGenerationPipeline& PathTracer::pipelineFor(RayGeneration rayGeneration) {
  const int i = int(rayGeneration);
  if (pipelines_[i].pipeline) return pipelines_[i];
  pipelines_[i] = createRayGenerationPipeline(device_, rayGeneration, pipelineEffects_,
                                              scene_->implicitFamilies());
  pipelineCreationSeconds_ += pipelines_[i].creationSeconds;
  if (rayGeneration != RayGeneration::Probe)
    bindings_[i] =
        createBindings(*pipelines_[i].pipeline, nullptr, nullptr, "path tracer bindings");
  return pipelines_[i];
}

rhi::BindingSetHandle PathTracer::createBindings(const rhi::IRayTracingPipeline& pipeline,
                                                 const rhi::BufferHandle& probeRays,
                                                 const rhi::BufferHandle& probeHits,
                                                 const char* name) {
  using Item = rhi::BindingSetItem;
  std::vector<Item> items = scene_->bindingItems();
  items.insert(items.end(), {Item::storageTexture(PT_SLOT_ACCUMULATION, accumulation_),
                             Item::storageTexture(PT_SLOT_GUIDE_ALBEDO, guides_.albedo),
                             Item::storageTexture(PT_SLOT_GUIDE_NORMAL_DEPTH, guides_.normalDepth),
                             Item::storageTexture(PT_SLOT_GUIDE_EMISSION, guides_.emission),
                             Item::storageTexture(PT_SLOT_GUIDE_MOMENTS, guides_.moments),
                             Item::storageBuffer(PT_SLOT_RAY_COUNTER, rayCounter_)});
  if (probeRays) items.push_back(Item::storageBuffer(PT_SLOT_PROBE_RAYS, probeRays));
  if (probeHits) items.push_back(Item::storageBuffer(PT_SLOT_PROBE_HITS, probeHits));
  return createDeclaredBindings(device_, pipeline, items, name);
}

const glm::dvec3& PathTracer::renderOrigin() const {
  return scene_->renderOrigin();
}

glm::dmat4 PathTracer::worldToRenderSpace() const {
  return scene_->worldToRenderSpace();
}

uint32_t PathTracer::emissiveTriangleCount() const {
  return scene_->emissiveTriangleCount();
}

const AccelStructBuildTimes& PathTracer::accelStructBuildTimes() const {
  return scene_->accelStructBuildTimes();
}

void PathTracer::setCamera(const scene::Camera& camera) {
  scene::validateCamera(camera);
  camera_ = camera;
  if (glm::length(camera.position - scene_->renderOrigin()) > kRebaseDistance) {
    scene_->rebase(renderOriginNear(camera.position));
    ++rebaseCount_;
  }
  resetAccumulation();
  const uint32_t effects =
      (sceneEffects_ & ~uint32_t(PT_EFFECT_ORTHOGRAPHIC)) | cameraEffects(camera);
  if (effects != sceneEffects_) {
    sceneEffects_ = effects;
    rebuildPipelines();
  }
}

bool PathTracer::updateMaterials(const std::vector<scene::Material>& materials) {
  if (materials.size() != materials_.size())
    throw Error(fmt::format("path tracer: updateMaterials got {} materials; the scene has {}",
                            materials.size(), materials_.size()));
  for (size_t i = 0; i < materials.size(); ++i)
    if (materials[i].emission != materials_[i].emission)
      throw Error(
          fmt::format("path tracer: material '{}' changes its emission; emitters are fixed "
                      "when the scene is uploaded",
                      materials[i].name));
  materials_ = materials;
  scene_->writeMaterials(materials_);
  resetAccumulation();

  // Emission, meshes and the camera are unchanged, so only the material bits
  // can differ.
  uint32_t effects = (sceneEffects_ & (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_DELTA_LIGHTS |
                                       PT_EFFECT_ENVIRONMENT | PT_EFFECT_ORTHOGRAPHIC)) |
                     meshEffects_;
  for (uint32_t m : drawnMaterials_) effects |= deriveMaterialEffects(materials_[m]);
  // Vertex alpha cuts a mesh under MASK or BLEND whatever its texture.
  for (uint32_t m : vertexAlphaMaterials_)
    if (alphaMasked(materials_[m], true)) effects |= PT_EFFECT_ALPHA_MASK;
  sceneEffects_ = effects;
  return rebuildPipelines();
}

uint32_t PathTracer::wantedPipelineEffects() const {
  return options_.allEffects ? uint32_t(PT_EFFECTS_ALL) : sceneEffects_;
}

bool PathTracer::rebuildPipelines() {
  const uint32_t effects = wantedPipelineEffects();
  if (effects == pipelineEffects_) return false;
  device_.waitForIdle();  // frames in flight still use the old pipelines
  pipelineEffects_ = effects;
  // Pipelines of the old effect set go; each is rebuilt when next used.
  for (auto& p : pipelines_) p = RayGenerationPipeline{};
  for (auto& b : bindings_) b.reset();
  for (bool& d : dispatched_) d = false;
  pipelineFor(RayGeneration::Path);
  return true;
}

gpu::CameraData cameraData(const scene::Camera& camera, uint32_t width, uint32_t height,
                           const glm::dvec3& renderOrigin) {
  const CameraModel m = cameraModel(camera, width, height);
  auto float3 = [](const glm::dvec3& v) {
    const glm::vec3 f(v);
    return gpu::float3{f.x, f.y, f.z};
  };
  gpu::CameraData c;
  c.position = float3(m.position - renderOrigin);
  c.filmHalfHeight = float(m.filmHalfHeight);
  c.right = float3(m.right);
  c.aspectRatio = float(m.aspect);
  c.up = float3(m.up);
  c.apertureRadius = camera.apertureRadius;
  c.forward = float3(m.forward);
  c.focusDistance = camera.focusDistance;
  return c;
}

uint32_t cameraSceneFlags(const scene::Camera& camera) {
  return (camera.apertureBlades << PT_SCENE_BLADES_SHIFT) |
         (camera.orthographic() ? PT_SCENE_ORTHOGRAPHIC : 0u);
}

uint32_t frameFlags(const PathTracerSettings& s) {
  uint32_t flags = 0;
  uint32_t directions = PT_DIRECTIONS_BSDF;
  switch (s.strategy) {
    case SamplingStrategy::Uniform:
      directions = PT_DIRECTIONS_UNIFORM;
      break;
    case SamplingStrategy::Cosine:
      directions = PT_DIRECTIONS_COSINE;
      break;
    case SamplingStrategy::Bsdf:
      break;
    case SamplingStrategy::Nee:
      flags |= PT_FLAG_NEE;
      break;
    case SamplingStrategy::Mis:
      flags |= PT_FLAG_NEE | PT_FLAG_MIS;
      break;
  }
  if (s.misHeuristic == MisHeuristic::Balance) flags |= PT_FLAG_BALANCE_HEURISTIC;
  if (s.russianRoulette) flags |= PT_FLAG_RUSSIAN_ROULETTE;
  if (s.sampler == Sampler::Sobol) flags |= PT_FLAG_SOBOL;
  return flags | (directions << PT_DIRECTIONS_SHIFT);
}

FrameStats PathTracer::renderFrame(const PathTracerSettings& settings, uint32_t samples) {
  auto* cmd = commandList_.get();
  cmd->open();
  recordFrame(*cmd, settings, samples, ownFrame_);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  return frameStats(ownFrame_);
}

FrameQueries PathTracer::createFrameQueries() {
  FrameQueries queries;
  queries.timer = device_.createTimerQuery();
  rhi::BufferDesc counter;
  counter.byteSize = 4;
  counter.memory = rhi::MemoryLocation::Readback;
  counter.usage = rhi::BufferUsage::CopyDest;
  counter.debugName = "ray counter readback";
  queries.rays = device_.createBuffer(counter);
  return queries;
}

void PathTracer::recordFrame(rhi::ICommandList& cmd, const PathTracerSettings& settings,
                             uint32_t samples, FrameQueries& queries) {
  if (!(settings.radianceClamp >= 0.0f))
    throw Error("path tracer: the radiance clamp must be >= 0 (0 = off)");
  if (samples < 1 || samples > kMaxSamplesPerFrame)
    throw Error(fmt::format("path tracer: {} samples per frame is outside 1..{}", samples,
                            kMaxSamplesPerFrame));
  gpu::FrameConstants c{};
  c.camera = cameraData(camera_, width_, height_, scene_->renderOrigin());
  c.width = width_;
  c.height = height_;
  c.samplesThisFrame = samples;
  c.samplesBefore = accumulatedSamples_;
  c.seed = settings.seed;
  c.maxDepth = settings.maxDepth;
  c.rouletteStartDepth = settings.rouletteStartDepth;
  c.flags = frameFlags(settings);
  uint32_t sceneFlags = cameraSceneFlags(camera_);
  if (environment_.present()) {
    sceneFlags |= PT_SCENE_ENVIRONMENT;
    if (environment_.visibleBackground) sceneFlags |= PT_SCENE_BACKGROUND;
  }
  c.emissiveTriangleCount = scene_->emissiveTriangleCount();
  c.pointLightCount = scene_->pointLightCount();
  c.firstSample = firstSample_;
  c.sceneFlags = sceneFlags;
  c.ambient = {ambient_.x, ambient_.y, ambient_.z};
  c.radianceClamp = settings.radianceClamp;

  const RayGeneration rayGeneration = settings.integrator == Integrator::Whitted
                                          ? RayGeneration::Whitted
                                      : settings.writeGuides ? RayGeneration::PathWithGuides
                                                             : RayGeneration::Path;
  auto& p = pipelineFor(rayGeneration);
  const rhi::RayTracingState state{
      p.pipeline.get(), p.table.get(), {bindings_[int(rayGeneration)].get()}};
  // lavapipe compiles a pipeline's shaders at its first dispatch, which the
  // timer would count as tracing (seconds, against milliseconds once
  // compiled). One pixel is traced untimed first, while the accumulation is
  // empty: the frame rewrites that pixel after the barrier the second
  // setRayTracingState records.
  if (!dispatched_[int(rayGeneration)] && accumulatedSamples_ == 0) {
    cmd.setRayTracingState(state);
    cmd.setPushConstants(&c, sizeof(c));
    cmd.dispatchRays(1, 1);
    dispatched_[int(rayGeneration)] = true;
  }
  // One counter serves every frame: the queue runs the frames' clear,
  // dispatch and copy in order, and each frame copies it to its own readback.
  cmd.clearBufferUint(rayCounter_.get(), 0);
  cmd.setRayTracingState(state);
  cmd.setPushConstants(&c, sizeof(c));
  cmd.beginTimerQuery(queries.timer.get());
  cmd.dispatchRays(width_, height_);
  cmd.endTimerQuery(queries.timer.get());
  cmd.copyBuffer(queries.rays.get(), 0, rayCounter_.get(), 0, 4);
  // The Whitted integrator leaves the guide buffers untouched.
  const bool guides = settings.writeGuides && settings.integrator == Integrator::Path;
  guidesWritten_ = (accumulatedSamples_ == 0 || guidesWritten_) && guides;
  accumulatedSamples_ += samples;
  queries.samples = samples;
}

FrameStats PathTracer::frameStats(FrameQueries& queries) {
  FrameStats stats;
  if (queries.samples == 0) return stats;  // nothing recorded with them yet
  stats.gpuSeconds = device_.timerQuerySeconds(queries.timer.get());
  std::memcpy(&stats.rays, queries.rays->mappedData(), 4);
  stats.samples = queries.samples;
  return stats;
}

image::Image PathTracer::readback() {
  return readback(accumulation_);
}

image::Image PathTracer::readback(const rhi::TextureHandle& texture) {
  if (texture->desc().format != rhi::Format::RGBA32_FLOAT || texture->desc().width != width_ ||
      texture->desc().height != height_)
    throw Error("path tracer: readback needs an RGBA32F texture of the image's size");
  rhi::BufferDesc desc;
  desc.byteSize = uint64_t(width_) * height_ * 16;
  desc.usage = rhi::BufferUsage::CopyDest;
  desc.memory = rhi::MemoryLocation::Readback;
  desc.debugName = "accumulation readback";
  auto buffer = device_.createBuffer(desc);
  auto* cmd = commandList_.get();
  cmd->open();
  cmd->copyTextureToBuffer(texture.get(), buffer.get());
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  image::Image img(width_, height_);
  std::memcpy(img.rgba.data(), buffer->mappedData(), desc.byteSize);
  return img;
}

image::Image renderImage(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                         uint32_t height, uint32_t spp, const PathTracerSettings& settings,
                         uint32_t samplesPerFrame, const PipelineOptions& options) {
  PathTracer tracer(device, scene, width, height, options);
  while (tracer.accumulatedSamples() < spp)
    tracer.renderFrame(settings, std::min(samplesPerFrame, spp - tracer.accumulatedSamples()));
  return tracer.readback();
}

}  // namespace penumbra::render
