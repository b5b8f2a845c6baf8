#include "penumbra/render/implicit_geometry.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace penumbra::render {
namespace {

namespace shapes = scene::implicit;
using scene::ImplicitKind;

template <class Vec>
auto largestComponent(Vec v) {
  return std::max(v.x, std::max(v.y, v.z));
}

ObjectBounds symmetric(glm::vec3 halfExtents) {
  return {-halfExtents, halfExtents};
}

ObjectBounds blendableBounds(
    const std::variant<shapes::Sphere, shapes::Box, shapes::Torus, shapes::RoundedBox>& shape) {
  struct Visitor {
    ObjectBounds operator()(const shapes::Sphere& s) const {
      return symmetric(glm::vec3(s.radius));
    }
    ObjectBounds operator()(const shapes::Box& b) const { return symmetric(b.halfExtents); }
    ObjectBounds operator()(const shapes::RoundedBox& b) const { return symmetric(b.halfExtents); }
    ObjectBounds operator()(const shapes::Torus& t) const {
      const float outer = t.majorRadius + t.minorRadius;
      return symmetric({outer, t.minorRadius, outer});
    }
  };
  return std::visit(Visitor{}, shape);
}

// The set lies in the ball of radius max(1, 2^(1/(n-1))): beyond it |z|
// grows every iteration (|z^n + c| >= |z|^n - |c| > |z|). 10% more keeps the
// bounds' surface where points escape within a few iterations, so the
// estimator is positive and well clear of the tolerance there.
float mandelbulbRadius(float power) {
  return 1.1f * std::max(1.0f, std::pow(2.0f, 1.0f / (power - 1.0f)));
}

ObjectBounds unpaddedBounds(const scene::ImplicitObject& object) {
  struct Visitor {
    ObjectBounds operator()(const shapes::Sphere& s) const {
      return symmetric(glm::vec3(s.radius));
    }
    ObjectBounds operator()(const shapes::Plane& p) const {
      const glm::vec2 h = p.halfExtents.value_or(glm::vec2(kUnboundedPlaneHalfExtent));
      return symmetric({h.x, 0.0f, h.y});
    }
    ObjectBounds operator()(const shapes::Box& b) const { return symmetric(b.halfExtents); }
    ObjectBounds operator()(const shapes::Torus& t) const { return blendableBounds(t); }
    ObjectBounds operator()(const shapes::RoundedBox& b) const { return blendableBounds(b); }
    ObjectBounds operator()(const shapes::Blend& b) const {
      ObjectBounds all{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
      for (const auto& primitive : b.primitives) {
        const ObjectBounds one = blendableBounds(primitive.shape);
        all.lo = glm::min(all.lo, one.lo + primitive.offset);
        all.hi = glm::max(all.hi, one.hi + primitive.offset);
      }
      // Each smooth minimum reaches at most blendRadius / 4 below the union.
      const float bulge = float(b.primitives.size() - 1) * 0.25f * b.blendRadius;
      return {all.lo - glm::vec3(bulge), all.hi + glm::vec3(bulge)};
    }
    ObjectBounds operator()(const shapes::Mandelbulb& m) const {
      return symmetric(glm::vec3(mandelbulbRadius(m.power)));
    }
  };
  return std::visit(Visitor{}, object.shape);
}

gpu::float4 blendableParameters(
    const std::variant<shapes::Sphere, shapes::Box, shapes::Torus, shapes::RoundedBox>& shape) {
  struct Visitor {
    gpu::float4 operator()(const shapes::Sphere& s) const { return {s.radius, 0, 0, 0}; }
    gpu::float4 operator()(const shapes::Box& b) const {
      return {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z, 0};
    }
    gpu::float4 operator()(const shapes::Torus& t) const {
      return {t.majorRadius, t.minorRadius, 0, 0};
    }
    gpu::float4 operator()(const shapes::RoundedBox& b) const {
      return {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z, b.cornerRadius};
    }
  };
  return std::visit(Visitor{}, shape);
}

// Matches IMPLICIT_* (static_asserted below).
uint32_t blendableKind(
    const std::variant<shapes::Sphere, shapes::Box, shapes::Torus, shapes::RoundedBox>& shape) {
  constexpr uint32_t kinds[] = {IMPLICIT_SPHERE, IMPLICIT_BOX, IMPLICIT_TORUS,
                                IMPLICIT_ROUNDED_BOX};
  return kinds[shape.index()];
}

static_assert(uint32_t(ImplicitKind::Sphere) == IMPLICIT_SPHERE);
static_assert(uint32_t(ImplicitKind::Plane) == IMPLICIT_PLANE);
static_assert(uint32_t(ImplicitKind::Box) == IMPLICIT_BOX);
static_assert(uint32_t(ImplicitKind::Torus) == IMPLICIT_TORUS);
static_assert(uint32_t(ImplicitKind::RoundedBox) == IMPLICIT_ROUNDED_BOX);
static_assert(uint32_t(ImplicitKind::Blend) == IMPLICIT_BLEND);
static_assert(uint32_t(ImplicitKind::Mandelbulb) == IMPLICIT_MANDELBULB);
static_assert(scene::implicit::Blend::kMaxPrimitives == IMPLICIT_MAX_BLEND_PRIMITIVES);

gpu::float4 shapeParameters(const scene::ImplicitObject& object) {
  struct Visitor {
    gpu::float4 operator()(const shapes::Sphere& s) const { return blendableParameters(s); }
    gpu::float4 operator()(const shapes::Plane& p) const {
      const glm::vec2 h = p.halfExtents.value_or(glm::vec2(kUnboundedPlaneHalfExtent));
      return {h.x, h.y, 0, 0};
    }
    gpu::float4 operator()(const shapes::Box& b) const { return blendableParameters(b); }
    gpu::float4 operator()(const shapes::Torus& t) const { return blendableParameters(t); }
    gpu::float4 operator()(const shapes::RoundedBox& b) const { return blendableParameters(b); }
    gpu::float4 operator()(const shapes::Blend&) const { return {}; }
    gpu::float4 operator()(const shapes::Mandelbulb& m) const {
      return {m.power, float(m.iterations), 0, 0};
    }
  };
  return std::visit(Visitor{}, object.shape);
}

// World AABB of the object's (padded) bounds: the eight corners through the
// transform in double, then widened by a few float ULPs of the coordinates'
// magnitude for the rounding of the float AABB test.
std::array<float, 6> worldAabb(const scene::ImplicitObject& object) {
  const ObjectBounds b = implicitObjectBounds(object);
  const glm::dmat4 m(object.transform);
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                       (corner & 4) ? b.hi.z : b.lo.z);
    const glm::dvec3 w(m * glm::dvec4(p, 1.0));
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
  const double magnitude = std::max(largestComponent(glm::abs(lo)), largestComponent(glm::abs(hi)));
  const double slack = 1e-6 * magnitude;
  return {float(lo.x - slack), float(lo.y - slack), float(lo.z - slack),
          float(hi.x + slack), float(hi.y + slack), float(hi.z + slack)};
}

}  // namespace

