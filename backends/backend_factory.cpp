#include "backend_factory.h"

#include <fmt/format.h>

#include "util/error.h"
#include "vulkan/vulkan_backend.h"

namespace penumbra::backends {
namespace {
void requireKnown(const std::string& backend) {
  if (backend == "vulkan") return;
  if (backend == "d3d12")
    throw Error("backend 'd3d12': the D3D12 backend exists in Windows builds only");
  throw Error(fmt::format("unknown backend '{}' (available: vulkan)", backend));
}
}  // namespace

std::vector<std::string> availableBackends() { return {"vulkan"}; }

rhi::DeviceHandle createDevice(const std::string& backend, const rhi::DeviceCreateInfo& info) {
  requireKnown(backend);
  return vk::createDevice(info);
}

std::vector<rhi::AdapterInfo> listAdapters(const std::string& backend) {
  requireKnown(backend);
  return vk::listAdapters();
}

}  // namespace penumbra::backends
