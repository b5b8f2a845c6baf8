// Fault injection (rhi/fault_injection.h): an armed allocation or submit
// fails as on a full or lost GPU, with the message a user would see, once.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "penumbra/rhi/fault_injection.h"
#include "test_device.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

TEST_CASE("fault injection: the armed allocation fails as out of memory, once", "[rhi][faults]") {
  auto device = test::makeTestDevice();
  BufferDesc desc;
  desc.byteSize = 3u << 20;
  desc.usage = BufferUsage::StorageBuffer;
  desc.debugName = "big";
  faults::arm(faults::Site::Allocation, 2);
  auto first = device->createBuffer(desc);  // the first call still succeeds
  // The API's own name for it: what a user would search for.
  const std::string code =
      test::testBackend() == "d3d12" ? "E_OUTOFMEMORY" : "VK_ERROR_OUT_OF_DEVICE_MEMORY";
  REQUIRE_THROWS_WITH(
      device->createBuffer(desc),
      ContainsSubstring("out of device memory allocating 3.0 MiB for buffer 'big'") &&
          ContainsSubstring(code));
  TextureDesc t;
  t.width = t.height = 16;
  t.debugName = "after";
  auto texture = device->createTexture(t);  // fired once: allocations work again
  REQUIRE(texture);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("fault injection: the armed submit reports a lost device naming the list",
          "[rhi][faults]") {
  auto device = test::makeTestDevice();
  auto list = device->createCommandList("doomed");
  list->open();
  list->close();
  faults::arm(faults::Site::Submit, 1);
  const std::string code =
      test::testBackend() == "d3d12" ? "DXGI_ERROR_DEVICE_REMOVED" : "VK_ERROR_DEVICE_LOST";
  REQUIRE_THROWS_WITH(device->submit(list.get()),
                      ContainsSubstring("was lost submitting command list 'doomed' (" + code));
  // The device was not really lost: the next submit goes through.
  device->submit(list.get());
  device->waitForIdle();
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
