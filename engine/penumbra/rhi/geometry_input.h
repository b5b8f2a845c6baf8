#pragma once
// A bottom-level geometry as both APIs take it to build an acceleration
// structure: device addresses, counts and flags resolved from
// rt::GeometryDesc once, so a backend only spells them in its own structs
// (D3D12: D3D12_RAYTRACING_GEOMETRY_DESC; Vulkan:
// VkAccelerationStructureGeometryKHR + its build range).
#include <cstdint>

#include "penumbra/rhi/resources.h"

namespace penumbra::rhi::rt {

struct GeometryInput {
  bool triangles = true;  // else axis-aligned boxes
  bool opaque = false;
  bool noDuplicateAnyHitInvocation = false;
  uint32_t primitiveCount = 0;  // triangles (indices / 3, or vertices / 3) or boxes

  // Triangles.
  Format vertexFormat = Format::RGB32_FLOAT;
  uint64_t vertexAddress = 0;
  uint32_t vertexStride = 0;
  uint32_t vertexCount = 0;
  bool indexed = false;
  Format indexFormat = Format::R32_UINT;
  uint64_t indexAddress = 0;
  uint32_t indexCount = 0;
  uint64_t transformAddress = 0;  // 0: none

  // Boxes.
  uint64_t aabbAddress = 0;
  uint32_t aabbStride = 0;
};

GeometryInput geometryInput(const GeometryDesc& geometry);

}  // namespace penumbra::rhi::rt
