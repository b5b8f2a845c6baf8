#include "rhi/shader_reflection.h"

#include <fmt/format.h>

#include <algorithm>
#include <spirv_cross/spirv_cross.hpp>

#include "util/error.h"

namespace penumbra::rhi {
namespace {

void addItem(PipelineBindingLayout& layout, uint32_t space, BindingLayoutItem item,
             const std::string& moduleName) {
  if (layout.spaces.size() <= space) layout.spaces.resize(space + 1);
  for (uint32_t i = 0; i < layout.spaces.size(); ++i) layout.spaces[i].space = i;
  auto& items = layout.spaces[space].items;
  auto existing = std::find_if(items.begin(), items.end(),
                               [&](const BindingLayoutItem& it) { return it.slot == item.slot; });
  if (existing != items.end()) {
    if (existing->type != item.type || existing->arraySize != item.arraySize)
      throw Error(fmt::format("shader '{}': binding (space {}, slot {}) '{}' is a {} but another "
                              "shader declares '{}' there as a {}",
                              moduleName, space, item.slot, item.name, resourceTypeName(item.type),
                              existing->name, resourceTypeName(existing->type)));
    existing->writable = existing->writable || item.writable;
    return;
  }
  items.push_back(std::move(item));
  std::sort(items.begin(), items.end(),
            [](const BindingLayoutItem& a, const BindingLayoutItem& b) { return a.slot < b.slot; });
}

uint32_t arraySizeOf(const spirv_cross::Compiler& compiler, const spirv_cross::Resource& resource) {
  const auto& type = compiler.get_type(resource.type_id);
  return type.array.empty() ? 1u : type.array[0];
}

}  // namespace

void reflectSpirv(std::span<const uint32_t> spirv, const std::string& moduleName,
                  PipelineBindingLayout& layout) {
  spirv_cross::Compiler compiler(spirv.data(), spirv.size());
  auto resources = compiler.get_shader_resources();

  auto add = [&](const spirv_cross::SmallVector<spirv_cross::Resource>& list, ResourceType type,
                 bool storage) {
    for (const auto& r : list) {
      BindingLayoutItem item;
      item.slot = compiler.get_decoration(r.id, spv::DecorationBinding);
      item.type = type;
      item.arraySize = arraySizeOf(compiler, r);
      item.name = r.name.empty() ? compiler.get_name(r.base_type_id) : r.name;
      if (storage) {
        const bool readOnly = type == ResourceType::StorageTexture
                                  ? compiler.get_decoration_bitset(r.id).get(spv::DecorationNonWritable)
                                  : compiler.get_buffer_block_flags(r.id).get(spv::DecorationNonWritable);
        item.writable = !readOnly;
      }
      addItem(layout, compiler.get_decoration(r.id, spv::DecorationDescriptorSet), std::move(item),
              moduleName);
    }
  };
  add(resources.acceleration_structures, ResourceType::AccelStruct, false);
  add(resources.storage_buffers, ResourceType::StorageBuffer, true);
  add(resources.uniform_buffers, ResourceType::ConstantBuffer, false);
  add(resources.storage_images, ResourceType::StorageTexture, true);
  if (!resources.sampled_images.empty() || !resources.separate_images.empty() ||
      !resources.separate_samplers.empty())
    throw Error(fmt::format("shader '{}': sampled textures are not supported by the RHI yet",
                            moduleName));
  for (const auto& pc : resources.push_constant_buffers) {
    const auto& type = compiler.get_type(pc.base_type_id);
    layout.pushConstantBytes =
        std::max(layout.pushConstantBytes, uint32_t(compiler.get_declared_struct_size(type)));
  }
}

void validateBindingSet(const BindingSetDesc& set, const PipelineBindingLayout& layout) {
  const std::string setName = set.debugName.empty() ? "binding set" : set.debugName;
  if (set.space >= layout.spaces.size() || layout.spaces[set.space].items.empty()) {
    if (set.items.empty()) return;
    throw Error(fmt::format("{}: the pipeline's shaders declare nothing in space {}", setName,
                            set.space));
  }
  const auto& expected = layout.spaces[set.space].items;
  for (const auto& item : set.items) {
    auto it = std::find_if(expected.begin(), expected.end(),
                           [&](const BindingLayoutItem& e) { return e.slot == item.slot; });
    if (it == expected.end())
      throw Error(fmt::format("{}: slot {} is not declared by the pipeline's shaders", setName,
                              item.slot));
    if (it->type != item.type)
      throw Error(fmt::format("{}: slot {} ('{}') is a {} in the shaders but a {} was bound",
                              setName, item.slot, it->name, resourceTypeName(it->type),
                              resourceTypeName(item.type)));
    const bool empty = (item.type == ResourceType::AccelStruct && !item.accelStruct) ||
                       (item.type == ResourceType::StorageTexture && !item.texture) ||
                       ((item.type == ResourceType::StorageBuffer ||
                         item.type == ResourceType::ConstantBuffer) &&
                        !item.buffer);
    if (empty)
      throw Error(fmt::format("{}: slot {} ('{}') is bound to nothing", setName, item.slot,
                              it->name));
  }
  for (const auto& e : expected) {
    auto count = std::count_if(set.items.begin(), set.items.end(),
                               [&](const BindingSetItem& i) { return i.slot == e.slot; });
    if (count != 1)
      throw Error(fmt::format("{}: slot {} ('{}') is bound {} times, expected once", setName,
                              e.slot, e.name, count));
  }
}

}  // namespace penumbra::rhi
