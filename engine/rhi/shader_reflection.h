#pragma once
// Derives a pipeline's binding layout from its shaders' SPIR-V (SPIRV-Cross),
// so the layout is never written a second time by hand.
#include <cstdint>
#include <span>

#include "rhi/pipeline.h"

namespace penumbra::rhi {

// Adds the resources one SPIR-V module declares to `layout`. A slot declared by
// several modules must agree in type and array size, else penumbra::Error.
void reflectSpirv(std::span<const uint32_t> spirv, const std::string& moduleName,
                  PipelineBindingLayout& layout);

// Checks a binding set against the layout of its space: every slot of the
// layout filled once with a resource of the right type, no unknown slots.
// Throws penumbra::Error naming the slot and shader variable otherwise.
void validateBindingSet(const BindingSetDesc& set, const PipelineBindingLayout& layout);

}  // namespace penumbra::rhi
