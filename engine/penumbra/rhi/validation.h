#pragma once
// The RHI's validation layer: one wrapper that every backend device sits
// behind (backends/backend_factory.cpp puts it there), checking each argument
// rule of the RHI once, for both APIs -- command-list state, copy and upload
// ranges, barrier states against a resource's usage and memory, acceleration
// structure build inputs, pipeline and hit-group composition, shader-record
// sizes, binding-set completeness and agreement with the bound pipeline,
// push-constant sizes, timer-query pairing. A broken rule throws
// penumbra::Error naming the call and the objects' debug names, before the
// backend records anything. The backends assume valid arguments.
//
// The layer wraps the device, its command lists, ray-tracing pipelines,
// shader tables, binding sets and swapchains; buffers, textures, samplers,
// acceleration structures, timer queries and compute pipelines are the
// backend's own objects. Its cost is a few comparisons per RHI call (tens per
// frame), nothing per ray or pixel, so it is always on (docs/ARCHITECTURE.md,
// "RHI validation").
#include "penumbra/rhi/device.h"

namespace penumbra::rhi::validation {

// Puts the validation layer in front of a backend's device.
DeviceHandle wrapDevice(DeviceHandle backendDevice);

}  // namespace penumbra::rhi::validation
