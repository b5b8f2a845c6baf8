#pragma once
// glm vectors into the shader-shared vector types (shaders/shared/shader_types.h).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shader_types.h"

namespace penumbra::render {

inline gpu::float2 toFloat2(glm::vec2 v) {
  return {v.x, v.y};
}
inline gpu::float3 toFloat3(glm::vec3 v) {
  return {v.x, v.y, v.z};
}
inline gpu::float4 toFloat4(glm::vec3 v, float w = 0.0f) {
  return {v.x, v.y, v.z, w};
}
inline gpu::float4 toFloat4(glm::vec4 v) {
  return {v.x, v.y, v.z, v.w};
}

}  // namespace penumbra::render
