#include "penumbra/scene/gltf_primitives.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "penumbra/scene/gltf_accessors.h"
#include "penumbra/scene/gltf_skin.h"
#include "penumbra/scene/mesh_attributes.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/scene/triangle_order.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {
namespace {

// Triangle lists from the index sequence of each triangle topology (glTF 3.7.2.1).
std::vector<uint32_t> toTriangleList(int mode, const std::vector<uint32_t>& v) {
  std::vector<uint32_t> out;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    out.assign(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 3 * 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < v.size(); ++i) {
      // Every other triangle is reversed so all keep the first one's winding.
      out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
    }
  } else {  // fan
    for (size_t i = 0; i + 2 < v.size(); ++i) out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
  }
  return out;
}

// The index sequence of a non-indexed primitive.
std::vector<uint32_t> consecutive(size_t count) {
  std::vector<uint32_t> v;
  v.reserve(count);
  for (size_t i = 0; i < count; ++i) v.push_back(uint32_t(i));
  return v;
}

int attribute(const tinygltf::Primitive& p, const char* name) {
  auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

// The attributes convertPrimitive reads besides POSITION.
constexpr const char* kAttributes[] = {"NORMAL", "TEXCOORD_0", "TEXCOORD_1", "TANGENT", "COLOR_0"};

// Charges what converting `p` reads and makes to `budget`, from the
// accessors' declared counts, before any of it is allocated.
void charge(const tinygltf::Model& model, const tinygltf::Primitive& p, int position, bool skinned,
            const std::string& where, DecodeBudget& budget) {
  const InputLimits& limits = budget.limits;
  uint64_t bytes = decodedBytes(model, position, limits, where + " POSITION");
  // The index sequence: the indices, or one per vertex.
  uint64_t sequence = accessorCount(model, position, where + " POSITION");
  if (p.indices >= 0) {
    bytes += decodedBytes(model, p.indices, limits, where + " indices");
    sequence = accessorCount(model, p.indices, where + " indices");
  }
  for (const char* name : kAttributes)
    if (const int index = attribute(p, name); index >= 0)
      bytes += decodedBytes(model, index, limits, fmt::format("{} {}", where, name));
  if (skinned)
    for (const std::string& name : skinAttributes(p))
      bytes += decodedBytes(model, attribute(p, name.c_str()), limits,
                            fmt::format("{} {}", where, name));
  for (size_t t = 0; t < p.targets.size(); ++t)
    for (const auto& [name, index] : p.targets[t])
      bytes += decodedBytes(model, index, limits, fmt::format("{} target {} {}", where, t, name));
  budget.decodedBytes = saturatingAdd(budget.decodedBytes, bytes);
  requireAtMost(budget.decodedBytes, limits.maxDecodedBytes, "maxDecodedBytes",
                where + ": the file's decoded accessor bytes");
  const uint64_t triangles = p.mode == TINYGLTF_MODE_TRIANGLES ? sequence / 3
                             : sequence >= 2                   ? sequence - 2
                                                               : 0;
  requireAtMost(saturatingAdd(budget.triangles, triangles), limits.maxTriangles, "maxTriangles",
                where + ": the file's triangle count");
}

template <class Vec>
std::vector<Vec> toVectors(const std::vector<float>& flat, const std::string& where) {
  constexpr int n = Vec::length();
  std::vector<Vec> out(flat.size() / n);
  for (size_t i = 0; i < out.size(); ++i)
    for (int c = 0; c < n; ++c) {
      const float value = flat[i * n + size_t(c)];
      if (!std::isfinite(value))
        throw Error(fmt::format("{}: element {} is not a finite number", where, i));
      out[i][c] = value;
    }
  return out;
}

}  // namespace

std::string degenerateTrianglesWarning(const DecodeBudget& budget, const std::string& at) {
  if (budget.primitivesWithDegenerate == 0) return "";
  if (budget.primitivesWithDegenerate == 1)
    return fmt::format("{}: {} degenerate (zero-area) triangles dropped",
                       budget.firstWithDegenerate, budget.degenerateTriangles);
  return fmt::format(
      "{}: {} degenerate (zero-area) triangles dropped from {} primitives (the first: {})", at,
      budget.degenerateTriangles, budget.primitivesWithDegenerate, budget.firstWithDegenerate);
}

