#include "penumbra/scene/gltf_animation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "penumbra/scene/gltf_accessors.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {
namespace {

enum class Interpolation { Step, Linear, CubicSpline };

// One sampler's keyframes: `width` numbers per value; CUBICSPLINE stores
// (in-tangent, value, out-tangent) per keyframe.
struct Keyframes {
  std::vector<float> times;
  std::vector<float> values;
  size_t width = 0;
  Interpolation interpolation = Interpolation::Linear;

  const float* at(size_t key, size_t part) const {
    const size_t perKey = interpolation == Interpolation::CubicSpline ? 3 : 1;
    const size_t slot = interpolation == Interpolation::CubicSpline ? part : 0;
    return &values[(key * perKey + slot) * width];
  }
};

// The value at `seconds` (glTF 2.0, appendix C: interpolation).
std::vector<double> sample(const Keyframes& k, double seconds, bool rotation) {
  const size_t n = k.times.size();
  std::vector<double> out(k.width);
  auto copy = [&](const float* v) {
    for (size_t c = 0; c < k.width; ++c) out[c] = v[c];
  };
  if (seconds <= k.times.front() || n == 1) {
    copy(k.at(0, 1));
  } else if (seconds >= k.times.back()) {
    copy(k.at(n - 1, 1));
  } else {
    const size_t i =
        size_t(std::upper_bound(k.times.begin(), k.times.end(), seconds) - k.times.begin()) - 1;
    const double span = double(k.times[i + 1]) - double(k.times[i]);
    const double u = (seconds - double(k.times[i])) / span;
    const float* a = k.at(i, 1);
    const float* b = k.at(i + 1, 1);
    if (k.interpolation == Interpolation::Step) {
      copy(a);
    } else if (k.interpolation == Interpolation::CubicSpline) {
      const float* outTangent = k.at(i, 2);
      const float* inTangent = k.at(i + 1, 0);
      const double u2 = u * u, u3 = u2 * u;
      for (size_t c = 0; c < k.width; ++c)
        out[c] = (2 * u3 - 3 * u2 + 1) * a[c] + (u3 - 2 * u2 + u) * span * outTangent[c] +
                 (-2 * u3 + 3 * u2) * b[c] + (u3 - u2) * span * inTangent[c];
    } else if (rotation) {
      // glm::slerp takes the shorter arc, as the specification's slerp does.
      const glm::dquat q =
          glm::slerp(glm::dquat(a[3], a[0], a[1], a[2]), glm::dquat(b[3], b[0], b[1], b[2]), u);
      out = {q.x, q.y, q.z, q.w};
    } else {
      for (size_t c = 0; c < k.width; ++c) out[c] = (1.0 - u) * a[c] + u * b[c];
    }
  }
  return out;
}

Interpolation interpolationOf(const std::string& name, const std::string& where) {
  if (name.empty() || name == "LINEAR") return Interpolation::Linear;
  if (name == "STEP") return Interpolation::Step;
  if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
  throw Error(
      fmt::format("{}: unknown interpolation '{}' (STEP, LINEAR, CUBICSPLINE)", where, name));
}

// The sampler's keyframes, `width` numbers per value: VEC3 or VEC4 elements,
// or with `scalars` that many SCALAR elements (morph weights, one per target).
Keyframes readKeyframes(const tinygltf::Model& model, const tinygltf::AnimationSampler& s,
                        size_t width, bool scalars, const std::string& where,
                        const InputLimits& limits) {
  Keyframes k;
  k.interpolation = interpolationOf(s.interpolation, where);
  k.times = readFloats(model, s.input, 1, where + " input", limits);
  if (k.times.empty()) throw Error(fmt::format("{} input: has no keyframes", where));
  for (size_t i = 0; i < k.times.size(); ++i) {
    if (!std::isfinite(k.times[i]))
      throw Error(fmt::format("{} input: time {} is not a finite number", where, i));
    if (i > 0 && !(k.times[i] > k.times[i - 1]))
      throw Error(fmt::format("{} input: times are not increasing (keyframe {}: {} after {})",
                              where, i, k.times[i], k.times[i - 1]));
  }
  const size_t perKey = k.interpolation == Interpolation::CubicSpline ? 3 : 1;
  k.width = width;
  k.values = readFloats(model, s.output, scalars ? 1 : int(width), where + " output", limits);
  if (k.values.size() != k.times.size() * perKey * k.width)
    throw Error(fmt::format("{} output: {} values for {} keyframes{}{}", where,
                            k.values.size() / (scalars ? 1 : width), k.times.size(),
                            scalars ? fmt::format(" of {} morph weights", width) : "",
                            perKey == 3 ? " (CUBICSPLINE keeps 3 per keyframe)" : ""));
  for (size_t i = 0; i < k.values.size(); ++i)
    if (!std::isfinite(k.values[i]))
      throw Error(fmt::format("{} output: value {} is not a finite number", where, i));
  return k;
}

}  // namespace

