#include "test_device.h"

#include <cstdlib>
#include <string>

#include "penumbra/render/shader_binding_offsets.h"

namespace penumbra::test {

std::string testBackend() {
  const char* backend = std::getenv("PENUMBRA_TEST_BACKEND");
  return backend && *backend ? backend : "vulkan";
}

rhi::DeviceHandle makeTestDevice() {
  rhi::DeviceCreateInfo info;
  info.bindingOffsets = render::kShaderBindingOffsets;
  // The API's own validation (Vulkan's validation layer, the D3D12 debug
  // layer) on top of the RHI's, which is always on. vkd3d-proton has no
  // D3D12 debug layer: the D3D12 run under Wine turns it off with
  // PENUMBRA_TEST_API_VALIDATION=0 (tests/apps/d3d12_device_cases.sh).
  const char* apiValidation = std::getenv("PENUMBRA_TEST_API_VALIDATION");
  info.validation = !(apiValidation && std::string(apiValidation) == "0");
  // PENUMBRA_TEST_DEVICE picks an adapter index (e.g. a GPU beside lavapipe).
  if (const char* index = std::getenv("PENUMBRA_TEST_DEVICE")) info.adapterIndex = std::atoi(index);
  return backends::createDevice(testBackend(), info);
}

}  // namespace penumbra::test
