#pragma once
// The path tracer on top of the RHI: a thin renderer that sequences frames.
// It holds the scene on the GPU (render/gpu_scene.h), one pipeline per
// ray-generation shader (render/ray_generation_pipeline.h), built for the
// effects the scene calls for (render/effect_set.h), the camera, and the
// accumulation: frames of 1-16 samples per pixel averaged into a linear HDR
// running mean, with the denoiser's guide buffers beside it.
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/image/image.h"
#include "penumbra/render/gpu_scene.h"
#include "penumbra/render/ray_generation_pipeline.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

enum class Integrator { Path, Whitted };

// How the path tracer finds light (for study and comparison; `Mis` is the
// production choice).
enum class SamplingStrategy {
  Uniform,  // directions uniform over the sphere, lights found by chance
  Cosine,   // cosine-weighted directions, lights found by chance
  Bsdf,     // BSDF importance sampling, lights found by chance
  Nee,      // BSDF sampling for indirect light, next-event estimation for direct light
  Mis,      // NEE and BSDF sampling combined by multiple importance sampling
};
enum class MisHeuristic { Power, Balance };
// Where a path's random numbers come from (shaders/shared/rng.hlsli).
enum class Sampler {
  Random,  // hashed PCG streams, the pixel position stratified per frame
  Sobol,   // Owen-scrambled Sobol points in every dimension, padded by pairs
};

struct PathTracerSettings {
  Integrator integrator = Integrator::Path;
  SamplingStrategy strategy = SamplingStrategy::Mis;
  MisHeuristic misHeuristic = MisHeuristic::Power;
  Sampler sampler = Sampler::Sobol;  // docs/study/README.md: 1.2-2x the efficiency from 4 spp on
  uint32_t maxDepth = 8;            // bounces after the camera ray (Whitted: recursion depth)
  uint32_t rouletteStartDepth = 3;  // Russian roulette from this bounce on
  bool russianRoulette = true;
  float radianceClamp = 0.0f;  // largest channel of one sample's contribution; 0 = off
  uint32_t seed = 0;
  // Write the guide buffers (GuideBuffers) beside the image: the denoiser
  // and the AOVs read them. Off by default: the pipeline that writes them
  // (PT_OUTPUT_GUIDES) is about a tenth slower.
  bool writeGuides = false;
  // Field by field: tests/render/test_render_settings.cpp finds a field the
  // settings table does not describe with it.
  bool operator==(const PathTracerSettings&) const = default;
};

// How the pipeline is built. By default it holds only the effects the scene
// calls for (engine/penumbra/render/effect_set.h); `allEffects` builds the full one,
// for comparison and benchmarks.
struct PipelineOptions {
  bool allEffects = false;
};

struct FrameStats {
  double gpuSeconds = 0;  // GPU timestamps around the dispatch
  uint64_t rays = 0;      // every traced ray (camera, bounce, shadow), counted on the GPU
  uint32_t samples = 0;   // samples per pixel in this frame
};

// Where a recorded frame's statistics land: one per frame in flight, read
// once the GPU has finished that frame (PathTracer::recordFrame).
struct FrameQueries {
  rhi::TimerQueryHandle timer;
  rhi::BufferHandle rays;  // readback of the ray counter
  uint32_t samples = 0;
};

// The camera as the shaders see it (gpu::CameraData, camera_shared.h), in
// render space: its position relative to `renderOrigin`
// (PathTracer::renderOrigin()).
gpu::CameraData cameraData(const scene::Camera& camera, uint32_t width, uint32_t height,
                           const glm::dvec3& renderOrigin);
// The FrameConstants.sceneFlags the camera sets: the aperture's blade count
// and PT_SCENE_ORTHOGRAPHIC.
uint32_t cameraSceneFlags(const scene::Camera& camera);

// FrameConstants.flags for these settings (PT_FLAG_* and PT_DIRECTIONS_*).
uint32_t frameFlags(const PathTracerSettings& settings);

// A world-space ray for PathTracer::traceProbeRays.
struct ProbeRay {
  glm::dvec3 origin{0.0};                 // world space, double as every world position
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // hitT is measured in units of its length
  float tMax = 1e30f;
};

// A closest hit as the integrators see it (shaders/shared/surface_hit.hlsli).
struct SurfaceHit {
  glm::vec3 position{0.0f};
  float hitT = -1.0f;               // < 0: the ray missed everything
  glm::vec3 geometricNormal{0.0f};  // unit, front side (counter-clockwise; outside of an implicit)
  uint32_t instanceIndex = 0;       // scene.instances first, then scene.implicits in their order
  uint32_t primitiveIndex = 0;      // triangle within the mesh; 0 for implicit objects
  bool isHit() const { return hitT >= 0.0f; }
};

