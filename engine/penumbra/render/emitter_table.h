#pragma once
// The table next-event estimation draws emissive triangles from, built on the
// CPU: each emissive mesh instance's triangles placed in render space, chosen
// in proportion to power (area x luminance of the mean emission). The GPU
// reads it as gpu::EmissiveTriangle rows (path_tracer_shared.h): each
// triangle's choice probability, area and cumulative probability, which the
// shader searches with a uniform number.
#include <glm/glm.hpp>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// One emissive mesh instance, kept in world space (double) so that the table
// can be placed again about another render origin (PathTracer::rebase).
struct EmitterSource {
  glm::dmat4 objectToWorld{1.0};
  bool mirrored = false;             // the transform reverses the winding
  std::vector<glm::vec3> positions;  // object space, three per triangle
  std::vector<glm::vec2> uvs;        // the emission texture's, three per triangle
  glm::vec3 emission{0.0f};
  uint32_t emissionTexture = PT_NO_TEXTURE;  // the emission's TextureRefData index
  double luminance = 0.0;  // of the mean emission (Rec. 709): power = area x luminance
};

// The source for instance `instance` of `scene`, whose material emits. A
// textured emitter is chosen by its mean radiance (emission x the texture's
// mean linear colour); the shader multiplies the texture in where it samples.
EmitterSource emitterSource(const scene::Scene& scene, const scene::Instance& instance);

struct EmitterTable {
  std::vector<gpu::EmissiveTriangle> triangles;  // in the order of the sources
  // How many triangles NEE chooses among: all of them, or 0 when none has
  // power (then NEE samples no emissive triangle).
  uint32_t sampledCount = 0;
};

// Every source's triangles placed by `toRenderSpace`. Zero-area triangles
// get probability 0 and are never chosen; the last cumulative value of a
// triangle with power, and every one after it, is exactly 1, so the search
// always ends on a triangle that can be chosen.
EmitterTable placeEmitters(const std::vector<EmitterSource>& sources,
                           const glm::dmat4& toRenderSpace);

}  // namespace penumbra::render
