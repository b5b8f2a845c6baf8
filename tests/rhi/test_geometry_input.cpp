// rt::geometryInput (engine/penumbra/rhi/geometry_input.h): what both
// backends put into their bottom-level build descriptions, on fake buffers
// whose addresses are chosen here. No GPU.
#include <catch2/catch_test_macros.hpp>

#include "penumbra/rhi/geometry_input.h"

using namespace penumbra::rhi;

namespace {
class FakeBuffer final : public IBuffer {
 public:
  explicit FakeBuffer(uint64_t address) : address_(address) {}
  const BufferDesc& desc() const override { return desc_; }
  uint64_t deviceAddress() const override { return address_; }
  void* mappedData() override { return nullptr; }

 private:
  BufferDesc desc_;
  uint64_t address_;
};
}  // namespace

TEST_CASE("geometry input: indexed triangles with a transform", "[rhi][accel-struct]") {
  FakeBuffer vertices(0x10000), indices(0x20000), transforms(0x30000);
  rt::GeometryDesc g;
  g.type = rt::GeometryType::Triangles;
  g.flags = rt::GeometryFlags::Opaque;
  g.triangles.vertexBuffer = &vertices;
  g.triangles.vertexOffset = 16;
  g.triangles.vertexStride = 16;
  g.triangles.vertexCount = 7;
  g.triangles.indexBuffer = &indices;
  g.triangles.indexOffset = 12;
  g.triangles.indexFormat = Format::R16_UINT;
  g.triangles.indexCount = 9;
  g.triangles.transformBuffer = &transforms;
  g.triangles.transformOffset = 48;
  const rt::GeometryInput in = rt::geometryInput(g);
  CHECK(in.triangles);
  CHECK(in.opaque);
  CHECK_FALSE(in.noDuplicateAnyHitInvocation);
  CHECK(in.vertexAddress == 0x10010);
  CHECK(in.vertexStride == 16);
  CHECK(in.vertexCount == 7);
  CHECK(in.indexed);
  CHECK(in.indexFormat == Format::R16_UINT);
  CHECK(in.indexAddress == 0x2000c);
  CHECK(in.indexCount == 9);
  CHECK(in.primitiveCount == 3);  // 9 indices
  CHECK(in.transformAddress == 0x30030);
}

TEST_CASE("geometry input: a triangle list without indices or transform", "[rhi][accel-struct]") {
  FakeBuffer vertices(0x40000);
  rt::GeometryDesc g;
  g.type = rt::GeometryType::Triangles;
  g.flags = rt::GeometryFlags::NoDuplicateAnyHitInvocation;
  g.triangles.vertexBuffer = &vertices;
  g.triangles.vertexCount = 12;
  const rt::GeometryInput in = rt::geometryInput(g);
  CHECK_FALSE(in.opaque);
  CHECK(in.noDuplicateAnyHitInvocation);
  CHECK_FALSE(in.indexed);
  CHECK(in.indexAddress == 0);
  CHECK(in.indexCount == 0);
  CHECK(in.transformAddress == 0);
  CHECK(in.primitiveCount == 4);  // 12 vertices
}

TEST_CASE("geometry input: boxes", "[rhi][accel-struct]") {
  FakeBuffer boxes(0x50000);
  rt::GeometryDesc g;
  g.type = rt::GeometryType::AABBs;
  g.flags = rt::GeometryFlags::None;
  g.aabbs.buffer = &boxes;
  g.aabbs.offset = 24;
  g.aabbs.count = 5;
  g.aabbs.stride = 32;
  const rt::GeometryInput in = rt::geometryInput(g);
  CHECK_FALSE(in.triangles);
  CHECK_FALSE(in.opaque);
  CHECK(in.aabbAddress == 0x50018);
  CHECK(in.aabbStride == 32);
  CHECK(in.primitiveCount == 5);
}
