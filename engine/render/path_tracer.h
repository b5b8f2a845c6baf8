#pragma once
// The path tracer on top of the RHI: uploads a scene (one BLAS per mesh, one
// TLAS instance per scene instance), builds the ray-tracing pipeline of the
// shading core, and accumulates frames of 1-16 samples per pixel into a
// linear HDR running mean.
#include <memory>

#include "image/image.h"
#include "rhi/rhi.h"
#include "scene/scene.h"

namespace penumbra::render {

struct PathTracerSettings {
  uint32_t maxDepth = 8;             // bounces after the camera ray
  uint32_t rouletteStartDepth = 3;   // Russian roulette from this bounce on
  bool nextEventEstimation = true;   // sample emissive triangles at every vertex
  bool multipleImportanceSampling = true;  // power heuristic between NEE and BSDF sampling
  bool russianRoulette = true;
  uint32_t seed = 0;
};

struct FrameStats {
  double gpuSeconds = 0;  // GPU timestamps around the dispatch
  uint64_t rays = 0;      // every traced ray (camera, bounce, shadow), counted on the GPU
  uint32_t samples = 0;   // samples per pixel in this frame
};

class PathTracer {
 public:
  static constexpr uint32_t kMaxSamplesPerFrame = 16;

  PathTracer(rhi::IDevice& device, const scene::Scene& scene, uint32_t width, uint32_t height);
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // Renders `samples` (1..16) more samples per pixel and waits for them.
  FrameStats renderFrame(const PathTracerSettings& settings, uint32_t samples);
  // The next frame starts a new mean (camera or settings changed).
  void resetAccumulation() { accumulatedSamples_ = 0; }
  uint32_t accumulatedSamples() const { return accumulatedSamples_; }

  // The running mean, linear RGB (alpha 1).
  image::Image readback();
  const rhi::TextureHandle& accumulation() const { return accumulation_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  uint32_t emissiveTriangleCount() const { return emissiveTriangleCount_; }

 private:
  struct SceneBuffers;
  void uploadScene(const scene::Scene& scene);
  void createPipeline();

  rhi::IDevice& device_;
  uint32_t width_, height_;
  scene::Camera camera_;
  uint32_t accumulatedSamples_ = 0;
  uint32_t emissiveTriangleCount_ = 0;
  std::unique_ptr<SceneBuffers> scene_;
  rhi::TextureHandle accumulation_;
  rhi::BufferHandle rayCounter_, rayCounterReadback_;
  rhi::RayTracingPipelineHandle pipeline_;
  rhi::ShaderTableHandle shaderTable_;
  rhi::BindingSetHandle bindings_;
  rhi::CommandListHandle commandList_;
  rhi::TimerQueryHandle timer_;
};

}  // namespace penumbra::render