ImplicitFamily implicitFamily(ImplicitKind kind) {
  switch (kind) {
    case ImplicitKind::Sphere:
      return ImplicitFamily::Sphere;
    case ImplicitKind::Plane:
    case ImplicitKind::Box:
      return ImplicitFamily::PlaneBox;
    case ImplicitKind::Torus:
    case ImplicitKind::RoundedBox:
    case ImplicitKind::Blend:
      return ImplicitFamily::Sdf;
    case ImplicitKind::Mandelbulb:
      return ImplicitFamily::Fractal;
  }
  return ImplicitFamily::Sdf;
}

const char* implicitHitGroupName(ImplicitFamily family) {
  constexpr const char* names[] = {"implicit_sphere", "implicit_plane_box", "implicit_sdf",
                                   "implicit_fractal"};
  return names[uint32_t(family)];
}

const char* implicitIntersectionShader(ImplicitFamily family) {
  constexpr const char* names[] = {"implicit_sphere.rint", "implicit_plane_box.rint",
                                   "implicit_sdf.rint", "implicit_fractal.rint"};
  return names[uint32_t(family)];
}

ObjectBounds implicitObjectBounds(const scene::ImplicitObject& object) {
  ObjectBounds b = unpaddedBounds(object);
  const float extent = largestComponent(glm::max(glm::abs(b.lo), glm::abs(b.hi)));
  float pad = 1e-4f * extent;
  if (scene::isSignedDistanceKind(object.kind())) pad += 2.0f * object.sphereTracing.tolerance;
  return {b.lo - glm::vec3(pad), b.hi + glm::vec3(pad)};
}

