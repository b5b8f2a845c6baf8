// Runs the shading core as compiled by glslang's HLSL front-end
// (tests/shaders/harness/core_check.hlsl) in an analytic furnace on the test device:
// the HLSL spelling of the core must compute the same physics as the GLSL one.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstring>

#include "path_tracer_shared.h"
#include "penumbra_test_shaders.h"
#include "test_device.h"

using namespace penumbra;

namespace {

std::vector<float> runFurnace(rhi::IDevice& device, uint32_t flags, uint32_t maxDepth,
                              uint32_t spp) {
  constexpr uint32_t kSide = 16, kPixels = kSide * kSide;
  rhi::ComputePipelineDesc desc;
  desc.shader = test_shaders::shaderDesc("core_check.hlsl");
  desc.debugName = "HLSL core furnace";
  auto pipeline = device.createComputePipeline(desc);

  rhi::BufferDesc out;
  out.byteSize = kPixels * 16;
  out.usage = rhi::BufferUsage::StorageBuffer;
  out.debugName = "furnace output";
  auto output = device.createBuffer(out);
  out.usage = rhi::BufferUsage::CopyDest;
  out.memory = rhi::MemoryLocation::Readback;
  out.debugName = "furnace readback";
  auto readback = device.createBuffer(out);
  rhi::BufferDesc sphereDesc;
  sphereDesc.byteSize = 16;
  sphereDesc.usage = rhi::BufferUsage::StorageBuffer;
  sphereDesc.debugName = "furnace sphere";
  auto sphere = device.createBuffer(sphereDesc);
  const gpu::float4 sphereParams{0.5f, 1.0f, 1.0f, 0.0f};  // albedo, emission, radius

  rhi::BindingSetDesc set;
  set.items = {rhi::BindingSetItem::storageBuffer(PENUMBRA_T(0), sphere),
               rhi::BindingSetItem::storageBuffer(PENUMBRA_U(0), output)};
  auto bindings = device.createBindingSet(set, *pipeline);

  gpu::FrameConstants push{};
  push.camera.position = {0, 0, 0};
  push.camera.filmHalfHeight = 1.0f;  // tan(45 deg)
  push.camera.right = {-1, 0, 0};
  push.camera.aspectRatio = 1.0f;
  push.camera.up = {0, 1, 0};
  push.camera.forward = {0, 0, 1};
  push.width = kSide;
  push.height = kSide;
  push.samplesThisFrame = spp;
  push.seed = 3;
  push.maxDepth = maxDepth;
  push.rouletteStartDepth = 1;
  push.flags = flags;

  auto cmd = device.createCommandList();
  cmd->open();
  cmd->writeBuffer(sphere.get(), &sphereParams, sizeof(sphereParams));
  cmd->setComputeState({pipeline.get(), {bindings.get()}});
  cmd->setPushConstants(&push, sizeof(push));
  cmd->dispatch(kPixels / 64);
  cmd->copyBuffer(readback.get(), 0, output.get(), 0, out.byteSize);
  cmd->close();
  device.submit(cmd.get());
  device.waitForIdle();
  std::vector<float> values(kPixels * 4);
  std::memcpy(values.data(), readback->mappedData(), out.byteSize);
  return values;
}
}  // namespace

TEST_CASE("HLSL-compiled core: furnace without roulette is exact", "[shaders][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  // BSDF sampling only: every bounce adds rho^k * Le exactly, so each pixel is
  // the truncated series Le * (1 - rho^(D+1)) / (1 - rho).
  const uint32_t depth = 30;
  const double expected = (1.0 - std::pow(0.5, depth + 1)) / 0.5;
  auto v = runFurnace(*device, 0u, depth, 4);
  for (size_t i = 0; i < v.size(); i += 4) {
    INFO("pixel " << i / 4 << ": " << v[i]);
    REQUIRE(std::abs(v[i] - expected) < 1e-4 * expected);
    REQUIRE(v[i + 1] == v[i]);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("HLSL-compiled core: furnace with Russian roulette is unbiased",
          "[shaders][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  auto v = runFurnace(*device, PT_FLAG_RUSSIAN_ROULETTE, 200, 256);
  double sum = 0;
  for (size_t i = 0; i < v.size(); i += 4) {
    REQUIRE(std::isfinite(v[i]));
    sum += v[i];
  }
  const double mean = sum / (v.size() / 4);
  INFO("mean " << mean);
  REQUIRE(std::abs(mean - 2.0) < 0.02);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
