#include "bsdf_harness.h"

#include <algorithm>
#include <cstring>

#include "penumbra_test_shaders.h"
#include "render/path_tracer.h"
#include "util/error.h"

namespace penumbra::test {

gpu::MaterialData packForGpu(const scene::Material& m) { return render::packMaterial(m); }

BsdfHarness::BsdfHarness(rhi::IDevice& device) : device_(device) {
  rhi::ComputePipelineDesc desc;
  desc.shader = test_shaders::shaderDesc("bsdf_harness.comp");
  desc.debugName = "BSDF harness";
  pipeline_ = device_.createComputePipeline(desc);
  commandList_ = device_.createCommandList();
}

std::vector<glm::vec4> BsdfHarness::run(uint32_t mode, uint32_t count, uint32_t seed, glm::vec3 wo,
                                        const gpu::MaterialData& material,
                                        const std::vector<glm::vec4>& directions,
                                        uint32_t resultsPerItem) {
  auto buffer = [&](uint64_t bytes, rhi::BufferUsage usage, rhi::MemoryLocation memory,
                    const char* name) {
    rhi::BufferDesc d;
    d.byteSize = std::max<uint64_t>(bytes, 16);
    d.usage = usage;
    d.memory = memory;
    d.debugName = name;
    return device_.createBuffer(d);
  };
  using rhi::BufferUsage;
  using rhi::MemoryLocation;
  const uint64_t resultBytes = uint64_t(count) * resultsPerItem * 16;
  auto materialBuffer = buffer(sizeof(material), BufferUsage::StorageBuffer, MemoryLocation::DeviceLocal, "material");
  auto directionBuffer = buffer(directions.size() * 16, BufferUsage::StorageBuffer, MemoryLocation::DeviceLocal, "directions");
  auto results = buffer(resultBytes, BufferUsage::StorageBuffer, MemoryLocation::DeviceLocal, "results");
  auto readback = buffer(resultBytes, BufferUsage::CopyDest, MemoryLocation::Readback, "results readback");

  rhi::BindingSetDesc set;
  set.items = {rhi::BindingSetItem::storageBuffer(PENUMBRA_T(0), materialBuffer),
               rhi::BindingSetItem::storageBuffer(PENUMBRA_T(1), directionBuffer),
               rhi::BindingSetItem::storageBuffer(PENUMBRA_U(0), results)};
  auto bindings = device_.createBindingSet(set, *pipeline_);
  struct {
    uint32_t mode, count, seed, pad;
    float wo[4];
  } push{mode, count, seed, 0, {wo.x, wo.y, wo.z, 0.0f}};

  auto* cmd = commandList_.get();
  cmd->open();
  cmd->writeBuffer(materialBuffer.get(), &material, sizeof(material));
  if (!directions.empty()) cmd->writeBuffer(directionBuffer.get(), directions.data(), directions.size() * 16);
  cmd->setComputeState({pipeline_.get(), {bindings.get()}});
  cmd->setPushConstants(&push, sizeof(push));
  cmd->dispatch((count + 63) / 64);
  cmd->copyBuffer(readback.get(), 0, results.get(), 0, resultBytes);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  std::vector<glm::vec4> out(size_t(count) * resultsPerItem);
  std::memcpy(out.data(), readback->mappedData(), resultBytes);
  return out;
}

std::vector<BsdfSampleResult> BsdfHarness::sample(const scene::Material& m, glm::vec3 wo, uint32_t count,
                                                  uint32_t seed) {
  auto raw = run(0, count, seed, wo, packForGpu(m), {}, 2);
  std::vector<BsdfSampleResult> r(count);
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec4 a = raw[2 * i], b = raw[2 * i + 1];
    const uint32_t code = uint32_t(b.w);
    r[i] = {glm::vec3(a), a.w, glm::vec3(b), code & 15u, (code & 16u) != 0};
  }
  return r;
}

std::vector<BsdfEvalResult> BsdfHarness::eval(const scene::Material& m, glm::vec3 wo,
                                              const std::vector<glm::vec3>& wi) {
  // Batches stay within the device's dispatch and storage-buffer limits
  // (65535 groups, 128 MiB on lavapipe).
  constexpr size_t kBatch = 1u << 20;
  std::vector<BsdfEvalResult> r(wi.size());
  const auto material = packForGpu(m);
  for (size_t first = 0; first < wi.size(); first += kBatch) {
    const size_t count = std::min(kBatch, wi.size() - first);
    std::vector<glm::vec4> dirs;
    dirs.reserve(count);
    for (size_t i = first; i < first + count; ++i) dirs.emplace_back(wi[i], 0.0f);
    auto raw = run(1, uint32_t(count), 0, wo, material, dirs, 2);
    for (size_t i = 0; i < count; ++i) {
      const glm::vec4 a = raw[2 * i], b = raw[2 * i + 1];
      r[first + i] = {glm::vec3(a), a.w, glm::vec3(b), b.w};
    }
  }
  return r;
}

std::vector<glm::vec4> BsdfHarness::sweep(uint32_t count, uint32_t seed) {
  return run(2, count, seed, glm::vec3(0, 0, 1), gpu::MaterialData{}, {}, 1);
}

std::vector<float> BsdfHarness::frameErrors(uint32_t count, uint32_t seed) {
  auto raw = run(3, count, seed, glm::vec3(0, 0, 1), gpu::MaterialData{}, {}, 1);
  std::vector<float> e(count);
  for (uint32_t i = 0; i < count; ++i) e[i] = raw[i].x;
  return e;
}

}  // namespace penumbra::test