// Adds each morph target's displacements of `name` (POSITION, NORMAL or
// TANGENT, xyz), times its weight, to `values` (glTF 3.7.2.2).
template <class Vec>
void addMorphDisplacements(const tinygltf::Model& model, const tinygltf::Primitive& p,
                           const std::vector<double>& weights, const char* name,
                           std::vector<Vec>& values, const std::string& where,
                           const InputLimits& limits) {
  if (values.empty()) return;
  for (size_t t = 0; t < p.targets.size() && t < weights.size(); ++t) {
    const auto found = p.targets[t].find(name);
    if (found == p.targets[t].end() || weights[t] == 0.0) continue;
    const std::string what = fmt::format("{} target {} {}", where, t, name);
    const std::vector<float> d = readFloats(model, found->second, 3, what, limits);
    if (d.size() != values.size() * 3)
      throw Error(fmt::format("{} (accessor {}): has {} elements but POSITION has {}", what,
                              found->second, d.size() / 3, values.size()));
    const float w = float(weights[t]);
    for (size_t v = 0; v < values.size(); ++v)
      for (int c = 0; c < 3; ++c) values[v][c] += w * d[v * 3 + size_t(c)];
  }
}

std::optional<Mesh> convertPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                     uint32_t material, const PrimitiveShape& shape,
                                     const std::string& where, std::vector<std::string>& warnings,
                                     DecodeBudget& budget) {
  if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    warnings.push_back(fmt::format("{}: mode {} is not made of triangles; skipped", where, p.mode));
    return std::nullopt;
  }
  const int position = attribute(p, "POSITION");
  if (position < 0) {
    warnings.push_back(fmt::format("{}: has no POSITION; skipped", where));
    return std::nullopt;
  }
  charge(model, p, position, !shape.joints.empty(), where, budget);
  const std::vector<double>& morphWeights = shape.morphWeights;
  const InputLimits& limits = budget.limits;
  Mesh mesh;
  mesh.material = material;
  const std::string at = where + " POSITION";
  mesh.positions = toVectors<glm::vec3>(readFloats(model, position, 3, at, limits),
                                        fmt::format("{} (accessor {})", at, position));
  const size_t vertexCount = mesh.positions.size();
  for (double w : morphWeights)
    if (!std::isfinite(w))
      throw Error(fmt::format("{}: a morph target weight is not finite", where));
  addMorphDisplacements(model, p, morphWeights, "POSITION", mesh.positions, where, limits);
  // Skinning follows morphing (glTF 2.0, 3.7.3.3).
  const std::vector<glm::mat4> skin =
      shape.joints.empty()
          ? std::vector<glm::mat4>()
          : vertexSkinMatrices(model, p, shape.joints, vertexCount, where, limits, warnings);
  for (size_t v = 0; v < skin.size(); ++v)
    mesh.positions[v] = glm::vec3(skin[v] * glm::vec4(mesh.positions[v], 1.0f));

  const std::vector<uint32_t> sequence =
      p.indices >= 0 ? readIndices(model, p.indices, where + " indices", limits)
                     : consecutive(vertexCount);
  for (size_t i = 0; i < sequence.size(); ++i)
    if (sequence[i] >= vertexCount)
      throw Error(
          fmt::format("{} indices (accessor {}): index {} at position {} is not below the "
                      "vertex count {}",
                      where, p.indices, sequence[i], i, vertexCount));
  mesh.indices = toTriangleList(p.mode, sequence);
  if (p.mode == TINYGLTF_MODE_TRIANGLES && sequence.size() % 3 != 0)
    warnings.push_back(fmt::format("{}: {} indices are not a multiple of 3; the last {} ignored",
                                   where, sequence.size(), sequence.size() % 3));
  // A zero-area triangle (a repeated or collinear corner) can never be hit
  // and has no normal: it is dropped here, so none reaches the GPU.
  std::vector<uint32_t> kept;
  kept.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]];
    const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[t + 1]] - a,
                                   mesh.positions[mesh.indices[t + 2]] - a);
    if (glm::dot(n, n) > 0.0f)
      kept.insert(kept.end(), mesh.indices.begin() + t, mesh.indices.begin() + t + 3);
  }
  if (const size_t dropped = (mesh.indices.size() - kept.size()) / 3; dropped > 0) {
    if (budget.primitivesWithDegenerate++ == 0) budget.firstWithDegenerate = where;
    budget.degenerateTriangles += dropped;
  }
  mesh.indices = std::move(kept);
  if (mesh.indices.empty()) {
    warnings.push_back(fmt::format("{}: has no triangles; skipped", where));
    return std::nullopt;
  }

  auto readAttribute = [&](const char* name, int components) -> std::vector<float> {
    const int index = attribute(p, name);
    if (index < 0) return {};
    const std::string what = fmt::format("{} {}", where, name);
    auto values = readFloats(model, index, components, what, limits);
    if (values.size() != vertexCount * size_t(components))
      throw Error(fmt::format("{} (accessor {}): has {} elements but POSITION has {}", what, index,
                              values.size() / size_t(components), vertexCount));
    return values;
  };
  auto accessorName = [&](const char* name) {
    return fmt::format("{} {} (accessor {})", where, name, attribute(p, name));
  };
  mesh.normals = toVectors<glm::vec3>(readAttribute("NORMAL", 3), accessorName("NORMAL"));
  addMorphDisplacements(model, p, morphWeights, "NORMAL", mesh.normals, where, limits);
  for (size_t v = 0; v < skin.size() && !mesh.normals.empty(); ++v)
    mesh.normals[v] = glm::transpose(glm::inverse(glm::mat3(skin[v]))) * mesh.normals[v];
  for (auto& n : mesh.normals) {
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f);
  }
  mesh.uv0 = toVectors<glm::vec2>(readAttribute("TEXCOORD_0", 2), accessorName("TEXCOORD_0"));
  mesh.uv1 = toVectors<glm::vec2>(readAttribute("TEXCOORD_1", 2), accessorName("TEXCOORD_1"));
  mesh.tangents = toVectors<glm::vec4>(readAttribute("TANGENT", 4), accessorName("TANGENT"));
  addMorphDisplacements(model, p, morphWeights, "TANGENT", mesh.tangents, where, limits);
  for (size_t v = 0; v < skin.size() && !mesh.tangents.empty(); ++v)
    mesh.tangents[v] =
        glm::vec4(glm::mat3(skin[v]) * glm::vec3(mesh.tangents[v]), mesh.tangents[v].w);
  for (auto& t : mesh.tangents) {
    const float len = glm::length(glm::vec3(t));
    t = glm::vec4(len > 0.0f ? glm::vec3(t) / len : glm::vec3(0.0f), t.w < 0.0f ? -1.0f : 1.0f);
  }
  // COLOR_0, RGB or RGBA (float or normalised integers), clamped to [0, 1].
  if (const int color = attribute(p, "COLOR_0"); color >= 0) {
    const bool rgb = size_t(color) < model.accessors.size() &&
                     model.accessors[size_t(color)].type == TINYGLTF_TYPE_VEC3;
    if (rgb)
      for (const glm::vec3& c :
           toVectors<glm::vec3>(readAttribute("COLOR_0", 3), accessorName("COLOR_0")))
        mesh.colors.emplace_back(c, 1.0f);
    else
      mesh.colors = toVectors<glm::vec4>(readAttribute("COLOR_0", 4), accessorName("COLOR_0"));
    for (auto& c : mesh.colors) c = glm::clamp(c, 0.0f, 1.0f);
  }
  if (p.targets.size() > morphWeights.size())
    warnings.push_back(fmt::format("{}: {} morph targets but {} default weights; the rest weigh 0",
                                   where, p.targets.size(), morphWeights.size()));

  if (mesh.normals.empty()) {
    makeFlatNormals(mesh);
  }
  if (mesh.tangents.empty()) generateTangents(mesh);
  sortTrianglesSpatially(mesh);
  budget.triangles += mesh.indices.size() / 3;
  return mesh;
}

}  // namespace penumbra::scene::gltf
