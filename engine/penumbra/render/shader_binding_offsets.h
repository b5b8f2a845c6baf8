#pragma once
// The binding offsets Penumbra's shaders are compiled with, read from the
// one place that defines them (shaders/shared/bindings.hlsli, which the
// shaders' register declarations use), as the RHI takes them: every device
// that runs these shaders is created with
// DeviceCreateInfo::bindingOffsets = kShaderBindingOffsets.
#include "bindings.hlsli"
#include "penumbra/rhi/binding_offsets.h"

namespace penumbra::render {

constexpr rhi::BindingOffsets kShaderBindingOffsets{
    .constantBuffer = PENUMBRA_B(0),
    .shaderResource = PENUMBRA_T(0),
    .unorderedAccess = PENUMBRA_U(0),
    .sampler = PENUMBRA_S(0),
    .pushConstantSpace = PENUMBRA_PUSH_CONSTANT_SPACE,
    .shaderRecordSpace = PENUMBRA_SHADER_RECORD_SPACE,
};
static_assert(kShaderBindingOffsets.valid(),
              "bindings.hlsli: register classes out of order or one space for both root constants");

}  // namespace penumbra::render
