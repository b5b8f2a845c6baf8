#include "penumbra/scene/mesh_attributes.h"

#include <cmath>

namespace penumbra::scene {
namespace {

// Any unit vector orthogonal to n (Duff et al. 2017).
glm::vec3 orthogonalTo(glm::vec3 n) {
  const float s = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (s + n.z);
  const float b = n.x * n.y * a;
  return {1.0f + s * n.x * n.x * a, s * b, -s * n.x};
}

}  // namespace

void makeFlatNormals(Mesh& mesh) {
  Mesh flat;
  const bool hasUv = !mesh.uv0.empty();
  const bool hasUv1 = !mesh.uv1.empty();
  const bool hasColors = !mesh.colors.empty();
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = mesh.positions[mesh.indices[t + k]];
    const glm::vec3 c = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float len = glm::length(c);
    const glm::vec3 n = len > 0.0f && std::isfinite(len) ? c / len : glm::vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
      flat.indices.push_back(uint32_t(flat.positions.size()));
      flat.positions.push_back(p[k]);
      flat.normals.push_back(n);
      if (hasUv) flat.uv0.push_back(mesh.uv0[mesh.indices[t + k]]);
      if (hasUv1) flat.uv1.push_back(mesh.uv1[mesh.indices[t + k]]);
      if (hasColors) flat.colors.push_back(mesh.colors[mesh.indices[t + k]]);
    }
  }
  mesh.positions = std::move(flat.positions);
  mesh.indices = std::move(flat.indices);
  mesh.normals = std::move(flat.normals);
  mesh.uv0 = std::move(flat.uv0);
  mesh.uv1 = std::move(flat.uv1);
  mesh.colors = std::move(flat.colors);
  mesh.tangents.clear();
}

void generateTangents(Mesh& mesh) {
  const size_t n = mesh.positions.size();
  if (mesh.normals.size() != n || mesh.uv0.size() != n) return;
  std::vector<glm::vec3> tangent(n, glm::vec3(0.0f)), bitangent(n, glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0];
    const glm::vec3 e2 = mesh.positions[i2] - mesh.positions[i0];
    // v flipped: the bitangent follows the image's up direction (decreasing v).
    const glm::vec2 d1(mesh.uv0[i1].x - mesh.uv0[i0].x, mesh.uv0[i0].y - mesh.uv0[i1].y);
    const glm::vec2 d2(mesh.uv0[i2].x - mesh.uv0[i0].x, mesh.uv0[i0].y - mesh.uv0[i2].y);
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 0.0f) || !std::isfinite(det)) continue;
    // Scaling by sign(det) instead of 1/det weighs each triangle by its UV
    // area and stays finite for nearly degenerate UVs.
    const float sign = det > 0.0f ? 1.0f : -1.0f;
    const glm::vec3 tri = (e1 * d2.y - e2 * d1.y) * sign;
    const glm::vec3 bi = (e2 * d1.x - e1 * d2.x) * sign;
    for (uint32_t i : {i0, i1, i2}) {
      tangent[i] += tri;
      bitangent[i] += bi;
    }
  }
  mesh.tangents.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 nrm = mesh.normals[i];
    glm::vec3 t = tangent[i] - nrm * glm::dot(nrm, tangent[i]);
    const float len = glm::length(t);
    if (!(len > 1e-12f) || !std::isfinite(len)) {
      mesh.tangents[i] =
          glm::vec4(orthogonalTo(glm::length(nrm) > 0.0f ? nrm : glm::vec3(0, 0, 1)), 1.0f);
      continue;
    }
    t /= len;
    const float w = glm::dot(glm::cross(nrm, t), bitangent[i]) < 0.0f ? -1.0f : 1.0f;
    mesh.tangents[i] = glm::vec4(t, w);
  }
}

}  // namespace penumbra::scene
