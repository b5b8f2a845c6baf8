#include "penumbra/render/ray_generation_pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "effects.h"
#include "path_tracer_shared.h"
#include "payloads_shared.h"
#include "penumbra/render/effect_set.h"
#include "penumbra_shaders.h"

namespace penumbra::render {

RayGenerationPipeline createRayGenerationPipeline(
    rhi::IDevice& device, RayGeneration rayGeneration, uint32_t effects,
    const std::vector<ImplicitFamily>& implicitFamilies) {
  static const char* const kNames[] = {"path_trace.rgen", "path_trace.rgen", "whitted.rgen",
                                       "probe.rgen"};
  const char* rayGen = kNames[int(rayGeneration)];
  // The shading ray-generation shaders are what the effect set specializes;
  // their export names stay the plain ones.
  const uint32_t variant =
      effects | (rayGeneration == RayGeneration::PathWithGuides ? PT_OUTPUT_GUIDES : 0u);
  rhi::ShaderDesc rayGenShader = rayGeneration == RayGeneration::Probe
                                     ? shaders::shaderDesc(rayGen)
                                     : shaders::shaderDesc(effectVariant(rayGen, variant));
  rayGenShader.exportName = rayGen;

  rhi::RayTracingPipelineDesc desc;
  desc.debugName = fmt::format("{} (effects {:#x})", rayGen, effects);
  desc.shaders = {rayGenShader, shaders::shaderDesc("path_trace.rmiss"),
                  shaders::shaderDesc("triangle.rchit")};
  // One hit group per geometry kind, for radiance and shadow rays alike
  // (PT_RAY_CONTRIBUTION). The triangles' comes first, with the alpha
  // any-hit when the scene has alpha-cut materials; then each implicit
  // family the scene uses, in the order of the TLAS instances' hit-group
  // offsets: a pipeline holds only the intersection shaders of the geometry
  // its scene contains.
  const bool alphaMask = (effects & PT_EFFECT_ALPHA_MASK) != 0;
  desc.hitGroups = {
      {"triangles", "triangle.rchit", alphaMask ? "triangle_alpha.rahit" : "", "", false}};
  if (alphaMask) desc.shaders.push_back(shaders::shaderDesc("triangle_alpha.rahit"));
  if (!implicitFamilies.empty()) desc.shaders.push_back(shaders::shaderDesc("implicit.rchit"));
  for (ImplicitFamily family : implicitFamilies) {
    const std::string name = implicitHitGroupName(family);
    desc.shaders.push_back(shaders::shaderDesc(implicitIntersectionShader(family)));
    desc.hitGroups.push_back(
        {name, "implicit.rchit", "", implicitIntersectionShader(family), true});
  }
  desc.maxPayloadBytes = sizeof(gpu::HitRecord);
  desc.maxAttributeBytes = sizeof(gpu::ImplicitAttributes);
  desc.maxRecursionDepth = 1;  // only the ray generation shader traces
  RayGenerationPipeline p;
  const auto start = std::chrono::steady_clock::now();
  p.pipeline = device.createRayTracingPipeline(desc);
  p.creationSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  p.table = p.pipeline->createShaderTable(std::string(rayGen) + " shader table");
  p.table->setRayGenerationShader(rayGen);
  p.table->addMissShader("path_trace.rmiss");  // miss index 0, for every ray
  for (const auto& group : desc.hitGroups) p.table->addHitGroup(group.exportName);
  return p;
}

rhi::BindingSetHandle createDeclaredBindings(rhi::IDevice& device,
                                             const rhi::IRayTracingPipeline& pipeline,
                                             const std::vector<rhi::BindingSetItem>& items,
                                             const std::string& name) {
  const auto& declared = pipeline.bindingLayout().spaces.at(0).items;
  rhi::BindingSetDesc set;
  set.debugName = name;
  for (const auto& item : items)
    if (std::any_of(declared.begin(), declared.end(),
                    [&](const auto& d) { return d.slot == item.slot; }))
      set.items.push_back(item);
  return device.createBindingSet(set, pipeline);
}

}  // namespace penumbra::render