// The denoiser's guide buffers, written by the path tracer beside the
// accumulation (running means over the same samples; PT_U_GUIDE_* in
// path_tracer_shared.h says what each channel holds). The Whitted
// integrator leaves them untouched.
struct GuideBuffers {
  rhi::TextureHandle albedo;
  rhi::TextureHandle normalDepth;
  rhi::TextureHandle emission;
  rhi::TextureHandle moments;
};

class PathTracer {
 public:
  static constexpr uint32_t kMaxSamplesPerFrame = 16;

  // Seen from `camera` (the scene's own if absent): a camera given here, not
  // by setCamera afterwards, builds the pipeline once for its projection.
  PathTracer(rhi::IDevice& device, const scene::Scene& scene, uint32_t width, uint32_t height,
             const PipelineOptions& options = {},
             const std::optional<scene::Camera>& camera = std::nullopt);
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // Renders `samples` (1..16) more samples per pixel and waits for them.
  FrameStats renderFrame(const PathTracerSettings& settings, uint32_t samples);
  // The same frame recorded into the caller's open command list, nothing
  // submitted or waited for: the viewer renders, displays and presents in one
  // list and keeps several frames in flight. `queries` must not be in flight.
  void recordFrame(rhi::ICommandList& commandList, const PathTracerSettings& settings,
                   uint32_t samples, FrameQueries& queries);
  FrameQueries createFrameQueries();
  // The statistics of the frame last recorded with `queries`; the GPU must
  // have finished it (its command list's next open() waits for that).
  FrameStats frameStats(FrameQueries& queries);
  // The next frame starts a new mean (camera or settings changed).
  void resetAccumulation() { startNewMean(0); }
  // The next frame starts a new mean whose samples are those of the sample
  // sequence from index `firstSample` on: the temporal denoiser's frames,
  // each its own mean, each with new samples. resetAccumulation() starts
  // the sequence over, so a render is the same however it was reached.
  void startNewMean(uint32_t firstSample) {
    accumulatedSamples_ = 0;
    firstSample_ = firstSample;
    ++accumulationGeneration_;
  }
  // The index of the next sample in the sequence.
  uint32_t nextSampleIndex() const { return firstSample_ + accumulatedSamples_; }
  // Counts the resets (resetAccumulation, setCamera, ...): a caller sees
  // that the image started over since it last looked.
  uint64_t accumulationGeneration() const { return accumulationGeneration_; }
  // Moves the camera (the scene's until then) and resets the accumulation.
  // A camera more than 64 m from renderOrigin() takes the origin with it
  // (the grid point nearest it): the instances, emitters, point lights and
  // implicit objects are placed again and the TLAS rebuilt, the meshes'
  // BLASes kept; the image is the one a tracer built with this camera makes.
  // A change of projection rebuilds the pipelines (PT_EFFECT_ORTHOGRAPHIC)
  // unless they hold all effects.
  void setCamera(const scene::Camera& camera);
  // How often setCamera moved the origin.
  uint32_t rebaseCount() const { return rebaseCount_; }
  const scene::Camera& camera() const { return camera_; }
  // Replaces the materials (same count and order as the scene's) and resets
  // the accumulation. Rebuilds the pipelines when the effects they call for
  // change (unless they hold all effects); returns whether it did. Emission
  // cannot change here: emitters are sampled from a table built with the
  // scene, so that needs a new PathTracer (penumbra::Error otherwise).
  bool updateMaterials(const std::vector<scene::Material>& materials);
  // Replaces the environment (scene::Environment; one that is not present
  // turns it off) and resets the accumulation. The new map's buffers are
  // built before the old ones go, so a map that cannot be uploaded throws
  // and leaves the environment as it was. Turning the environment on or off
  // rebuilds the pipelines (PT_EFFECT_ENVIRONMENT).
  void setEnvironment(scene::Environment environment);
  // Turns, scales or hides the environment uploaded, writing only its
  // placement (no map is copied, compared or uploaded: the viewer's
  // sliders call this every tick); resets the accumulation. Throws
  // penumbra::Error without an environment or with a rotation that is not
  // finite or an intensity that is not a finite number >= 0.
  void setEnvironmentPlacement(float rotationDegrees, float intensity, bool visibleBackground);
  const scene::Environment& environment() const { return environment_; }
  // A new accumulation image of this size (the viewer's render scale); the
  // scene and pipelines stay. Resets the accumulation.
  void resize(uint32_t width, uint32_t height);
  uint32_t accumulatedSamples() const { return accumulatedSamples_; }

