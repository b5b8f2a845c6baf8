// Command lists and the device's bookkeeping of what they hold
// (engine/penumbra/rhi/command_list.h, IDevice::submit / waitForIdle).
#include <catch2/catch_test_macros.hpp>
#include <cstring>
#include <numeric>
#include <vector>

#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;

// A pass that must replace a binding set mid-frame waits for the device while
// the frame's list records (render::DisplayPass does). The list's staging
// buffers from this recording are not the device's to release then: if they
// were, the recorded copy would read a destroyed buffer (a validation error)
// and the data would not arrive.
TEST_CASE("command lists: a waitForIdle while a list records leaves its staging buffers to it",
          "[rhi]") {
  auto device = test::makeTestDevice();
  std::vector<uint32_t> data(1u << 16);
  std::iota(data.begin(), data.end(), 7u);
  const uint64_t bytes = data.size() * sizeof(uint32_t);
  BufferDesc target;
  target.byteSize = bytes;
  target.usage = BufferUsage::CopyDest | BufferUsage::CopySource;
  target.debugName = "written";
  auto buffer = device->createBuffer(target);
  BufferDesc back = target;
  back.usage = BufferUsage::CopyDest;
  back.memory = MemoryLocation::Readback;
  back.debugName = "readback";
  auto readback = device->createBuffer(back);

  auto list = device->createCommandList("recorded twice");
  // A first recording, submitted: the device now counts the list in flight.
  list->open();
  const uint32_t zero = 0;
  list->writeBuffer(buffer.get(), &zero, sizeof(zero));
  list->close();
  device->submit(list.get());
  // The second recording writes through a new staging buffer, then waits.
  list->open();
  list->writeBuffer(buffer.get(), data.data(), bytes);
  device->waitForIdle();
  list->copyBuffer(readback.get(), 0, buffer.get(), 0, bytes);
  list->close();
  device->submit(list.get());
  device->waitForIdle();

  REQUIRE(std::memcmp(readback->mappedData(), data.data(), bytes) == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
