#include "penumbra/scene/gltf_skin.h"

#include <fmt/format.h>

#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "penumbra/scene/gltf_accessors.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {

std::vector<glm::mat4> jointMatrices(const tinygltf::Model& model, int skin,
                                     const glm::dmat4& nodeWorld,
                                     const std::function<glm::dmat4(int node)>& worldOf,
                                     const std::string& where, const InputLimits& limits) {
  if (skin < 0 || size_t(skin) >= model.skins.size())
    throw Error(
        fmt::format("{}: skin {} does not exist ({} skins)", where, skin, model.skins.size()));
  const tinygltf::Skin& s = model.skins[size_t(skin)];
  const std::string at = fmt::format("{} skin {}", where, skin);
  std::vector<float> inverseBind;
  if (s.inverseBindMatrices >= 0) {
    inverseBind = readFloats(model, s.inverseBindMatrices, 16, at + " inverseBindMatrices", limits);
    if (inverseBind.size() < s.joints.size() * 16)
      throw Error(fmt::format("{} inverseBindMatrices: {} matrices for {} joints", at,
                              inverseBind.size() / 16, s.joints.size()));
  }
  const glm::dmat4 toNode = glm::inverse(nodeWorld);
  std::vector<glm::mat4> out;
  out.reserve(s.joints.size());
  for (size_t j = 0; j < s.joints.size(); ++j) {
    const int joint = s.joints[j];
    if (joint < 0 || size_t(joint) >= model.nodes.size())
      throw Error(fmt::format("{}: joint {} is node {}, which does not exist ({} nodes)", at, j,
                              joint, model.nodes.size()));
    glm::dmat4 bind(1.0);
    if (!inverseBind.empty())
      for (int i = 0; i < 16; ++i) glm::value_ptr(bind)[i] = inverseBind[j * 16 + size_t(i)];
    const glm::mat4 m(toNode * worldOf(joint) * bind);
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(glm::value_ptr(m)[i]))
        throw Error(fmt::format("{}: joint {}'s matrix is not finite", at, j));
    out.push_back(m);
  }
  return out;
}

std::vector<std::string> skinAttributes(const tinygltf::Primitive& primitive) {
  std::vector<std::string> names;
  for (int set = 0;; ++set) {
    const std::string joints = fmt::format("JOINTS_{}", set);
    const std::string weights = fmt::format("WEIGHTS_{}", set);
    if (!primitive.attributes.count(joints) || !primitive.attributes.count(weights)) break;
    names.push_back(joints);
    names.push_back(weights);
  }
  return names;
}

std::vector<glm::mat4> vertexSkinMatrices(const tinygltf::Model& model,
                                          const tinygltf::Primitive& primitive,
                                          const std::vector<glm::mat4>& joints, size_t vertexCount,
                                          const std::string& where, const InputLimits& limits,
                                          std::vector<std::string>& warnings) {
  const std::vector<std::string> names = skinAttributes(primitive);
  if (names.empty()) {
    warnings.push_back(fmt::format(
        "{}: its node has a skin but it has no JOINTS_0 and WEIGHTS_0; drawn unskinned", where));
    return {};
  }
  std::vector<glm::mat4> sum(vertexCount, glm::mat4(0.0f));
  std::vector<float> total(vertexCount, 0.0f);
  for (size_t n = 0; n < names.size(); n += 2) {
    auto read = [&](const std::string& name) {
      const int index = primitive.attributes.at(name);
      const std::string what = fmt::format("{} {} (accessor {})", where, name, index);
      std::vector<float> v = readFloats(model, index, 4, what, limits);
      if (v.size() != vertexCount * 4)
        throw Error(fmt::format("{}: has {} elements but POSITION has {}", what, v.size() / 4,
                                vertexCount));
      return v;
    };
    // Joint indices are unsigned bytes or shorts, not normalised (3.7.3.1).
    const int jointAccessor = primitive.attributes.at(names[n]);
    if (jointAccessor >= 0 && size_t(jointAccessor) < model.accessors.size()) {
      const tinygltf::Accessor& a = model.accessors[size_t(jointAccessor)];
      if ((a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
          a.normalized)
        throw Error(fmt::format(
            "{} {} (accessor {}): joint indices must be unsigned bytes or shorts, not normalised",
            where, names[n], jointAccessor));
    }
    const std::vector<float> index = read(names[n]);
    const std::vector<float> weight = read(names[n + 1]);
    for (size_t v = 0; v < vertexCount; ++v)
      for (size_t k = 0; k < 4; ++k) {
        const float w = weight[v * 4 + k];
        if (!(w >= 0.0f) || !std::isfinite(w))
          throw Error(fmt::format("{} {}: vertex {} has weight {}, not a finite number >= 0", where,
                                  names[n + 1], v, w));
        if (w == 0.0f) continue;
        const float j = index[v * 4 + k];
        if (!(j >= 0.0f) || !(j < float(joints.size())))
          throw Error(fmt::format("{} {}: vertex {} names joint {}, not one of the skin's {}",
                                  where, names[n], v, j, joints.size()));
        sum[v] += w * joints[size_t(j)];
        total[v] += w;
      }
  }
  for (size_t v = 0; v < vertexCount; ++v)
    sum[v] = total[v] > 0.0f ? sum[v] / total[v] : glm::mat4(1.0f);
  return sum;
}

}  // namespace penumbra::scene::gltf
