// Many devices, one after another, in one process: what a viewer that
// switches scenes, a long study or a farm worker does. Each lifetime creates
// an instance and a device (validation on, as every test device), records
// and submits work, reads it back and destroys everything; a driver or layer
// that keeps something per lifetime fails to create one eventually (the
// NVIDIA driver once refused new instances after about 30 in one process).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "backend_factory.h"
#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;

TEST_CASE(
    "device lifetimes: 200 devices in one process (50 on D3D12 under Wine), each with work and a "
    "readback",
    "[rhi][lifetimes]") {
  // PENUMBRA_TEST_LIFETIMES overrides the count (the GPU runs try more).
  int lifetimes = 200;
  if (const char* n = std::getenv("PENUMBRA_TEST_LIFETIMES")) lifetimes = std::atoi(n);
  for (int i = 0; i < lifetimes; ++i) {
    INFO("lifetime " << i);
    auto device = test::makeTestDevice();
    BufferDesc desc;
    desc.byteSize = 256;
    desc.usage = BufferUsage::CopyDest | BufferUsage::CopySource;
    desc.debugName = "lifetime data";
    auto buffer = device->createBuffer(desc);
    desc.usage = BufferUsage::CopyDest;
    desc.memory = MemoryLocation::Readback;
    desc.debugName = "lifetime readback";
    auto readback = device->createBuffer(desc);
    std::vector<uint32_t> data(64, uint32_t(i) * 2654435761u);
    auto list = device->createCommandList("lifetime");
    list->open();
    list->writeBuffer(buffer.get(), data.data(), desc.byteSize);
    list->copyBuffer(readback.get(), 0, buffer.get(), 0, desc.byteSize);
    list->close();
    device->submit(list.get());
    device->waitForIdle();
    REQUIRE(std::memcmp(readback->mappedData(), data.data(), desc.byteSize) == 0);
    REQUIRE_NO_VALIDATION_MESSAGES(device);
  }
}

TEST_CASE("device creation: binding offsets that are not set are refused by name",
          "[rhi][lifetimes]") {
  // The RHI holds no register shifts of its own (binding_offsets.h): a device
  // created without the shaders' would map every binding to the wrong
  // D3D12 register, so it is refused before anything is created.
  DeviceCreateInfo info;
  REQUIRE_THROWS_WITH(backends::createDevice(test::testBackend(), info),
                      Catch::Matchers::ContainsSubstring("DeviceCreateInfo::bindingOffsets"));
}
