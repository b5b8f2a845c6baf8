#pragma once
// How a scene's implicit objects reach the GPU. Objects are grouped into
// families, one per intersection shader (and hit group); each family present
// in the scene gets one BLAS of world-space AABBs (one per object, in
// ImplicitData order) and one TLAS instance with the identity transform,
// whose InstanceID() is the family's first ImplicitData, so InstanceID() +
// PrimitiveIndex() finds the object. The object's own transform lives in its
// ImplicitData and the intersection shader applies it.
#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// In hit-group order after the triangle hit group (index 0).
enum class ImplicitFamily : uint32_t { Sphere, PlaneBox, Sdf, Fractal };
constexpr uint32_t kImplicitFamilyCount = 4;

ImplicitFamily implicitFamily(scene::ImplicitKind kind);
const char* implicitHitGroupName(ImplicitFamily family);
const char* implicitIntersectionShader(ImplicitFamily family);

// An infinite plane stops here (object-space units): acceleration structures
// need finite boxes.
constexpr float kUnboundedPlaneHalfExtent = 1e5f;

struct ObjectBounds {
  glm::vec3 lo, hi;
};

// Object-space box holding the surface, padded so that the point where a ray
// enters it is clear of the surface by more than the sphere-tracing
// tolerance (marching starts there) and covers rounding in the AABB test.
ObjectBounds implicitObjectBounds(const scene::ImplicitObject& object);

gpu::ImplicitData packImplicit(const scene::ImplicitObject& object, uint32_t instanceIndex);

struct ImplicitFamilyRange {
  ImplicitFamily family;
  uint32_t firstObject;  // into ImplicitLayout::data
  uint32_t objectCount;
};

struct ImplicitLayout {
  std::vector<gpu::ImplicitData> data;        // grouped by family, families in enum order
  std::vector<std::array<float, 6>> aabbs;    // world space (min xyz, max xyz), same order
  std::vector<ImplicitFamilyRange> families;  // only the families the scene uses
};

// `firstInstanceIndex`: InstanceData index of scene.implicits[0]; the others
// follow in scene order.
ImplicitLayout layoutImplicits(const std::vector<scene::ImplicitObject>& objects,
                               uint32_t firstInstanceIndex);

}  // namespace penumbra::render
