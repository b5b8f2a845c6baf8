#pragma once
// glTF animations (glTF 2.0, 3.11) evaluated at one moment: what each channel
// sets on its node (translation, rotation, scale, morph weights) at that
// time, interpolated by its sampler: STEP, LINEAR (rotations by spherical
// linear interpolation) or CUBICSPLINE (cubic Hermite with the file's
// tangents). Before a sampler's first keyframe and after its last, the
// first and last values hold, as the specification asks.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

// What an animation sets on one node; each part it does not animate is empty.
struct NodePose {
  std::optional<glm::dvec3> translation, scale;
  std::optional<glm::dquat> rotation;  // unit
  std::optional<std::vector<double>> weights;
};

struct AnimationPose {
  std::vector<NodePose> nodes;    // one per glTF node
  // The first and last keyframe times of the channels drawn, seconds;
  // start > end when no channel was.
  double start = 0.0, end = 0.0;
};

// The animation `choice` names: its name, or its index ("0" the first) when
// no animation has that name. Throws penumbra::Error listing the file's
// animations by index and name.
size_t findAnimation(const tinygltf::Model& model, const std::string& choice,
                     const std::string& where);

// Animation `animation` of the model at `seconds`. Bad samplers (times not
// increasing, output counts that do not match, a target node that does not
// exist) are penumbra::Errors naming the animation and channel; channels
// with a path Penumbra does not animate are skipped with a warning.
AnimationPose evaluateAnimation(const tinygltf::Model& model, size_t animation, double seconds,
                                const std::string& where, const InputLimits& limits,
                                std::vector<std::string>& warnings);

}  // namespace penumbra::scene::gltf
