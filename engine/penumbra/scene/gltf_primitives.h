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

// The primitive as a triangle list, or nothing (with a warning) when it is
// not made of triangles or has no positions. `material` is the scene
// material index to give it; `morphWeights` the mesh's default morph
// target weights (glTF mesh.weights: the shape drawn without animation);
// `where` names it in errors. Before reading
// anything, the accessors it reads and the triangles its index sequence can
// make are charged to `budget`, and a primitive that would pass its limits
// is an error naming the accessor or the count and the limit.
std::optional<Mesh> convertPrimitive(const tinygltf::Model& model,
                                     const tinygltf::Primitive& primitive, uint32_t material,
                                     const std::vector<double>& morphWeights,
                                     const std::string& where, std::vector<std::string>& warnings,
                                     DecodeBudget& budget);

}  // namespace penumbra::scene::gltf
