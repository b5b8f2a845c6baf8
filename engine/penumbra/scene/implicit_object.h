#pragma once
// Implicit surfaces: shapes given by an equation rather than by triangles.
// Sphere, plane and box are intersected analytically; torus, rounded box,
// blend and Mandelbulb are signed distance functions (SDFs) rendered by
// sphere tracing (Hart 1996). Every shape is defined in its own object space
// and placed by an object-to-world transform.
//
// Transforms: analytic kinds take any invertible affine transform (a sphere
// under non-uniform scale is an exact ellipsoid, because the ray is
// intersected in object space). SDF kinds take rotation, translation and
// uniform scale only: sphere tracing steps by object-space distances, which
// non-uniform scale would stop being lower bounds of.
//
// Front side: the outside of closed shapes, the +y side of a plane. Emission
// leaves the front side (like the counter-clockwise face of a triangle).
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace penumbra::scene {

namespace implicit {
// Centred at the object-space origin.
struct Sphere {
  float radius = 1.0f;
};
// The plane y = 0, front side +y. Half extents bound it in x and z.
struct Plane {
  std::optional<glm::vec2> halfExtents;  // nullopt: infinite
};
struct Box {
  glm::vec3 halfExtents{1.0f};
};
// Around the y axis: the tube's centre circle of radius majorRadius lies in
// the xz plane.
struct Torus {
  float majorRadius = 1.0f;
  float minorRadius = 0.25f;
};
// The box of these half extents with edges and corners rounded off by
// cornerRadius (<= the smallest half extent).
struct RoundedBox {
  glm::vec3 halfExtents{1.0f};
  float cornerRadius = 0.1f;
};
// One shape of a blend, moved by `offset` in the blend's object space.
struct BlendPrimitive {
  std::variant<Sphere, Box, Torus, RoundedBox> shape;
  glm::vec3 offset{0.0f};
};
// Smooth union (polynomial smooth minimum, Quilez) of 2..kMaxBlendPrimitives
// primitives: surfaces closer than blendRadius melt into each other.
struct Blend {
  static constexpr size_t kMaxPrimitives = 4;  // IMPLICIT_MAX_BLEND_PRIMITIVES on the GPU
  std::vector<BlendPrimitive> primitives;
  float blendRadius = 0.1f;
};
// The power-n Mandelbulb (White/Nylander triplex power) with its distance
// estimator 0.5 r ln(r) / dr; it lies within the ball of radius
// max(1, 2^(1/(power-1))).
struct Mandelbulb {
  float power = 8.0f;
  uint32_t iterations = 12;
};
}  // namespace implicit

// Order = the variant's alternatives = IMPLICIT_* in path_tracer_shared.h.
enum class ImplicitKind : uint32_t { Sphere, Plane, Box, Torus, RoundedBox, Blend, Mandelbulb };

using ImplicitShape =
    std::variant<implicit::Sphere, implicit::Plane, implicit::Box, implicit::Torus,
                 implicit::RoundedBox, implicit::Blend, implicit::Mandelbulb>;

// How an SDF kind is sphere traced. A ray that takes maxSteps distance
// evaluations without reaching the surface misses.
struct SphereTracing {
  uint32_t maxSteps = 256;
  // Object-space distance that counts as on the surface; at least 1e-6 of
  // the object's size is used (float resolution of its coordinates).
  float tolerance = 1e-4f;
};

struct ImplicitObject {
  std::string name;
  ImplicitShape shape;
  glm::dmat4 transform{
      1.0};  // object to world, double as Instance's (see the header comment for what is allowed)
  uint32_t material = 0;
  SphereTracing sphereTracing;  // SDF kinds only

  ImplicitKind kind() const { return ImplicitKind(shape.index()); }
};

const char* implicitKindName(ImplicitKind kind);
// Torus, rounded box, blend and Mandelbulb: rendered by sphere tracing.
bool isSignedDistanceKind(ImplicitKind kind);

// Throws penumbra::Error naming the object: non-finite or non-positive sizes,
// a blend of fewer than 2 or more than 4 primitives, a step limit < 1, a
// non-invertible transform, or non-uniform scale on an SDF kind.
void validateImplicit(const ImplicitObject& object, size_t materialCount);

}  // namespace penumbra::scene
