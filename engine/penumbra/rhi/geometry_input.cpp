#include "penumbra/rhi/geometry_input.h"

namespace penumbra::rhi::rt {

GeometryInput geometryInput(const GeometryDesc& geometry) {
  GeometryInput in;
  in.opaque = (uint8_t(geometry.flags) & uint8_t(GeometryFlags::Opaque)) != 0;
  in.noDuplicateAnyHitInvocation =
      (uint8_t(geometry.flags) & uint8_t(GeometryFlags::NoDuplicateAnyHitInvocation)) != 0;
  if (geometry.type == GeometryType::Triangles) {
    const GeometryTriangles& t = geometry.triangles;
    in.triangles = true;
    in.vertexFormat = t.vertexFormat;
    in.vertexAddress = t.vertexBuffer->deviceAddress() + t.vertexOffset;
    in.vertexStride = t.vertexStride;
    in.vertexCount = t.vertexCount;
    in.indexed = t.indexBuffer != nullptr;
    if (in.indexed) {
      in.indexFormat = t.indexFormat;
      in.indexAddress = t.indexBuffer->deviceAddress() + t.indexOffset;
      in.indexCount = t.indexCount;
    }
    in.primitiveCount = (in.indexed ? t.indexCount : t.vertexCount) / 3;
    if (t.transformBuffer)
      in.transformAddress = t.transformBuffer->deviceAddress() + t.transformOffset;
  } else {
    const GeometryAABBs& a = geometry.aabbs;
    in.triangles = false;
    in.aabbAddress = a.buffer->deviceAddress() + a.offset;
    in.aabbStride = a.stride;
    in.primitiveCount = a.count;
  }
  return in;
}

}  // namespace penumbra::rhi::rt