gpu::ImplicitData packImplicit(const scene::ImplicitObject& object, uint32_t instanceIndex) {
  gpu::ImplicitData d{};
  // Inverted in double: a small object far from the origin keeps its
  // translation exact.
  const glm::dmat4 worldToObject = glm::inverse(glm::dmat4(object.transform));
  gpu::float4* rows[3] = {&d.worldToObject0, &d.worldToObject1, &d.worldToObject2};
  for (int r = 0; r < 3; ++r)
    *rows[r] = {float(worldToObject[0][r]), float(worldToObject[1][r]), float(worldToObject[2][r]),
                float(worldToObject[3][r])};
  d.shape = shapeParameters(object);
  const ObjectBounds bounds = implicitObjectBounds(object);
  // Below a few float ULPs of the object's coordinates a march can never
  // get within the tolerance and would end at its step limit, so the
  // tolerance does not go below 1e-6 of the object's size.
  const float size =
      std::max(largestComponent(glm::abs(bounds.lo)), largestComponent(glm::abs(bounds.hi)));
  const float tolerance = std::max(object.sphereTracing.tolerance, 1e-6f * size);
  d.boundsMin = {bounds.lo.x, bounds.lo.y, bounds.lo.z};
  d.tolerance = tolerance;
  d.boundsMax = {bounds.hi.x, bounds.hi.y, bounds.hi.z};
  d.kind = uint32_t(object.kind());
  d.instanceIndex = instanceIndex;
  d.maxSteps = object.sphereTracing.maxSteps;
  if (const auto* blend = std::get_if<shapes::Blend>(&object.shape)) {
    d.blendRadius = blend->blendRadius;
    d.blendCount = uint32_t(blend->primitives.size());
    uint32_t* kinds[4] = {&d.blendKinds.x, &d.blendKinds.y, &d.blendKinds.z, &d.blendKinds.w};
    for (size_t i = 0; i < blend->primitives.size(); ++i) {
      const auto& primitive = blend->primitives[i];
      *kinds[i] = blendableKind(primitive.shape);
      d.blendOffsets[i] = {primitive.offset.x, primitive.offset.y, primitive.offset.z, 0.0f};
      d.blendShapes[i] = blendableParameters(primitive.shape);
    }
  }
  return d;
}

ImplicitLayout layoutImplicits(const std::vector<scene::ImplicitObject>& objects,
                               uint32_t firstInstanceIndex) {
  ImplicitLayout layout;
  for (uint32_t f = 0; f < kImplicitFamilyCount; ++f) {
    const auto family = ImplicitFamily(f);
    const uint32_t first = uint32_t(layout.data.size());
    for (size_t i = 0; i < objects.size(); ++i) {
      if (implicitFamily(objects[i].kind()) != family) continue;
      layout.data.push_back(packImplicit(objects[i], firstInstanceIndex + uint32_t(i)));
      layout.aabbs.push_back(worldAabb(objects[i]));
    }
    const uint32_t count = uint32_t(layout.data.size()) - first;
    if (count > 0) layout.families.push_back({family, first, count});
  }
  return layout;
}

}  // namespace penumbra::render
