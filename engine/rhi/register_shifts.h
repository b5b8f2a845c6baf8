#pragma once
// One register-to-binding shift table for both APIs (docs/ARCHITECTURE.md, "RHI").
// HLSL register(tN, spaceS) is Vulkan (set S, binding kShiftT + N), and so on.
// The DXC SPIR-V flags use the same numbers (-fvk-t-shift 32 all, ...), the
// GLSL entry points write bindings with the macros of
// shaders/shared/bindings.hlsli, and the D3D12 root signature maps a reflected
// binding back to its register with registerForBinding().
#include <cstdint>

namespace penumbra::rhi {

enum class RegisterClass : uint8_t { B, T, U, S };  // CBV, SRV, UAV, sampler

constexpr uint32_t kShiftB = 0;
constexpr uint32_t kShiftT = 32;
constexpr uint32_t kShiftU = 64;
constexpr uint32_t kShiftS = 96;

struct Register {
  RegisterClass registerClass;
  uint32_t index;
};

constexpr Register registerForBinding(uint32_t binding) {
  if (binding >= kShiftS) return {RegisterClass::S, binding - kShiftS};
  if (binding >= kShiftU) return {RegisterClass::U, binding - kShiftU};
  if (binding >= kShiftT) return {RegisterClass::T, binding - kShiftT};
  return {RegisterClass::B, binding - kShiftB};
}

}  // namespace penumbra::rhi
