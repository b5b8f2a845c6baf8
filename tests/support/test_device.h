#pragma once
// The device every GPU test runs on: Vulkan, validation layer on, the default
// adapter (lavapipe on CI). Tests end with REQUIRE_NO_VALIDATION_MESSAGES.
#include <catch2/catch_test_macros.hpp>

#include "backend_factory.h"

namespace penumbra::test {
rhi::DeviceHandle makeTestDevice();
}

#define REQUIRE_NO_VALIDATION_MESSAGES(device) REQUIRE((device)->validationMessageCount() == 0u)
