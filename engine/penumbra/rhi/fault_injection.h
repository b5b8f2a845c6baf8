#pragma once
// A test hook that makes the backends fail as a GPU does when it runs out of
// memory or is lost, so those error paths run in tests rather than first on a
// user's machine. The backends ask shouldFail() at each device-memory
// allocation and each submit; when it says so they report the failure the API
// would have returned (VK_ERROR_OUT_OF_DEVICE_MEMORY / E_OUTOFMEMORY,
// VK_ERROR_DEVICE_LOST / DXGI_ERROR_DEVICE_REMOVED) through the same code as
// a real one.
//
// Armed by the environment variable PENUMBRA_INJECT_FAULT=allocation:N or
// submit:N (the process's Nth allocation or submit fails, N >= 1), read once,
// or by arm() (the viewer's `inject-fault` script command). One fault at a
// time; it fires once.
#include <cstdint>

namespace penumbra::rhi::faults {

enum class Site : uint8_t { Allocation, Submit };

// Reads PENUMBRA_INJECT_FAULT now and throws penumbra::Error when it is
// malformed. backends::createDevice calls it before creating anything, so a
// bad setting fails there rather than in the middle of a resource's creation.
void readEnvironment();
// The `countdown`th call at `site` from now fails (1: the next one).
void arm(Site site, uint64_t countdown);
// Counts a call at `site`; true when it is the armed one.
bool shouldFail(Site site);

}  // namespace penumbra::rhi::faults
