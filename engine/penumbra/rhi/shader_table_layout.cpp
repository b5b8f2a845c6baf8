#include "penumbra/rhi/shader_table_layout.h"

#include <fmt/format.h>

#include "penumbra/util/error.h"

namespace penumbra::rhi {
namespace {
uint64_t recordStride(const ShaderTableAlignment& a, uint32_t localBytes, const char* region) {
  uint64_t stride = alignUp(uint64_t(a.handleSize) + localBytes, a.recordAlignment);
  if (stride > a.maxRecordStride)
    throw Error(fmt::format("shader table: {} record of {} bytes exceeds the maximum stride {}",
                            region, stride, a.maxRecordStride));
  return stride;
}
}  // namespace

ShaderTableLayout computeShaderTableLayout(const ShaderTableAlignment& alignment,
                                           uint32_t rayGenLocalBytes, uint32_t missCount,
                                           uint32_t missLocalBytes, uint32_t hitGroupCount,
                                           uint32_t hitGroupLocalBytes) {
  ShaderTableLayout layout;
  uint64_t cursor = 0;
  auto place = [&](ShaderTableRegion& region, uint32_t count, uint32_t localBytes,
                   const char* name) {
    region.count = count;
    region.stride = recordStride(alignment, localBytes, name);
    region.offset = alignUp(cursor, alignment.tableAlignment);
    region.size = region.stride * count;
    if (count > 0) cursor = region.offset + region.size;
  };
  place(layout.rayGeneration, 1, rayGenLocalBytes, "ray generation");
  place(layout.miss, missCount, missLocalBytes, "miss");
  place(layout.hitGroup, hitGroupCount, hitGroupLocalBytes, "hit group");
  layout.totalBytes = alignUp(cursor, alignment.tableAlignment);
  return layout;
}

}  // namespace penumbra::rhi
