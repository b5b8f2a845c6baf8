#include "penumbra/rhi/shader_reflection.h"

#include <fmt/format.h>

#include <algorithm>
#include <spirv_cross/spirv_cross.hpp>

#include "penumbra/util/error.h"

namespace penumbra::rhi {
namespace {

// SPIRV-Cross gives a runtime array (`texture2D t[]`) the size 0, which is
// also the RHI's mark of an unbounded array.
uint32_t arraySizeOf(const spirv_cross::Compiler& compiler, const spirv_cross::Resource& resource,
                     const std::string& moduleName) {
  const auto& type = compiler.get_type(resource.type_id);
  if (type.array.size() > 1)
    throw Error(
        fmt::format("shader '{}': '{}' is a multi-dimensional array, which the RHI does not model",
                    moduleName, resource.name));
  if (!type.array.empty() && !type.array_size_literal[0])
    throw Error(
        fmt::format("shader '{}': '{}' is sized by a specialization constant, which the RHI does "
                    "not model",
                    moduleName, resource.name));
  return type.array.empty() ? 1u : type.array[0];
}

// The element size of the (RW)StructuredBuffer<T> a storage block stands for:
// a trailing runtime array's stride (`buffer B { T data[]; }`), else the
// whole block (`buffer B { uint count; }` is a one-element buffer).
uint32_t structureStrideOf(const spirv_cross::Compiler& compiler, const spirv_cross::Resource& r) {
  const auto& block = compiler.get_type(r.base_type_id);
  if (!block.member_types.empty()) {
    const uint32_t last = uint32_t(block.member_types.size() - 1);
    const auto& member = compiler.get_type(block.member_types[last]);
    if (!member.array.empty() && member.array.back() == 0)
      return compiler.type_struct_member_array_stride(block, last);
  }
  return uint32_t(compiler.get_declared_struct_size(block));
}

}  // namespace

ShaderReflection reflectSpirvModule(std::span<const uint32_t> spirv,
                                    const std::string& moduleName) {
  if (spirv.empty()) throw Error(fmt::format("shader '{}': no SPIR-V to reflect", moduleName));
  spirv_cross::Compiler compiler(spirv.data(), spirv.size());
  auto resources = compiler.get_shader_resources();
  ShaderReflection result;

  auto add = [&](const spirv_cross::SmallVector<spirv_cross::Resource>& list, ResourceType type,
                 bool storage) {
    for (const auto& r : list) {
      BindingLayoutItem item;
      item.slot = compiler.get_decoration(r.id, spv::DecorationBinding);
      item.type = type;
      item.arraySize = arraySizeOf(compiler, r, moduleName);
      item.name = r.name.empty() ? compiler.get_name(r.base_type_id) : r.name;
      if (storage) {
        const bool readOnly =
            type == ResourceType::StorageTexture
                ? compiler.get_decoration_bitset(r.id).get(spv::DecorationNonWritable)
                : compiler.get_buffer_block_flags(r.id).get(spv::DecorationNonWritable);
        item.writable = !readOnly;
      }
      if (type == ResourceType::StorageBuffer)
        item.structureStride = structureStrideOf(compiler, r);
      addBindingLayoutItem(result.layout,
                           compiler.get_decoration(r.id, spv::DecorationDescriptorSet),
                           std::move(item), moduleName);
    }
  };
  add(resources.acceleration_structures, ResourceType::AccelStruct, false);
  add(resources.storage_buffers, ResourceType::StorageBuffer, true);
  add(resources.uniform_buffers, ResourceType::ConstantBuffer, false);
  add(resources.storage_images, ResourceType::StorageTexture, true);
  add(resources.separate_images, ResourceType::SampledTexture, false);
  add(resources.separate_samplers, ResourceType::Sampler, false);
  // HLSL has no combined image-samplers, so the portable dialect cannot use them.
  if (!resources.sampled_images.empty())
    throw Error(
        fmt::format("shader '{}': '{}' is a combined image sampler (sampler2D); declare a "
                    "texture2D and a sampler separately (HLSL Texture2D + SamplerState)",
                    moduleName, resources.sampled_images[0].name));
  for (const auto& pc : resources.push_constant_buffers) {
    const auto& type = compiler.get_type(pc.base_type_id);
    result.layout.pushConstantBytes = std::max(result.layout.pushConstantBytes,
                                               uint32_t(compiler.get_declared_struct_size(type)));
  }
  for (const auto& record : resources.shader_record_buffers) {
    const auto& type = compiler.get_type(record.base_type_id);
    result.shaderRecordBytes =
        std::max(result.shaderRecordBytes, uint32_t(compiler.get_declared_struct_size(type)));
  }
  return result;
}

void reflectSpirv(std::span<const uint32_t> spirv, const std::string& moduleName,
                  PipelineBindingLayout& layout) {
  mergeBindingLayout(layout, reflectSpirvModule(spirv, moduleName).layout, moduleName);
}

}  // namespace penumbra::rhi
