#pragma once
// Combining the shaders' reflected layouts into a pipeline's, and checking
// binding sets against it. Backend-independent, no SPIR-V tooling: the
// layouts come from the build (ShaderDesc::bindingLayout).
#include <string>

#include "penumbra/rhi/pipeline.h"

namespace penumbra::rhi {

// Adds what one shader declares to a pipeline's layout. A slot declared by
// several shaders must agree in type and array size, else penumbra::Error
// naming both variables; writable wins if any shader writes the slot.
void mergeBindingLayout(PipelineBindingLayout& pipeline, const PipelineBindingLayout& shader,
                        const std::string& shaderName);

// Adds one item to `space` of a layout (kept sorted by slot), with the same
// agreement rule as mergeBindingLayout.
void addBindingLayoutItem(PipelineBindingLayout& layout, uint32_t space, BindingLayoutItem item,
                          const std::string& shaderName);

// Checks a binding set against the layout of its space: every slot of the
// layout filled once with a resource of the right type, no unknown slots;
// texture and sampler arrays with arraySize elements (fixed arrays) or 1 ..
// kMaxBindlessDescriptors (unbounded arrays), textures with Sampled usage.
// Throws penumbra::Error naming the slot and shader variable otherwise.
void validateBindingSet(const BindingSetDesc& set, const PipelineBindingLayout& layout);

}  // namespace penumbra::rhi
