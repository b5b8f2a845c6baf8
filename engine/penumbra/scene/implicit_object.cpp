#include "penumbra/scene/implicit_object.h"

#include <fmt/format.h>

#include <cmath>

#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

bool finite(float v) {
  return std::isfinite(v);
}
bool finite(glm::vec3 v) {
  return finite(v.x) && finite(v.y) && finite(v.z);
}
bool positive(float v) {
  return std::isfinite(v) && v > 0.0f;
}
bool positive(glm::vec2 v) {
  return positive(v.x) && positive(v.y);
}
bool positive(glm::vec3 v) {
  return positive(v.x) && positive(v.y) && positive(v.z);
}

std::string show(glm::vec3 v) {
  return fmt::format("[{}, {}, {}]", v.x, v.y, v.z);
}

class ShapeChecker {
 public:
  explicit ShapeChecker(std::string where) : where_(std::move(where)) {}

  void operator()(const implicit::Sphere& s) const {
    require(positive(s.radius), fmt::format("radius must be positive, got {}", s.radius));
  }
  void operator()(const implicit::Plane& p) const {
    if (p.halfExtents)
      require(positive(*p.halfExtents), fmt::format("halfExtents must be positive, got [{}, {}]",
                                                    p.halfExtents->x, p.halfExtents->y));
  }
  void operator()(const implicit::Box& b) const {
    require(positive(b.halfExtents),
            fmt::format("halfExtents must be positive, got {}", show(b.halfExtents)));
  }
  void operator()(const implicit::Torus& t) const {
    require(positive(t.majorRadius) && positive(t.minorRadius),
            fmt::format("majorRadius and minorRadius must be positive, got {} and {}",
                        t.majorRadius, t.minorRadius));
  }
  void operator()(const implicit::RoundedBox& b) const {
    require(positive(b.halfExtents),
            fmt::format("halfExtents must be positive, got {}", show(b.halfExtents)));
    const float smallest = std::min(b.halfExtents.x, std::min(b.halfExtents.y, b.halfExtents.z));
    require(finite(b.cornerRadius) && b.cornerRadius >= 0.0f && b.cornerRadius <= smallest,
            fmt::format("cornerRadius must lie in [0, {}] (the smallest half extent), got {}",
                        smallest, b.cornerRadius));
  }
  void operator()(const implicit::Blend& b) const {
    require(b.primitives.size() >= 2 && b.primitives.size() <= implicit::Blend::kMaxPrimitives,
            fmt::format("a blend needs 2 to {} primitives, got {}", implicit::Blend::kMaxPrimitives,
                        b.primitives.size()));
    require(finite(b.blendRadius) && b.blendRadius >= 0.0f,
            fmt::format("blendRadius must be >= 0, got {}", b.blendRadius));
    for (size_t i = 0; i < b.primitives.size(); ++i) {
      const auto& primitive = b.primitives[i];
      ShapeChecker inner(fmt::format("{} primitive {}", where_, i));
      inner.require(finite(primitive.offset),
                    fmt::format("offset must be finite, got {}", show(primitive.offset)));
      std::visit(inner, primitive.shape);
    }
  }
  void operator()(const implicit::Mandelbulb& m) const {
    require(finite(m.power) && m.power >= 2.0f && m.power <= 32.0f,
            fmt::format("power must lie in [2, 32], got {}", m.power));
    require(m.iterations >= 1 && m.iterations <= 256,
            fmt::format("iterations must lie in [1, 256], got {}", m.iterations));
  }

  void require(bool ok, const std::string& what) const {
    if (!ok) throw Error(fmt::format("{}: {}", where_, what));
  }

 private:
  std::string where_;
};

// Columns of the linear part pairwise orthogonal and of one length: rotation
// times uniform scale. Relative 1e-4 admits the rounding of a file's
// degrees-to-matrix conversion, not a real stretch.
bool isSimilarity(const glm::mat3& m) {
  const float lengths[3] = {glm::length(m[0]), glm::length(m[1]), glm::length(m[2])};
  constexpr float kRelative = 1e-4f;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(lengths[i] - lengths[0]) > kRelative * lengths[0]) return false;
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(glm::dot(m[i], m[j])) > kRelative * lengths[i] * lengths[j]) return false;
  }
  return true;
}

}  // namespace

const char* implicitKindName(ImplicitKind kind) {
  switch (kind) {
    case ImplicitKind::Sphere:
      return "sphere";
    case ImplicitKind::Plane:
      return "plane";
    case ImplicitKind::Box:
      return "box";
    case ImplicitKind::Torus:
      return "torus";
    case ImplicitKind::RoundedBox:
      return "roundedBox";
    case ImplicitKind::Blend:
      return "blend";
    case ImplicitKind::Mandelbulb:
      return "mandelbulb";
  }
  return "unknown";
}

bool isSignedDistanceKind(ImplicitKind kind) {
  return kind == ImplicitKind::Torus || kind == ImplicitKind::RoundedBox ||
         kind == ImplicitKind::Blend || kind == ImplicitKind::Mandelbulb;
}

void validateImplicit(const ImplicitObject& object, size_t materialCount) {
  const ShapeChecker check(
      fmt::format("implicit '{}' ({})", object.name, implicitKindName(object.kind())));
  check.require(object.material < materialCount,
                fmt::format("uses material {} of {}", object.material, materialCount));
  const glm::mat4& m = object.transform;
  for (int c = 0; c < 4; ++c)
    check.require(std::isfinite(m[c].x) && std::isfinite(m[c].y) && std::isfinite(m[c].z) &&
                      std::isfinite(m[c].w),
                  "the transform has a non-finite element");
  check.require(m[0].w == 0.0f && m[1].w == 0.0f && m[2].w == 0.0f && m[3].w == 1.0f,
                "the transform must be affine (last row 0 0 0 1)");
  const glm::mat3 linear(m);
  const float det = glm::determinant(linear);
  check.require(std::isfinite(det) && std::abs(det) > 1e-12f,
                "the transform is not invertible (zero scale?)");
  if (isSignedDistanceKind(object.kind())) {
    check.require(
        isSimilarity(linear),
        fmt::format("non-uniform scale (column lengths {}, {}, {}) or shear: sphere "
                    "tracing needs rotation, translation and uniform scale only",
                    glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])));
    check.require(object.sphereTracing.maxSteps >= 1,
                  fmt::format("maxSteps must be >= 1, got {}", object.sphereTracing.maxSteps));
    check.require(
        positive(object.sphereTracing.tolerance),
        fmt::format("tolerance must be positive, got {}", object.sphereTracing.tolerance));
  }
  std::visit(check, object.shape);
}

}  // namespace penumbra::scene
