#pragma once
// Creates RHI devices by backend name. The only place that knows which
// backends this build contains.
#include <string>
#include <vector>

#include "penumbra/rhi/device.h"

namespace penumbra::backends {

// Backends compiled into this build ("vulkan"; "d3d12" on Windows builds).
std::vector<std::string> availableBackends();

// Every device comes behind the RHI validation layer (rhi/validation.h).
// Throws penumbra::Error with a one-line reason for an unknown backend, a
// backend missing from this build, or no suitable device.
rhi::DeviceHandle createDevice(const std::string& backend, const rhi::DeviceCreateInfo& info);
std::vector<rhi::AdapterInfo> listAdapters(const std::string& backend);

}  // namespace penumbra::backends
