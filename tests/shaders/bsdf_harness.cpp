#include "bsdf_harness.h"

#include <algorithm>
#include <cstring>

#include "penumbra/render/path_tracer.h"
#include "penumbra/render/sheen_albedo_table.h"
#include "penumbra/util/error.h"

namespace penumbra::test {

gpu::MaterialData packForGpu(const scene::Material& m) {
  return render::packMaterial(m);
}

BsdfHarness::BsdfHarness(rhi::IDevice& device) : harness_(device, "bsdf_harness.comp") {}

std::vector<glm::vec4> BsdfHarness::run(uint32_t mode, uint32_t count, uint32_t seed, glm::vec3 wo,
                                        glm::vec3 coatNormal, const gpu::MaterialData& material,
                                        const std::vector<glm::vec4>& directions,
                                        uint32_t resultsPerItem) {
  struct {
    uint32_t mode, count, seed, pad;
    float wo[4];
    float coatNormal[4];
  } push{mode,
         count,
         seed,
         0,
         {wo.x, wo.y, wo.z, 0.0f},
         {coatNormal.x, coatNormal.y, coatNormal.z, 0.0f}};
  const uint64_t resultBytes = uint64_t(count) * resultsPerItem * 16;
  const auto bytes = harness_.run(&push, sizeof(push),
                                  {{&material, sizeof(material)},
                                   {directions.data(), directions.size() * 16},
                                   {render::kSheenAlbedo.data(), sizeof(render::kSheenAlbedo)}},
                                  resultBytes, (count + 63) / 64);
  std::vector<glm::vec4> out(size_t(count) * resultsPerItem);
  std::memcpy(out.data(), bytes.data(), resultBytes);
  return out;
}

std::vector<BsdfSampleResult> BsdfHarness::sample(const scene::Material& m, glm::vec3 wo,
                                                  uint32_t count, uint32_t seed,
                                                  glm::vec3 coatNormal) {
  auto raw = run(0, count, seed, wo, coatNormal, packForGpu(m), {}, 2);
  std::vector<BsdfSampleResult> r(count);
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec4 a = raw[2 * i], b = raw[2 * i + 1];
    const uint32_t code = uint32_t(b.w);
    r[i] = {glm::vec3(a), a.w, glm::vec3(b), code & 15u, (code & 16u) != 0};
  }
  return r;
}

std::vector<BsdfEvalResult> BsdfHarness::eval(const scene::Material& m, glm::vec3 wo,
                                              const std::vector<glm::vec3>& wi,
                                              glm::vec3 coatNormal) {
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
    auto raw = run(1, uint32_t(count), 0, wo, coatNormal, material, dirs, 2);
    for (size_t i = 0; i < count; ++i) {
      const glm::vec4 a = raw[2 * i], b = raw[2 * i + 1];
      r[first + i] = {glm::vec3(a), a.w, glm::vec3(b), b.w};
    }
  }
  return r;
}

std::vector<glm::vec4> BsdfHarness::sweep(uint32_t count, uint32_t seed) {
  return run(2, count, seed, glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), gpu::MaterialData{}, {}, 1);
}

std::vector<float> BsdfHarness::frameErrors(uint32_t count, uint32_t seed) {
  auto raw =
      run(3, count, seed, glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), gpu::MaterialData{}, {}, 1);
  std::vector<float> e(count);
  for (uint32_t i = 0; i < count; ++i) e[i] = raw[i].x;
  return e;
}

}  // namespace penumbra::test
