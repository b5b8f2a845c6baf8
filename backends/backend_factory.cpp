#include "backend_factory.h"

#include <fmt/format.h>

#include "penumbra/rhi/fault_injection.h"
#include "penumbra/rhi/validation.h"
#include "penumbra/util/error.h"
#include "vulkan/vulkan_backend.h"
#ifdef PENUMBRA_HAVE_D3D12
#include "d3d12/d3d12_backend.h"
#endif

namespace penumbra::backends {
namespace {
void requireKnown(const std::string& backend) {
  if (backend == "vulkan") return;
#ifdef PENUMBRA_HAVE_D3D12
  if (backend == "d3d12") return;
  throw Error(fmt::format("unknown backend '{}' (available: vulkan, d3d12)", backend));
#else
  if (backend == "d3d12")
    throw Error("backend 'd3d12': the D3D12 backend exists in Windows builds only");
  throw Error(fmt::format("unknown backend '{}' (available: vulkan)", backend));
#endif
}
}  // namespace

std::vector<std::string> availableBackends() {
#ifdef PENUMBRA_HAVE_D3D12
  return {"vulkan", "d3d12"};
#else
  return {"vulkan"};
#endif
}

rhi::DeviceHandle createDevice(const std::string& backend, const rhi::DeviceCreateInfo& info) {
  requireKnown(backend);
  const rhi::BindingOffsets& o = info.bindingOffsets;
  if (!o.valid())
    throw Error(fmt::format(
        "device: binding offsets b{} t{} u{} s{}, root-constant spaces {} and {}: the register "
        "classes must start in the order b < t < u < s and the spaces differ "
        "(DeviceCreateInfo::bindingOffsets)",
        o.constantBuffer, o.shaderResource, o.unorderedAccess, o.sampler, o.pushConstantSpace,
        o.shaderRecordSpace));
  rhi::faults::readEnvironment();  // a malformed PENUMBRA_INJECT_FAULT fails here
#ifdef PENUMBRA_HAVE_D3D12
  if (backend == "d3d12") return rhi::validation::wrapDevice(d3d12::createDevice(info));
#endif
  return rhi::validation::wrapDevice(vk::createDevice(info));
}

std::vector<rhi::AdapterInfo> listAdapters(const std::string& backend) {
  requireKnown(backend);
#ifdef PENUMBRA_HAVE_D3D12
  if (backend == "d3d12") return d3d12::listAdapters();
#endif
  return vk::listAdapters();
}

}  // namespace penumbra::backends
