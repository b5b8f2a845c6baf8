#pragma once
// One glTF mesh primitive as a scene Mesh (positions, indices, normals,
// tangents, uv0, uv1), checked against the file's data.
#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// What the primitives of one file may decode, summed as they are converted.
struct DecodeBudget {
  InputLimits limits;
  uint64_t decodedBytes = 0;  // accessor data read (InputLimits::maxDecodedBytes)
  uint64_t triangles = 0;     // triangles kept (InputLimits::maxTriangles)
  // Zero-area triangles dropped, told in one line for the file (a model can
  // have them in every primitive): how many, from how many primitives, and
  // the first primitive that had any.
  uint64_t degenerateTriangles = 0;
  uint32_t primitivesWithDegenerate = 0;
  std::string firstWithDegenerate;
};

// The line telling what `budget` dropped (file `at`), or "" when nothing was.
std::string degenerateTrianglesWarning(const DecodeBudget& budget, const std::string& at);

// The shape a primitive is drawn in: its morph target weights (the mesh's
// default weights, its node's, or an animation's at the chosen time) and,
// for a node with a skin, the skin's joint matrices in the node's space
// (gltf_skin.h); empty for an unskinned node.
struct PrimitiveShape {
  std::vector<double> morphWeights;
  std::vector<glm::mat4> joints;
};

// The primitive as a triangle list, or nothing (with a warning) when it is
// not made of triangles or has no positions. `material` is the scene
// material index to give it; `shape` the morph weights and skin to apply;
// `where` names it in errors. Before reading
// anything, the accessors it reads and the triangles its index sequence can
// make are charged to `budget`, and a primitive that would pass its limits
// is an error naming the accessor or the count and the limit.
std::optional<Mesh> convertPrimitive(const tinygltf::Model& model,
                                     const tinygltf::Primitive& primitive, uint32_t material,
                                     const PrimitiveShape& shape, const std::string& where,
                                     std::vector<std::string>& warnings, DecodeBudget& budget);

}  // namespace penumbra::scene::gltf
