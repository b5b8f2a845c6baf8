#pragma once
// glTF's EXT_mesh_gpu_instancing: a node that draws its mesh many times,
// each copy placed by per-instance TRANSLATION, ROTATION and SCALE
// accessors (the renderer's TLAS instances, one per copy).
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// The node-local transforms T * R * S of each copy the node's
// EXT_mesh_gpu_instancing asks for (a missing attribute is the identity
// part), in accessor order; empty when the node has no such extension. The
// copies are placed in the node's space: world = node world x copy.
// Throws penumbra::Error naming `where` when the extension has no
// attributes, an attribute has the wrong type, the counts differ, a value
// is not finite or a rotation is not a unit quaternion's direction.
std::vector<glm::dmat4> gpuInstanceTransforms(const tinygltf::Model& model,
                                              const tinygltf::Node& node, const std::string& where,
                                              const InputLimits& limits);

}  // namespace penumbra::scene::gltf
