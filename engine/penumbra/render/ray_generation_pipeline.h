#pragma once
// One ray-tracing pipeline per ray-generation shader: drivers compile every
// hit and intersection shader into each ray-generation shader of a pipeline,
// so a pipeline holding several costs that many times as much to build as
// the one a render needs. Each holds the scene's hit groups (triangles, then
// the implicit families in the TLAS's hit-group order) and one miss shader.
#include <string>
#include <vector>

#include "penumbra/render/implicit_geometry.h"
#include "penumbra/rhi/rhi.h"

namespace penumbra::render {

// The path tracer's comes in two: with and without the code that writes the
// guide buffers (PT_OUTPUT_GUIDES). The probe traces given rays and reports
// their closest hits (PathTracer::traceProbeRays).
enum class RayGeneration { Path, PathWithGuides, Whitted, Probe };
constexpr int kRayGenerationCount = 4;

struct RayGenerationPipeline {
  rhi::RayTracingPipelineHandle pipeline;
  rhi::ShaderTableHandle table;
  double creationSeconds = 0;  // CPU time of createRayTracingPipeline (compiling shaders)
};

// `effects`: the PT_EFFECT_* bits the shading shaders are specialized for
// (render/effect_set.h); `implicitFamilies`: GpuScene::implicitFamilies().
RayGenerationPipeline createRayGenerationPipeline(
    rhi::IDevice& device, RayGeneration rayGeneration, uint32_t effects,
    const std::vector<ImplicitFamily>& implicitFamilies);

// A binding set of those `items` that `pipeline`'s shaders declare (each
// ray-generation shader declares its own outputs).
rhi::BindingSetHandle createDeclaredBindings(rhi::IDevice& device,
                                             const rhi::IRayTracingPipeline& pipeline,
                                             const std::vector<rhi::BindingSetItem>& items,
                                             const std::string& name);

}  // namespace penumbra::render
