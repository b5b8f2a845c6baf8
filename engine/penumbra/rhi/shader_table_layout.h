#pragma once
// Where each record of a shader table goes, given an API's alignment rules.
// Shared by both backends so the arithmetic is written (and tested) once.
//
// D3D12: records are 32-byte aligned (D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT),
// each table starts 64-byte aligned (..._SHADER_TABLE_BYTE_ALIGNMENT),
// identifiers are 32 bytes.
// Vulkan: records are shaderGroupHandleAlignment aligned, regions start
// shaderGroupBaseAlignment aligned, and the raygen region's size must equal
// its stride.
#include <cstdint>
#include <vector>

#include "penumbra/rhi/device.h"

namespace penumbra::rhi {

struct ShaderTableRegion {
  uint64_t offset = 0;  // from the start of the table buffer
  uint64_t stride = 0;  // bytes per record
  uint64_t size = 0;    // stride * count (0 when the region is empty)
  uint32_t count = 0;
};

struct ShaderTableLayout {
  ShaderTableRegion rayGeneration;
  ShaderTableRegion miss;
  ShaderTableRegion hitGroup;
  uint64_t totalBytes = 0;
};

// localBytes*: the largest local data of any record in that region.
// Throws penumbra::Error if a record exceeds the API's maximum stride.
ShaderTableLayout computeShaderTableLayout(const ShaderTableAlignment& alignment,
                                           uint32_t rayGenLocalBytes, uint32_t missCount,
                                           uint32_t missLocalBytes, uint32_t hitGroupCount,
                                           uint32_t hitGroupLocalBytes);

constexpr uint64_t alignUp(uint64_t value, uint64_t alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace penumbra::rhi
