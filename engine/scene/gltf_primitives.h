#pragma once
// One glTF mesh primitive as a scene Mesh (positions, indices, normals,
// tangents, uv0, uv1), checked against the file's data.
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// The primitive as a triangle list, or nothing (with a warning) when it is
// not made of triangles or has no positions. `material` is the scene
// material index to give it; `where` names it in errors.
std::optional<Mesh> convertPrimitive(const tinygltf::Model& model,
                                     const tinygltf::Primitive& primitive, uint32_t material,
                                     const std::string& where, std::vector<std::string>& warnings);

}  // namespace penumbra::scene::gltf
