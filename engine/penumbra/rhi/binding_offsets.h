#pragma once
// Where the shaders put each HLSL register class among the Vulkan binding
// numbers, and which register spaces hold root constants (docs/ARCHITECTURE.md,
// "RHI"). HLSL register(tN, spaceS) is Vulkan (set S, binding
// shaderResource + N), and so on. The application that compiles the shaders
// says what it compiled them with (DeviceCreateInfo::bindingOffsets, as
// NVRHI's VulkanBindingOffsets); the RHI holds no numbers of its own. The
// D3D12 root signature maps a reflected binding back to its register with
// registerForBinding() and puts the push constants and shader records in
// their spaces (root_signature_layout.h).
#include <cstdint>

namespace penumbra::rhi {

enum class RegisterClass : uint8_t { B, T, U, S };  // CBV, SRV, UAV, sampler

struct Register {
  RegisterClass registerClass;
  uint32_t index;
};

struct BindingOffsets {
  uint32_t constantBuffer = 0;   // register(bN): binding constantBuffer + N
  uint32_t shaderResource = 0;   // register(tN)
  uint32_t unorderedAccess = 0;  // register(uN)
  uint32_t sampler = 0;          // register(sN)
  // D3D12 root constants: the push-constant block (register b0 of this
  // space) and a shader's local record data (b0 of its own space). Vulkan has
  // push constants and shader records of its own and ignores them.
  uint32_t pushConstantSpace = 0;
  uint32_t shaderRecordSpace = 0;

  // The classes must be in the order b < t < u < s, each starting above the
  // last, and the two root-constant spaces must differ: what
  // registerForBinding and the root signature rely on.
  constexpr bool valid() const {
    return constantBuffer < shaderResource && shaderResource < unorderedAccess &&
           unorderedAccess < sampler && pushConstantSpace != shaderRecordSpace;
  }

  constexpr Register registerForBinding(uint32_t binding) const {
    if (binding >= sampler) return {RegisterClass::S, binding - sampler};
    if (binding >= unorderedAccess) return {RegisterClass::U, binding - unorderedAccess};
    if (binding >= shaderResource) return {RegisterClass::T, binding - shaderResource};
    return {RegisterClass::B, binding - constantBuffer};
  }

  friend constexpr bool operator==(const BindingOffsets&, const BindingOffsets&) = default;
};

}  // namespace penumbra::rhi
