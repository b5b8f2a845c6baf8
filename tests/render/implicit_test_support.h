#pragma once
// Building small scenes of implicit objects and checking probe hits against
// analytic answers (tests/render/test_implicit_*.cpp).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "penumbra/render/path_tracer.h"
#include "penumbra/scene/scene.h"

namespace penumbra::test {

inline glm::mat4 translate(glm::vec3 t) {
  return glm::translate(glm::mat4(1.0f), t);
}

inline scene::ImplicitObject implicitObject(std::string name, scene::ImplicitShape shape,
                                            glm::mat4 transform = glm::mat4(1.0f),
                                            uint32_t material = 0) {
  scene::ImplicitObject o;
  o.name = std::move(name);
  o.shape = std::move(shape);
  o.transform = transform;
  o.material = material;
  return o;
}

// Adds, far from everything the tests look at (around (1000, 1000, 1000)),
// one small object of each implicit family the scene lacks. The hit groups
// follow the families present, so with all of them every implicit test
// builds the same pipeline, which lavapipe compiles once (about 20 s) and
// then finds in its shader cache.
inline void addEveryFamily(scene::Scene& s) {
  namespace shapes = scene::implicit;
  bool present[4] = {false, false, false, false};
  const auto family = [](scene::ImplicitKind k) {
    using K = scene::ImplicitKind;
    return k == K::Sphere ? 0 : (k == K::Plane || k == K::Box) ? 1 : k == K::Mandelbulb ? 3 : 2;
  };
  for (const auto& o : s.implicits) present[family(o.kind())] = true;
  const scene::ImplicitShape fillers[4] = {shapes::Sphere{0.1f}, shapes::Box{glm::vec3(0.1f)},
                                           shapes::Torus{0.1f, 0.05f}, shapes::Mandelbulb{}};
  for (int f = 0; f < 4; ++f)
    if (!present[f])
      s.implicits.push_back(implicitObject("far filler", fillers[f],
                                           translate(glm::vec3(1000.0f + 10.0f * float(f)))));
}

// A grey Lambertian material 0 and the given objects (then addEveryFamily);
// the camera is unused by probe rays.
inline scene::Scene implicitScene(std::vector<scene::ImplicitObject> objects) {
  scene::Scene s;
  s.name = "implicit probe";
  s.materials.push_back(scene::Material::lambert("grey", glm::vec3(0.5f)));
  s.implicits = std::move(objects);
  addEveryFamily(s);
  return s;
}

inline render::ProbeRay probeRay(glm::dvec3 origin, glm::dvec3 direction, float tMax = 1e30f) {
  return {glm::vec3(origin), glm::vec3(glm::normalize(direction)), tMax};
}

struct ExpectedHit {
  double t;
  glm::dvec3 normal;
  double tTolerance;
  double normalTolerance;  // per component of the unit normal
};

// The hit's distance and normal within the tolerances, and its position on
// the ray at that distance (to float precision of the position).
inline void checkHit(const render::ProbeRay& ray, const render::SurfaceHit& hit,
                     const ExpectedHit& expected) {
  INFO("ray from (" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") along ("
                    << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z
                    << ")");
  INFO("hit t " << hit.hitT << " (expected " << expected.t << "), normal (" << hit.geometricNormal.x
                << ", " << hit.geometricNormal.y << ", " << hit.geometricNormal.z << ")");
  REQUIRE(hit.isHit());
  CHECK(std::abs(hit.hitT - expected.t) <= expected.tTolerance);
  for (int i = 0; i < 3; ++i)
    CHECK(std::abs(hit.geometricNormal[i] - expected.normal[i]) <= expected.normalTolerance);
  const glm::dvec3 onRay = glm::dvec3(ray.origin) + double(hit.hitT) * glm::dvec3(ray.direction);
  const double scale = std::max(1.0, glm::length(onRay));
  CHECK(glm::length(glm::dvec3(hit.position) - onRay) <= 1e-6 * scale);
}

inline void checkMiss(const render::ProbeRay& ray, const render::SurfaceHit& hit) {
  INFO("ray from (" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") along ("
                    << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z
                    << ") hit at t " << hit.hitT);
  CHECK_FALSE(hit.isHit());
}

}  // namespace penumbra::test
