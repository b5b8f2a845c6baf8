#pragma once
// How a pipeline's binding layout becomes a D3D12 root signature (docs/ARCHITECTURE.md,
// "D3D12 backend"), as plain data: the mapping is written once, unit-tested on any
// platform, and backends/d3d12 only translates it into D3D12_ROOT_PARAMETER1s.
//
// Global root signature, one per pipeline:
//   parameter 0 (if the shaders have push constants): root constants, one
//     32-bit value per 4 bytes of the push-constant block, at register
//     b0 of BindingOffsets::pushConstantSpace (Penumbra's shaders:
//     PENUMBRA_PUSH_CONSTANTS in bindings.hlsli, space 900). A space of its
//     own, so it can never collide with a reflected binding.
//   then one descriptor table per non-empty space, in space order. The table
//     of space N has one range per layout item in slot order: the register
//     class and number from offsets.registerForBinding(slot) (b -> CBV, t -> SRV,
//     u -> UAV), register space N, `arraySize` descriptors, packed back to
//     back. A binding set writes its descriptors at the same offsets into its
//     range of the shader-visible CBV/SRV/UAV heap.
// Local root signature, one per shader that reads its shader record: root
//   constants at b0 of BindingOffsets::shaderRecordSpace (Penumbra's
//   shaders: PENUMBRA_SHADER_RECORD, space 901).
#include <cstdint>
#include <optional>
#include <vector>

#include "penumbra/rhi/binding_offsets.h"
#include "penumbra/rhi/pipeline.h"

namespace penumbra::rhi {

constexpr uint32_t kPushConstantRegister = 0;
constexpr uint32_t kShaderRecordRegister = 0;
// D3D12 root signatures hold at most 64 DWORDs: a root constant costs one,
// a descriptor table one.
constexpr uint32_t kMaxRootSignatureDwords = 64;

// NumDescriptors of an unbounded range (D3D12's UINT_MAX: "to the end of the heap").
constexpr uint32_t kUnboundedDescriptors = 0xffffffffu;

enum class DescriptorRangeType : uint8_t { SRV, UAV, CBV, Sampler };

// Which shader-visible heap a table points into.
enum class DescriptorHeapKind : uint8_t { CbvSrvUav, Sampler };

struct DescriptorRangeLayout {
  DescriptorRangeType type = DescriptorRangeType::SRV;
  uint32_t baseRegister = 0;   // register number within its class
  uint32_t count = 1;          // descriptors (the item's arraySize), or kUnboundedDescriptors
  uint32_t offsetInTable = 0;  // descriptors from the table's start
  uint32_t slot = 0;           // the binding slot it came from
};

struct DescriptorTableLayout {
  uint32_t space = 0;  // register space = Vulkan descriptor set
  uint32_t rootParameterIndex = 0;
  DescriptorHeapKind heap = DescriptorHeapKind::CbvSrvUav;
  // One range of kUnboundedDescriptors: the heap range a binding set needs is
  // as long as the array it binds there.
  bool unbounded = false;
  uint32_t descriptorCount = 0;  // size of the heap range a binding set needs (0 when unbounded)
  std::vector<DescriptorRangeLayout> ranges;
  // The range that holds `slot`, or nullptr.
  const DescriptorRangeLayout* rangeForSlot(uint32_t slot) const;
};

struct RootConstantsLayout {
  uint32_t rootParameterIndex = 0;
  uint32_t shaderRegister = 0;
  uint32_t registerSpace = 0;
  uint32_t num32BitValues = 0;
};

struct RootSignatureLayout {
  std::optional<RootConstantsLayout> pushConstants;
  std::vector<DescriptorTableLayout> tables;
  uint32_t dwordCost = 0;
  uint32_t parameterCount() const { return uint32_t(tables.size()) + (pushConstants ? 1u : 0u); }
  // The CBV/SRV/UAV table of the bounded items of `space`, or nullptr if the
  // shaders declare none there.
  const DescriptorTableLayout* tableForSpace(uint32_t space) const;
  // The table holding `slot` of `space` (any kind), or nullptr.
  const DescriptorTableLayout* tableForSlot(uint32_t space, uint32_t slot) const;
};

// Throws penumbra::Error when a binding cannot be expressed in D3D12: a
// constant buffer outside the b registers, an acceleration structure or a
// sampled texture outside t, a writable resource outside u, a sampler outside
// s or anything else in s, an unbounded array below another register of its
// class and space, a push-constant block that is not whole DWORDs, a binding
// in the reserved spaces, or more than 64 DWORDs in all.
RootSignatureLayout computeRootSignatureLayout(const PipelineBindingLayout& layout,
                                               const BindingOffsets& offsets);

// The local root signature of a shader whose record carries
// `shaderRecordBytes` of local data (rounded up to whole DWORDs).
RootConstantsLayout computeShaderRecordConstants(uint32_t shaderRecordBytes,
                                                 const BindingOffsets& offsets);

}  // namespace penumbra::rhi