  // Traces each ray (from tMin 0) through the production pipeline (the same
  // acceleration structures, hit groups and closest-hit shaders as the
  // integrators) and returns what its closest hit reported. For tests and
  // picking; waits for the GPU.
  std::vector<SurfaceHit> traceProbeRays(const std::vector<ProbeRay>& rays);

  // The running mean, linear RGB (alpha 1).
  image::Image readback();
  // Any of this tracer's images (accumulation or a guide buffer), RGBA float.
  image::Image readback(const rhi::TextureHandle& texture);
  const rhi::TextureHandle& accumulation() const { return accumulation_; }
  rhi::IDevice& device() const { return device_; }
  const GuideBuffers& guides() const { return guides_; }
  // Whether the guide buffers hold the running means of every sample of the
  // current mean (each of its frames had PathTracerSettings::writeGuides).
  bool guidesWritten() const { return guidesWritten_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  uint32_t emissiveTriangleCount() const;
  // Where render space's origin lies in the world: near the camera's position
  // when the scene was uploaded (a 64 m grid point). The GPU sees every
  // position relative to it, so floats are precise near the camera however
  // far from the world's origin the scene is (docs/ARCHITECTURE.md,
  // "Precision").
  const glm::dvec3& renderOrigin() const;
  glm::dmat4 worldToRenderSpace() const;
  // The PT_EFFECT_* bits the scene calls for, and those the pipeline holds.
  uint32_t sceneEffects() const { return sceneEffects_; }
  uint32_t pipelineEffects() const { return pipelineEffects_; }
  // CPU time spent creating ray-tracing pipelines so far (compiling shaders).
  double pipelineCreationSeconds() const { return pipelineCreationSeconds_; }
  const AccelStructBuildTimes& accelStructBuildTimes() const;

 private:
  void createAccumulation();
  // New binding sets for the pipelines built (the images or the scene's
  // buffers changed).
  void rebuildBindings();
  // The effects the pipelines hold: the scene's, or all (PipelineOptions).
  uint32_t wantedPipelineEffects() const;
  // Drops the pipelines if they were built for other effects than those
  // (PT_EFFECT_*) and builds the path tracer's; whether it did.
  bool rebuildPipelines();
  // Created on first use (render/ray_generation_pipeline.h says why).
  const RayGenerationPipeline& pipelineFor(RayGeneration rayGeneration);
  rhi::BindingSetHandle createBindings(const rhi::IRayTracingPipeline& pipeline,
                                       const rhi::BufferHandle& probeRays,
                                       const rhi::BufferHandle& probeHits, const char* name);

  rhi::IDevice& device_;
  uint32_t width_, height_;
  PipelineOptions options_;
  scene::Camera camera_;
  scene::Environment environment_;
  glm::vec3 ambient_{0.0f};
  std::vector<scene::Material> materials_;
  std::vector<uint32_t> drawnMaterials_;  // materials of instances and implicit objects
  std::vector<uint32_t> vertexAlphaMaterials_;  // materials of meshes with COLOR_0 alpha below 1
  uint32_t meshEffects_ = 0;                    // meshEffects of the drawn meshes
  uint32_t accumulatedSamples_ = 0;
  bool guidesWritten_ = false;
  uint32_t firstSample_ = 0;
  uint64_t accumulationGeneration_ = 0;
  uint32_t sceneEffects_ = 0;
  uint32_t pipelineEffects_ = 0;
  double pipelineCreationSeconds_ = 0;
  uint32_t rebaseCount_ = 0;
  std::unique_ptr<GpuScene> scene_;
  rhi::TextureHandle accumulation_;
  GuideBuffers guides_;
  rhi::BufferHandle rayCounter_;
  RayGenerationPipeline pipelines_[kRayGenerationCount];
  rhi::BindingSetHandle bindings_[kRayGenerationCount];  // for rendering; the probe binds its own
  bool dispatched_[kRayGenerationCount] = {};            // recordFrame's untimed first dispatch
  rhi::CommandListHandle commandList_;
  FrameQueries ownFrame_;  // renderFrame's
};

// Renders `spp` samples per pixel in frames of up to 16 and returns the mean
// (linear RGBA). `progress`, if set, is called after each frame with the
// samples done so far.
image::Image renderImage(rhi::IDevice& device, const scene::Scene& scene, uint32_t width,
                         uint32_t height, uint32_t spp, const PathTracerSettings& settings,
                         uint32_t samplesPerFrame = PathTracer::kMaxSamplesPerFrame,
                         const PipelineOptions& options = {});

}  // namespace penumbra::render
