#pragma once
// glTF's KHR_lights_punctual: the point, spot and directional lights nodes
// carry, mapped onto the engine's delta lights (scene::PointLight).
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/scene.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// The light `node` carries (its KHR_lights_punctual extension), placed by
// the node's world transform: a light sits at the node's origin and faces
// the node's -z, as the extension defines; the node's scale moves it but
// leaves range and intensity alone. Intensity: candela for point and spot
// lights, lux for directional ones, taken as the renderer's radiometric
// units one to one (as glTF's emissive values are). None when the node
// carries no light. Throws penumbra::Error naming `where` on a light index
// out of range, an unknown type, a negative intensity or range, or cone
// angles outside 0 <= inner < outer <= pi/2.
std::optional<PointLight> nodeLight(const tinygltf::Model& model, const tinygltf::Node& node,
                                    const glm::dmat4& world, const std::string& where);

}  // namespace penumbra::scene::gltf
