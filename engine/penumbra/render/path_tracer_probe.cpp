// PathTracer::traceProbeRays: arbitrary rays through the production pipeline
// (shaders/stages/probe.rgen), for tests of the hit shaders and for picking.
#include <fmt/format.h>

#include <cstring>

#include "penumbra/render/path_tracer.h"
#include "penumbra/util/error.h"

namespace penumbra::render {

std::vector<SurfaceHit> PathTracer::traceProbeRays(const std::vector<ProbeRay>& rays) {
  if (rays.empty()) return {};
  // One launch per ray in x: Vulkan guarantees widths of 65535 x 1024 and
  // D3D12 2^30, both far above this bound.
  constexpr size_t kMaxRays = 1u << 22;
  if (rays.size() > kMaxRays)
    throw Error(fmt::format("path tracer: {} probe rays is more than {}", rays.size(), kMaxRays));
  const glm::dvec3& origin = scene_->renderOrigin();
  std::vector<gpu::ProbeRay> packed;
  packed.reserve(rays.size());
  // Rays and hits are world space here, render space on the GPU.
  for (const auto& r : rays)
    packed.push_back({.origin = {float(r.origin.x - origin.x), float(r.origin.y - origin.y),
                                 float(r.origin.z - origin.z)},
                      .tMax = r.tMax,
                      .direction = {r.direction.x, r.direction.y, r.direction.z}});

  rhi::BufferDesc desc;
  desc.byteSize = packed.size() * sizeof(gpu::ProbeRay);
  desc.usage = rhi::BufferUsage::StorageBuffer;
  desc.debugName = "probe rays";
  auto rayBuffer = device_.createBuffer(desc);
  desc.byteSize = packed.size() * sizeof(gpu::ProbeHit);
  desc.debugName = "probe hits";
  auto hitBuffer = device_.createBuffer(desc);
  desc.usage = rhi::BufferUsage::CopyDest;
  desc.memory = rhi::MemoryLocation::Readback;
  desc.debugName = "probe hits readback";
  auto readback = device_.createBuffer(desc);
  auto& probe = pipelineFor(RayGeneration::Probe);
  auto bindings = createBindings(*probe.pipeline, rayBuffer, hitBuffer, "probe bindings");

  auto* cmd = commandList_.get();
  cmd->open();
  cmd->writeBuffer(rayBuffer.get(), packed.data(), packed.size() * sizeof(gpu::ProbeRay));
  cmd->setRayTracingState({probe.pipeline.get(), probe.table.get(), {bindings.get()}});
  gpu::FrameConstants unused{};  // the layout has push constants; probe.rgen reads none
  cmd->setPushConstants(&unused, sizeof(unused));
  cmd->dispatchRays(uint32_t(packed.size()), 1);
  cmd->copyBuffer(readback.get(), 0, hitBuffer.get(), 0, desc.byteSize);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();

  std::vector<gpu::ProbeHit> results(packed.size());
  std::memcpy(results.data(), readback->mappedData(), desc.byteSize);
  std::vector<SurfaceHit> hits;
  hits.reserve(results.size());
  for (const auto& r : results) {
    SurfaceHit h;
    h.position = glm::vec3(glm::dvec3(r.position.x, r.position.y, r.position.z) + origin);
    h.hitT = r.hitT;
    h.geometricNormal = {r.normal.x, r.normal.y, r.normal.z};
    // The GPU orders mesh instances its own way (meshInstanceOrder);
    // implicit objects follow them in both orders.
    const auto& toScene = scene_->gpuToSceneInstance();
    h.instanceIndex = r.instanceIndex < toScene.size() ? toScene[r.instanceIndex] : r.instanceIndex;
    h.primitiveIndex = r.primitiveIndex;
    hits.push_back(h);
  }
  return hits;
}

}  // namespace penumbra::render
