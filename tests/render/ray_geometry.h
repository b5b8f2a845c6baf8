#pragma once
// Host-side ray optics for render tests: the scene's triangles in world
// space, ray intersection, mirror reflection, Snell refraction and the
// unpolarised Fresnel reflectance, written from the textbook formulas (not
// from the shading core) so a test can predict where a pixel's ray must end.
#include <cmath>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "penumbra/scene/scene.h"

namespace penumbra::test {

struct WorldTriangle {
  glm::vec3 p0, p1, p2;
  glm::vec3 normal;  // unit, the counter-clockwise (front) side
  uint32_t instance = 0;
  uint32_t material = 0;
};

inline std::vector<WorldTriangle> worldTriangles(const scene::Scene& scene) {
  std::vector<WorldTriangle> out;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const auto& inst = scene.instances[i];
    const auto& mesh = scene.meshes[inst.mesh];
    auto world = [&](uint32_t v) {
      return glm::vec3(inst.transform * glm::vec4(mesh.positions[v], 1.0f));
    };
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
      WorldTriangle w;
      w.p0 = world(mesh.indices[t]);
      w.p1 = world(mesh.indices[t + 1]);
      w.p2 = world(mesh.indices[t + 2]);
      w.normal = glm::normalize(glm::cross(w.p1 - w.p0, w.p2 - w.p0));
      w.instance = i;
      w.material = mesh.material;
      out.push_back(w);
    }
  }
  return out;
}

struct HostHit {
  float t = 0;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // front-side unit normal of the triangle hit
  uint32_t instance = 0;
  uint32_t material = 0;
};

// Closest hit with t > tMin (Möller-Trumbore, double precision so that
// grazing edges do not decide a test).
inline std::optional<HostHit> intersect(const std::vector<WorldTriangle>& tris, glm::vec3 origin,
                                        glm::vec3 direction, float tMin = 1e-4f) {
  std::optional<HostHit> best;
  const glm::dvec3 o(origin), d(direction);
  for (const auto& tri : tris) {
    const glm::dvec3 p0(tri.p0), e1 = glm::dvec3(tri.p1) - p0, e2 = glm::dvec3(tri.p2) - p0;
    const glm::dvec3 pv = glm::cross(d, e2);
    const double det = glm::dot(e1, pv);
    if (std::abs(det) < 1e-14) continue;
    const glm::dvec3 tv = o - p0;
    const double u = glm::dot(tv, pv) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 qv = glm::cross(tv, e1);
    const double v = glm::dot(d, qv) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = glm::dot(e2, qv) / det;
    if (t <= tMin || (best && t >= best->t)) continue;
    best = HostHit{float(t), glm::vec3(o + t * d), tri.normal, tri.instance, tri.material};
  }
  return best;
}

// Mirror direction of `d` (travelling towards the surface) about normal `n`
// (either side).
inline glm::vec3 reflectAbout(glm::vec3 d, glm::vec3 n) {
  return d - 2.0f * glm::dot(d, n) * n;
}

// Snell's law n1 sin(theta_i) = n2 sin(theta_t) for `d` travelling from
// index n1 into n2 through a surface of normal `n` (either side); nothing on
// total internal reflection.
inline std::optional<glm::vec3> refractSnell(glm::vec3 d, glm::vec3 n, float n1, float n2) {
  if (glm::dot(d, n) > 0.0f) n = -n;  // n now faces the incident side
  const float cosI = -glm::dot(d, n);
  const float sinT = n1 / n2 * std::sqrt(std::max(0.0f, 1.0f - cosI * cosI));
  if (sinT >= 1.0f) return std::nullopt;
  const float cosT = std::sqrt(1.0f - sinT * sinT);
  // The tangential part keeps its direction and scales by n1 / n2.
  const glm::vec3 tangential = d + cosI * n;
  return glm::normalize(tangential * (n1 / n2) - cosT * n);
}

// Unpolarised reflectance (mean of the s and p Fresnel equations) for light
// going from index n1 into n2 at incidence cosine cosI; 1 beyond the critical
// angle.
inline float fresnelUnpolarised(float cosI, float n1, float n2) {
  cosI = std::abs(cosI);
  const float sinT = n1 / n2 * std::sqrt(std::max(0.0f, 1.0f - cosI * cosI));
  if (sinT >= 1.0f) return 1.0f;
  const float cosT = std::sqrt(1.0f - sinT * sinT);
  const float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  const float rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return 0.5f * (rs * rs + rp * rp);
}

// How a host trace treats a material: the tests use only opaque surfaces,
// perfect mirrors and smooth dielectrics.
enum class SurfaceKind { Opaque, Mirror, Glass };

// The route that carries most of a ray's weight through mirrors and smooth
// glass: reflect at mirrors, refract at glass unless Snell's law forbids it
// (total internal reflection), until an opaque surface or nothing is hit.
// The branches it leaves (Fresnel reflections) carry 1 - weight in all.
struct MainPath {
  static constexpr uint32_t kNothing = ~0u;
  uint32_t material = kNothing;  // the opaque surface it ends on, kNothing if it escapes
  glm::vec3 position{0.0f};      // where it ends
  glm::vec3 normal{0.0f};        // front normal there
  glm::vec3 direction{0.0f};     // of the last segment, arriving there
  float weight = 1.0f;           // product of (1 - F) over the refractions taken
  uint32_t hits = 0;             // surfaces hit, including the last
  uint32_t reflections = 0;      // mirror reflections
  uint32_t refractions = 0;
  uint32_t internalReflections = 0;  // total internal reflections
  std::vector<uint32_t> route;       // instance hit at each step, to compare rays
};

// `kindOf(material)` classifies a material, `iorOf(material)` gives a glass's
// index (air outside: entering through the front face goes from 1 to ior).
template <class KindOf, class IorOf>
MainPath traceMainPath(const std::vector<WorldTriangle>& tris, glm::vec3 origin,
                       glm::vec3 direction, KindOf kindOf, IorOf iorOf, uint32_t maxHits = 32) {
  MainPath path;
  glm::vec3 o = origin, d = glm::normalize(direction);
  while (path.hits < maxHits) {
    const auto hit = intersect(tris, o, d);
    if (!hit) return path;
    path.hits += 1;
    path.route.push_back(hit->instance);
    const SurfaceKind kind = kindOf(hit->material);
    if (kind == SurfaceKind::Opaque) {
      path.material = hit->material;
      path.position = hit->position;
      path.normal = hit->normal;
      path.direction = d;
      return path;
    }
    glm::vec3 next = reflectAbout(d, hit->normal);
    if (kind == SurfaceKind::Mirror) {
      path.reflections += 1;
    } else {
      const bool entering = glm::dot(d, hit->normal) < 0.0f;
      const float ior = iorOf(hit->material);
      const float n1 = entering ? 1.0f : ior, n2 = entering ? ior : 1.0f;
      const auto refracted = refractSnell(d, hit->normal, n1, n2);
      if (refracted) {
        path.weight *= 1.0f - fresnelUnpolarised(glm::dot(d, hit->normal), n1, n2);
        path.refractions += 1;
        next = *refracted;
      } else {
        path.internalReflections += 1;
      }
    }
    o = hit->position;
    d = next;
  }
  path.material = MainPath::kNothing;  // too many hits: treat as lost
  path.route.push_back(MainPath::kNothing);
  return path;
}

}  // namespace penumbra::test
