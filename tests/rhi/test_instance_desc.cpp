#include <catch2/catch_test_macros.hpp>
#include <cstddef>
#include <cstring>

#include "penumbra/rhi/resources.h"

using penumbra::rhi::rt::InstanceDesc;

// D3D12_RAYTRACING_INSTANCE_DESC / VkAccelerationStructureInstanceKHR layout:
// float[3][4] transform at 0, InstanceID:24 | InstanceMask:8 at 48,
// InstanceContributionToHitGroupIndex:24 | Flags:8 at 52, address at 56.
TEST_CASE("instance desc packs like the API structs", "[rhi][instance]") {
  static_assert(sizeof(InstanceDesc) == 64);
  static_assert(offsetof(InstanceDesc, transform) == 0);
  static_assert(offsetof(InstanceDesc, bottomLevelAddress) == 56);

  InstanceDesc d;
  for (int i = 0; i < 12; ++i) d.transform[i] = float(i + 1);
  d.instanceID = 0xABCDEF;
  d.instanceMask = 0x5A;
  d.instanceContributionToHitGroupIndex = 0x123456;
  d.flags = 0x0F;
  d.bottomLevelAddress = 0x1122334455667788ull;

  unsigned char bytes[64];
  std::memcpy(bytes, &d, 64);
  float t[12];
  std::memcpy(t, bytes, 48);
  for (int i = 0; i < 12; ++i) REQUIRE(t[i] == float(i + 1));
  uint32_t word0, word1;
  uint64_t address;
  std::memcpy(&word0, bytes + 48, 4);
  std::memcpy(&word1, bytes + 52, 4);
  std::memcpy(&address, bytes + 56, 8);
  REQUIRE((word0 & 0xFFFFFF) == 0xABCDEF);
  REQUIRE((word0 >> 24) == 0x5A);
  REQUIRE((word1 & 0xFFFFFF) == 0x123456);
  REQUIRE((word1 >> 24) == 0x0F);
  REQUIRE(address == 0x1122334455667788ull);
}

TEST_CASE("instance desc defaults: identity, full mask", "[rhi][instance]") {
  InstanceDesc d;
  REQUIRE(d.transform == penumbra::rhi::rt::kIdentityTransform);
  REQUIRE(d.instanceMask == 0xFF);
  REQUIRE(d.instanceID == 0u);
  REQUIRE(d.bottomLevelAddress == 0u);
}
