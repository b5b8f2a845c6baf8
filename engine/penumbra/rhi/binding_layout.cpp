#include "penumbra/rhi/binding_layout.h"

#include <fmt/format.h>

#include <algorithm>

#include "penumbra/util/error.h"

namespace penumbra::rhi {

void addBindingLayoutItem(PipelineBindingLayout& layout, uint32_t space, BindingLayoutItem item,
                          const std::string& shaderName) {
  if (layout.spaces.size() <= space) layout.spaces.resize(space + 1);
  for (uint32_t i = 0; i < layout.spaces.size(); ++i) layout.spaces[i].space = i;
  auto& items = layout.spaces[space].items;
  auto existing = std::find_if(items.begin(), items.end(),
                               [&](const BindingLayoutItem& it) { return it.slot == item.slot; });
  if (existing != items.end()) {
    if (existing->type != item.type || existing->arraySize != item.arraySize ||
        existing->structureStride != item.structureStride)
      throw Error(
          fmt::format("shader '{}': binding (space {}, slot {}) '{}' is a {} but another "
                      "shader declares '{}' there as a {}",
                      shaderName, space, item.slot, item.name, resourceTypeName(item.type),
                      existing->name, resourceTypeName(existing->type)));
    existing->writable = existing->writable || item.writable;
    return;
  }
  items.push_back(std::move(item));
  std::sort(items.begin(), items.end(),
            [](const BindingLayoutItem& a, const BindingLayoutItem& b) { return a.slot < b.slot; });
}

void mergeBindingLayout(PipelineBindingLayout& pipeline, const PipelineBindingLayout& shader,
                        const std::string& shaderName) {
  for (const auto& space : shader.spaces)
    for (const auto& item : space.items)
      addBindingLayoutItem(pipeline, space.space, item, shaderName);
  pipeline.pushConstantBytes = std::max(pipeline.pushConstantBytes, shader.pushConstantBytes);
}

namespace {

// Texture and sampler items carry one handle per array element: exactly
// arraySize of them for a fixed array, 1..kMaxBindlessDescriptors for an
// unbounded one, none null, textures created for sampling.
void validateArrayItem(const std::string& setName, const BindingSetItem& item,
                       const BindingLayoutItem& expected) {
  const size_t count = item.elementCount();
  const char* what = item.type == ResourceType::Sampler ? "samplers" : "textures";
  if (expected.arraySize == 0) {
    if (count == 0 || count > kMaxBindlessDescriptors)
      throw Error(
          fmt::format("{}: slot {} ('{}') is an unbounded array and takes 1 to {} {}, "
                      "but {} were bound",
                      setName, item.slot, expected.name, kMaxBindlessDescriptors, what, count));
  } else if (count != expected.arraySize) {
    throw Error(
        fmt::format("{}: slot {} ('{}') is an array of {} {} in the shaders, but {} were "
                    "bound",
                    setName, item.slot, expected.name, expected.arraySize, what, count));
  }
  for (size_t i = 0; i < count; ++i) {
    const bool null =
        item.type == ResourceType::Sampler ? !item.samplerHandles[i] : !item.textures[i];
    if (null)
      throw Error(fmt::format("{}: slot {} ('{}') element {} is bound to nothing", setName,
                              item.slot, expected.name, i));
    if (item.type == ResourceType::SampledTexture &&
        !hasFlag(item.textures[i]->desc().usage, TextureUsage::Sampled))
      throw Error(
          fmt::format("{}: slot {} ('{}') element {}: texture '{}' was not created with "
                      "TextureUsage::Sampled",
                      setName, item.slot, expected.name, i, item.textures[i]->desc().debugName));
  }
}

}  // namespace

void validateBindingSet(const BindingSetDesc& set, const PipelineBindingLayout& layout) {
  const std::string setName = set.debugName.empty() ? "binding set" : set.debugName;
  if (set.space >= layout.spaces.size() || layout.spaces[set.space].items.empty()) {
    if (set.items.empty()) return;
    throw Error(
        fmt::format("{}: the pipeline's shaders declare nothing in space {}", setName, set.space));
  }
  const auto& expected = layout.spaces[set.space].items;
  for (const auto& item : set.items) {
    auto it = std::find_if(expected.begin(), expected.end(),
                           [&](const BindingLayoutItem& e) { return e.slot == item.slot; });
    if (it == expected.end())
      throw Error(
          fmt::format("{}: slot {} is not declared by the pipeline's shaders", setName, item.slot));
    if (it->type != item.type)
      throw Error(fmt::format("{}: slot {} ('{}') is a {} in the shaders but a {} was bound",
                              setName, item.slot, it->name, resourceTypeName(it->type),
                              resourceTypeName(item.type)));
    if (item.type == ResourceType::SampledTexture || item.type == ResourceType::Sampler)
      validateArrayItem(setName, item, *it);
    const bool empty =
        (item.type == ResourceType::AccelStruct && !item.accelStruct) ||
        (item.type == ResourceType::StorageTexture && !item.texture) ||
        ((item.type == ResourceType::StorageBuffer || item.type == ResourceType::ConstantBuffer) &&
         !item.buffer);
    if (empty)
      throw Error(
          fmt::format("{}: slot {} ('{}') is bound to nothing", setName, item.slot, it->name));
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
