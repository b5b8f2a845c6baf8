#include "compute_harness.h"

#include <algorithm>

#include "path_tracer_shared.h"  // PENUMBRA_T, PENUMBRA_U
#include "penumbra_test_shaders.h"

namespace penumbra::test {

ComputeHarness::ComputeHarness(rhi::IDevice& device, const std::string& shader) : device_(device) {
  rhi::ComputePipelineDesc desc;
  desc.shader = test_shaders::shaderDesc(shader);
  desc.debugName = shader;
  pipeline_ = device_.createComputePipeline(desc);
  commandList_ = device_.createCommandList();
}

std::vector<uint8_t> ComputeHarness::run(const void* push, uint32_t pushBytes,
                                         const std::vector<Input>& inputs, uint64_t resultBytes,
                                         uint32_t groups) {
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
  std::vector<rhi::BufferHandle> inputBuffers;
  rhi::BindingSetDesc set;
  for (size_t i = 0; i < inputs.size(); ++i) {
    inputBuffers.push_back(buffer(inputs[i].bytes, BufferUsage::StorageBuffer,
                                  MemoryLocation::DeviceLocal, "harness input"));
    set.items.push_back(
        rhi::BindingSetItem::storageBuffer(PENUMBRA_T(uint32_t(i)), inputBuffers.back()));
  }
  auto results = buffer(resultBytes, BufferUsage::StorageBuffer, MemoryLocation::DeviceLocal,
                        "harness results");
  auto readback =
      buffer(resultBytes, BufferUsage::CopyDest, MemoryLocation::Readback, "harness readback");
  set.items.push_back(rhi::BindingSetItem::storageBuffer(PENUMBRA_U(0), results));
  auto bindings = device_.createBindingSet(set, *pipeline_);

  auto* cmd = commandList_.get();
  cmd->open();
  for (size_t i = 0; i < inputs.size(); ++i)
    if (inputs[i].bytes > 0)
      cmd->writeBuffer(inputBuffers[i].get(), inputs[i].data, inputs[i].bytes);
  cmd->setComputeState({pipeline_.get(), {bindings.get()}});
  cmd->setPushConstants(push, pushBytes);
  cmd->dispatch(groups);
  cmd->copyBuffer(readback.get(), 0, results.get(), 0, resultBytes);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  const auto* bytes = static_cast<const uint8_t*>(readback->mappedData());
  return std::vector<uint8_t>(bytes, bytes + resultBytes);
}

}  // namespace penumbra::test
