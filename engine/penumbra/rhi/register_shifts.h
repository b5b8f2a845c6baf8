#pragma once
// One register-to-binding shift table for both APIs (docs/ARCHITECTURE.md, "RHI"):
// HLSL register(tN, spaceS) is Vulkan (set S, binding kShiftT + N), and so on.
// The numbers are defined once, in shaders/shared/bindings.hlsli, which the
// shaders' declarations use; the D3D12 root signature maps a reflected
// binding back to its register with registerForBinding().
#include <cstdint>

#include "bindings.hlsli"

namespace penumbra::rhi {

enum class RegisterClass : uint8_t { B, T, U, S };  // CBV, SRV, UAV, sampler

// The register spaces of the push constants and of shader records (D3D12
// root constants; root_signature_layout.h).
constexpr uint32_t kPushConstantSpace = PENUMBRA_PUSH_CONSTANT_SPACE;
constexpr uint32_t kShaderRecordSpace = PENUMBRA_SHADER_RECORD_SPACE;

constexpr uint32_t kShiftB = PENUMBRA_B(0);
constexpr uint32_t kShiftT = PENUMBRA_T(0);
constexpr uint32_t kShiftU = PENUMBRA_U(0);
constexpr uint32_t kShiftS = PENUMBRA_S(0);
static_assert(kShiftB < kShiftT && kShiftT < kShiftU && kShiftU < kShiftS,
              "registerForBinding needs the classes in this order");

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
