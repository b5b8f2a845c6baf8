#include "penumbra/scene/gltf_instancing.h"

#include <fmt/format.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include "penumbra/scene/gltf_accessors.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {

std::vector<glm::dmat4> gpuInstanceTransforms(const tinygltf::Model& model,
                                              const tinygltf::Node& node, const std::string& where,
                                              const InputLimits& limits) {
  const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
  if (ext == node.extensions.end()) return {};
  const std::string at = where + " EXT_mesh_gpu_instancing";
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  if (!attributes.IsObject()) throw Error(fmt::format("{}: has no \"attributes\"", at));
  // Each attribute's values, or nothing; the element count they agree on.
  std::optional<size_t> count;
  auto read = [&](const char* name, int components) -> std::vector<float> {
    const tinygltf::Value& index = attributes.Get(name);
    if (!index.IsNumber()) return {};
    const std::string what = fmt::format("{} {}", at, name);
    std::vector<float> values = readFloats(model, index.GetNumberAsInt(), components, what, limits);
    const size_t n = values.size() / size_t(components);
    if (count && *count != n)
      throw Error(
          fmt::format("{}: {} instances where the other attributes have {}", what, n, *count));
    count = n;
    for (float v : values)
      if (!std::isfinite(v)) throw Error(fmt::format("{}: a value is not finite", what));
    return values;
  };
  const std::vector<float> translation = read("TRANSLATION", 3);
  const std::vector<float> rotation = read("ROTATION", 4);
  const std::vector<float> scale = read("SCALE", 3);
  if (!count) throw Error(fmt::format("{}: none of TRANSLATION, ROTATION, SCALE is given", at));
  requireAtMost(*count, limits.maxInstances, "maxInstances", at + " instance count");
  std::vector<glm::dmat4> transforms;
  transforms.reserve(*count);
  for (size_t i = 0; i < *count; ++i) {
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!translation.empty())
      t = glm::translate(glm::dmat4(1.0), glm::dvec3(translation[3 * i], translation[3 * i + 1],
                                                     translation[3 * i + 2]));
    if (!rotation.empty()) {
      // glTF stores (x, y, z, w); glm::dquat's constructor takes w first.
      const glm::dquat q(rotation[4 * i + 3], rotation[4 * i], rotation[4 * i + 1],
                         rotation[4 * i + 2]);
      const double length = glm::length(q);
      if (!(length > 0.0))
        throw Error(
            fmt::format("{} ROTATION: instance {} is not a rotation (zero quaternion)", at, i));
      r = glm::mat4_cast(q / length);
    }
    if (!scale.empty())
      s = glm::scale(glm::dmat4(1.0), glm::dvec3(scale[3 * i], scale[3 * i + 1], scale[3 * i + 2]));
    transforms.push_back(t * r * s);
  }
  return transforms;
}

}  // namespace penumbra::scene::gltf
