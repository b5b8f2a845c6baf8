#pragma once
// The device every GPU test runs on: the backend PENUMBRA_TEST_BACKEND names
// (vulkan by default; d3d12 in the Windows build under Wine), validation on,
// the default adapter (lavapipe on CI). Tests end with
// REQUIRE_NO_VALIDATION_MESSAGES.
#include <catch2/catch_test_macros.hpp>
#include <string>

#include "backend_factory.h"

namespace penumbra::test {
rhi::DeviceHandle makeTestDevice();
// "vulkan" or "d3d12": the backend makeTestDevice creates.
std::string testBackend();
}

#define REQUIRE_NO_VALIDATION_MESSAGES(device) REQUIRE((device)->validationMessageCount() == 0u)
