#pragma once
// Runs a test compute shader (tests/shaders/harness/) once on the test
// device: push constants, read-only storage buffers at PENUMBRA_T(0..), one
// result buffer at PENUMBRA_U(0) read back. The harnesses that test shading
// code (bsdf_harness.h, the sampler's) are thin layers over this.
#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/rhi/rhi.h"

namespace penumbra::test {

class ComputeHarness {
 public:
  // `shader`: a name of penumbra_test_shaders, e.g. "bsdf_harness.comp".
  ComputeHarness(rhi::IDevice& device, const std::string& shader);

  struct Input {
    const void* data;
    uint64_t bytes;
  };
  // Dispatches `groups` workgroups and returns the result buffer's
  // `resultBytes` bytes.
  std::vector<uint8_t> run(const void* push, uint32_t pushBytes, const std::vector<Input>& inputs,
                           uint64_t resultBytes, uint32_t groups);

 private:
  rhi::IDevice& device_;
  rhi::ComputePipelineHandle pipeline_;
  rhi::CommandListHandle commandList_;
};

}  // namespace penumbra::test
