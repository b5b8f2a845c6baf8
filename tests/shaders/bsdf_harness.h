#pragma once
// Runs the shading core's Disney BSDF on the test device through the compute
// harness shaders/harness/bsdf_harness.comp (compute_harness.h).
#include <glm/glm.hpp>
#include <vector>

#include "compute_harness.h"
#include "path_tracer_shared.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"

namespace penumbra::test {

struct BsdfSampleResult {
  glm::vec3 wi;
  float pdf;
  glm::vec3 weight;
  uint32_t lobe;  // BSDF_LOBE_* (4 = none)
  bool isDelta;
};

struct BsdfEvalResult {
  glm::vec3 f;
  float pdf;
  glm::vec3 fReversed;  // f(wi, wo)
  float pdfReversed;
};

class BsdfHarness {
 public:
  explicit BsdfHarness(rhi::IDevice& device);
  // `coatNormal`: the glTF coat's own normal in the shading frame (unit).
  std::vector<BsdfSampleResult> sample(const scene::Material& m, glm::vec3 wo, uint32_t count,
                                       uint32_t seed, glm::vec3 coatNormal = {0, 0, 1});
  std::vector<BsdfEvalResult> eval(const scene::Material& m, glm::vec3 wo,
                                   const std::vector<glm::vec3>& wi,
                                   glm::vec3 coatNormal = {0, 0, 1});
  // Per item: (bad eval, bad sample, bad direction) flags over random extreme inputs.
  std::vector<glm::vec4> sweep(uint32_t count, uint32_t seed);
  // Per item: orthonormality error of the frame of an extreme normal.
  std::vector<float> frameErrors(uint32_t count, uint32_t seed);

 private:
  std::vector<glm::vec4> run(uint32_t mode, uint32_t count, uint32_t seed, glm::vec3 wo,
                             glm::vec3 coatNormal, const gpu::MaterialData& material,
                             const std::vector<glm::vec4>& directions, uint32_t resultsPerItem);
  ComputeHarness harness_;
};

gpu::MaterialData packForGpu(const scene::Material& m);

}  // namespace penumbra::test
