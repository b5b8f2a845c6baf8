#pragma once
// Derives a shader's binding layout from its SPIR-V (SPIRV-Cross), so the
// layout is never written a second time by hand. Runs on the build machine
// (tools/shader_layout writes the result beside the embedded SPIR-V) and in
// Linux tests; the engine and the backends take the build-time result from
// ShaderDesc::bindingLayout and never link SPIRV-Cross.
#include <cstdint>
#include <span>
#include <string>

#include "penumbra/rhi/binding_layout.h"

namespace penumbra::rhi {

struct ShaderReflection {
  PipelineBindingLayout layout;
  uint32_t shaderRecordBytes = 0;  // size of the shaderRecordEXT block, 0 if none
};

// What one SPIR-V module declares: separate images (texture2D) become
// SampledTexture items, separate samplers Sampler items, runtime arrays
// arraySize 0. Throws penumbra::Error for what the RHI does not model
// (combined image samplers, multi-dimensional or spec-constant-sized arrays).
ShaderReflection reflectSpirvModule(std::span<const uint32_t> spirv, const std::string& moduleName);

// Adds the resources one SPIR-V module declares to `layout`
// (reflectSpirvModule + mergeBindingLayout).
void reflectSpirv(std::span<const uint32_t> spirv, const std::string& moduleName,
                  PipelineBindingLayout& layout);

}  // namespace penumbra::rhi