size_t findAnimation(const tinygltf::Model& model, const std::string& choice,
                     const std::string& where) {
  for (size_t i = 0; i < model.animations.size(); ++i)
    if (model.animations[i].name == choice) return i;
  const bool digits =
      !choice.empty() && std::all_of(choice.begin(), choice.end(),
                                     [](unsigned char c) { return std::isdigit(c) != 0; });
  if (digits && choice.size() < 10 && std::stoul(choice) < model.animations.size())
    return std::stoul(choice);
  std::string names;
  for (size_t i = 0; i < model.animations.size(); ++i)
    names += fmt::format("{}{} '{}'", i ? ", " : "", i, model.animations[i].name);
  throw Error(fmt::format(
      "{}: no animation '{}' ({})", where, choice,
      names.empty() ? "the file has no animations" : "animations by index and name: " + names));
}

AnimationPose evaluateAnimation(const tinygltf::Model& model, size_t animation, double seconds,
                                const std::string& where, const InputLimits& limits,
                                std::vector<std::string>& warnings) {
  const tinygltf::Animation& a = model.animations.at(animation);
  const std::string at = fmt::format("{} animation {}{}", where, animation,
                                     a.name.empty() ? "" : fmt::format(" '{}'", a.name));
  AnimationPose pose;
  pose.nodes.resize(model.nodes.size());
  pose.start = INFINITY;
  pose.end = -INFINITY;
  std::set<std::string> skipped;
  for (size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& channel = a.channels[c];
    const std::string here = fmt::format("{} channel {}", at, c);
    const std::string& path = channel.target_path;
    if (path != "translation" && path != "rotation" && path != "scale" && path != "weights") {
      if (skipped.insert(path).second)
        warnings.push_back(
            fmt::format("{}: animates '{}', which is not supported; skipped", here, path));
      continue;
    }
    // A channel without a node animates what an extension names
    // (KHR_animation_pointer).
    if (channel.target_node < 0) {
      if (skipped.insert("no node").second)
        warnings.push_back(fmt::format("{}: has no target node; skipped", here));
      continue;
    }
    if (size_t(channel.target_node) >= model.nodes.size())
      throw Error(fmt::format("{}: target node {} does not exist ({} nodes)", here,
                              channel.target_node, model.nodes.size()));
    if (channel.sampler < 0 || size_t(channel.sampler) >= a.samplers.size())
      throw Error(fmt::format("{}: sampler {} does not exist ({} samplers)", here, channel.sampler,
                              a.samplers.size()));
    size_t width = path == "rotation" ? 4 : 3;
    if (path == "weights") {
      // One weight per morph target of the node's mesh.
      const tinygltf::Node& node = model.nodes[size_t(channel.target_node)];
      if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size())
        throw Error(fmt::format("{}: animates the morph weights of node {}, which has no mesh",
                                here, channel.target_node));
      width = 0;
      for (const auto& primitive : model.meshes[size_t(node.mesh)].primitives)
        width = std::max(width, primitive.targets.size());
      if (width == 0)
        throw Error(
            fmt::format("{}: animates the morph weights of node {}, whose mesh has no "
                        "morph targets",
                        here, channel.target_node));
    }
    const Keyframes k =
        readKeyframes(model, a.samplers[size_t(channel.sampler)], width, path == "weights",
                      fmt::format("{} sampler {}", here, channel.sampler), limits);
    pose.start = std::min(pose.start, double(k.times.front()));
    pose.end = std::max(pose.end, double(k.times.back()));
    const std::vector<double> v = sample(k, seconds, path == "rotation");
    NodePose& node = pose.nodes[size_t(channel.target_node)];
    if (path == "translation") {
      node.translation = glm::dvec3(v[0], v[1], v[2]);
    } else if (path == "scale") {
      node.scale = glm::dvec3(v[0], v[1], v[2]);
    } else if (path == "weights") {
      node.weights = v;
    } else {
      const glm::dquat q(v[3], v[0], v[1], v[2]);
      const double length = glm::length(q);
      if (!(length > 0.0))
        throw Error(
            fmt::format("{}: the rotation at {} s is not a unit quaternion", here, seconds));
      node.rotation = q / length;
    }
  }
  return pose;  // start > end: no channel was drawn
}

}  // namespace penumbra::scene::gltf
