#include "test_device.h"

#include <cstdlib>

namespace penumbra::test {

rhi::DeviceHandle makeTestDevice() {
  rhi::DeviceCreateInfo info;
  info.validation = true;
  // PENUMBRA_TEST_DEVICE picks an adapter index (e.g. a GPU beside lavapipe).
  if (const char* index = std::getenv("PENUMBRA_TEST_DEVICE")) info.adapterIndex = std::atoi(index);
  return backends::createDevice("vulkan", info);
}

}  // namespace penumbra::test
