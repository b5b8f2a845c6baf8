#pragma once
// glTF skins (glTF 2.0, 3.7.3): each vertex of a skinned mesh follows up to
// four joints per JOINTS_n / WEIGHTS_n pair, by the weighted sum of the
// joints' skinning matrices (joint world transform times inverse bind
// matrix). The skinned node's own transform does not move the mesh; the
// matrices here are taken into its space so that the instance keeps the
// node's world transform in double (scene.h: precision far from the origin).
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// Skin `skin`'s joint matrices in the space of the node that draws the mesh
// (world transform `nodeWorld`): inverse(nodeWorld) * world(joint) *
// inverseBindMatrix, for each joint in order. `worldOf` gives a node's world
// transform (the pose being drawn).
std::vector<glm::mat4> jointMatrices(const tinygltf::Model& model, int skin,
                                     const glm::dmat4& nodeWorld,
                                     const std::function<glm::dmat4(int node)>& worldOf,
                                     const std::string& where, const InputLimits& limits);

// The attribute names a skinned primitive reads: JOINTS_n and WEIGHTS_n for
// each set n the primitive has both of.
std::vector<std::string> skinAttributes(const tinygltf::Primitive& primitive);

// One matrix per vertex: the weighted sum of its joints' matrices (weights
// that do not sum to 1 are scaled to; a vertex with no weight stays where
// it is). Empty, with a warning, when the primitive has no JOINTS_0 and
// WEIGHTS_0. A joint index past the skin's joints is a penumbra::Error.
std::vector<glm::mat4> vertexSkinMatrices(const tinygltf::Model& model,
                                          const tinygltf::Primitive& primitive,
                                          const std::vector<glm::mat4>& joints, size_t vertexCount,
                                          const std::string& where, const InputLimits& limits,
                                          std::vector<std::string>& warnings);

}  // namespace penumbra::scene::gltf
