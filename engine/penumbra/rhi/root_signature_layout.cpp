#include "penumbra/rhi/root_signature_layout.h"

#include <fmt/format.h>

#include "penumbra/util/error.h"

namespace penumbra::rhi {
namespace {

const char* className(RegisterClass c) {
  switch (c) {
    case RegisterClass::B:
      return "b";
    case RegisterClass::T:
      return "t";
    case RegisterClass::U:
      return "u";
    case RegisterClass::S:
      return "s";
  }
  return "?";
}

DescriptorRangeType rangeTypeFor(const BindingLayoutItem& item, uint32_t space,
                                 const BindingOffsets& offsets) {
  const Register reg = offsets.registerForBinding(item.slot);
  auto fail = [&](const char* why) {
    return Error(fmt::format("root signature: '{}' (space {}, slot {} = register {}{}) {}",
                             item.name, space, item.slot, className(reg.registerClass), reg.index,
                             why));
  };
  if (item.type == ResourceType::Sampler) {
    if (reg.registerClass != RegisterClass::S) throw fail("is a sampler outside the s registers");
    return DescriptorRangeType::Sampler;
  }
  if (reg.registerClass == RegisterClass::S)
    throw fail("is not a sampler but lies in the sampler (s) registers");
  switch (item.type) {
    case ResourceType::ConstantBuffer:
      if (reg.registerClass != RegisterClass::B)
        throw fail("is a constant buffer outside the b registers");
      return DescriptorRangeType::CBV;
    case ResourceType::AccelStruct:
      if (reg.registerClass != RegisterClass::T)
        throw fail("is an acceleration structure outside the t registers");
      return DescriptorRangeType::SRV;
    case ResourceType::StorageBuffer:
    case ResourceType::StorageTexture:
      if (reg.registerClass == RegisterClass::U) return DescriptorRangeType::UAV;
      if (reg.registerClass != RegisterClass::T)
        throw fail("is a storage resource in the b registers");
      if (item.writable)
        throw fail("is written by the shaders but lies in the read-only t registers");
      return DescriptorRangeType::SRV;
    case ResourceType::SampledTexture:
      if (reg.registerClass != RegisterClass::T)
        throw fail("is a sampled texture outside the t registers");
      return DescriptorRangeType::SRV;
    case ResourceType::Sampler:
      break;
  }
  throw fail("has an unknown resource type");
}

// An unbounded range claims every register of its class from its base up,
// so another binding of the class above it in the same space would overlap.
void checkUnboundedIsLast(const BindingLayoutItem& item, const BindingLayout& space,
                          const BindingOffsets& offsets) {
  const Register reg = offsets.registerForBinding(item.slot);
  for (const auto& other : space.items) {
    const Register o = offsets.registerForBinding(other.slot);
    if (other.slot != item.slot && o.registerClass == reg.registerClass && o.index > reg.index)
      throw Error(fmt::format(
          "root signature: unbounded array '{}' (space {}, register {}{}) would overlap "
          "'{}' at register {}{}; an unbounded array must have the highest register "
          "of its class in its space",
          item.name, space.space, className(reg.registerClass), reg.index, other.name,
          className(o.registerClass), o.index));
  }
}

}  // namespace

const DescriptorRangeLayout* DescriptorTableLayout::rangeForSlot(uint32_t slot) const {
  for (const auto& r : ranges)
    if (r.slot == slot) return &r;
  return nullptr;
}

const DescriptorTableLayout* RootSignatureLayout::tableForSpace(uint32_t space) const {
  for (const auto& t : tables)
    if (t.space == space && t.heap == DescriptorHeapKind::CbvSrvUav && !t.unbounded) return &t;
  return nullptr;
}

const DescriptorTableLayout* RootSignatureLayout::tableForSlot(uint32_t space,
                                                               uint32_t slot) const {
  for (const auto& t : tables)
    if (t.space == space && t.rangeForSlot(slot)) return &t;
  return nullptr;
}

RootSignatureLayout computeRootSignatureLayout(const PipelineBindingLayout& layout,
                                               const BindingOffsets& offsets) {
  RootSignatureLayout result;
  uint32_t parameter = 0;
  if (layout.pushConstantBytes > 0) {
    if (layout.pushConstantBytes % 4 != 0)
      throw Error(fmt::format("root signature: push constants of {} bytes are not whole DWORDs",
                              layout.pushConstantBytes));
    result.pushConstants =
        RootConstantsLayout{parameter++, kPushConstantRegister, offsets.pushConstantSpace,
                            layout.pushConstantBytes / 4};
    result.dwordCost += result.pushConstants->num32BitValues;
  }
  for (const auto& space : layout.spaces) {
    if (space.items.empty()) continue;
    if (space.space == offsets.pushConstantSpace || space.space == offsets.shaderRecordSpace)
      throw Error(
          fmt::format("root signature: space {} is reserved for root constants", space.space));
    DescriptorTableLayout views, samplers;
    views.space = samplers.space = space.space;
    samplers.heap = DescriptorHeapKind::Sampler;
    std::vector<DescriptorTableLayout> unbounded;
    for (const auto& item : space.items) {
      DescriptorRangeLayout range;
      range.type = rangeTypeFor(item, space.space, offsets);
      range.baseRegister = offsets.registerForBinding(item.slot).index;
      range.slot = item.slot;
      if (item.arraySize == 0) {
        checkUnboundedIsLast(item, space, offsets);
        DescriptorTableLayout table;
        table.space = space.space;
        table.heap = range.type == DescriptorRangeType::Sampler ? DescriptorHeapKind::Sampler
                                                                : DescriptorHeapKind::CbvSrvUav;
        table.unbounded = true;
        range.count = kUnboundedDescriptors;
        table.ranges.push_back(range);
        unbounded.push_back(std::move(table));
        continue;
      }
      auto& table = range.type == DescriptorRangeType::Sampler ? samplers : views;
      range.count = item.arraySize;
      range.offsetInTable = table.descriptorCount;
      table.descriptorCount += item.arraySize;
      table.ranges.push_back(range);
    }
    // Table order within a space: views, samplers, then the unbounded arrays.
    std::vector<DescriptorTableLayout> tables;
    for (auto* table : {&views, &samplers})
      if (!table->ranges.empty()) tables.push_back(std::move(*table));
    for (auto& table : unbounded) tables.push_back(std::move(table));
    for (auto& table : tables) {
      table.rootParameterIndex = parameter++;
      result.tables.push_back(std::move(table));
      result.dwordCost += 1;
    }
  }
  if (result.dwordCost > kMaxRootSignatureDwords)
    throw Error(fmt::format(
        "root signature: {} DWORDs exceed D3D12's limit of {} (push constants: {} "
        "bytes, {} descriptor tables)",
        result.dwordCost, kMaxRootSignatureDwords, layout.pushConstantBytes, result.tables.size()));
  return result;
}

RootConstantsLayout computeShaderRecordConstants(uint32_t shaderRecordBytes,
                                                 const BindingOffsets& offsets) {
  return {0, kShaderRecordRegister, offsets.shaderRecordSpace, (shaderRecordBytes + 3) / 4};
}

}  // namespace penumbra::rhi
