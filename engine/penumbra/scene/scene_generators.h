#pragma once
// Procedural content in scene files, for scenes too large to list: the
// "generated" array of the JSON format (scene_loader.h), used by the
// performance scene.
//
//   { "kind": "terrain", "material": "rock", "resolution": 1582, "size": 40,
//     "height": 2, "octaves": 6, "seed": 1, "translate": [x,y,z] }
//       a heightfield mesh (scene/terrain.h), 2 (resolution - 1)^2 triangles;
//   { "kind": "spheres", "material": "m", "count": [nx, nz], "spacing": s,
//     "origin": [x,y,z], "radius": r, "subdivisions": 6 }
//       a grid of icosphere meshes (20 * 4^subdivisions triangles each), one
//       BLAS instanced nx * nz times;
//   { "kind": "implicitGrid", "materials": ["a", "b"], "count": [nx, ny, nz],
//     "spacing": s, "origin": [x,y,z], "size": r }
//       nx * ny * nz implicit objects of size r cycling through sphere, box,
//       torus and rounded box, and through the materials.
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// Appends what each entry of `generated` describes to `scene`; lengths are
// multiplied by `scale`. Throws penumbra::Error naming the entry, and the
// limit, before allocating anything that would pass `limits` (terrain
// resolution, sphere subdivisions, and the scene's triangles, instances and
// implicit objects with the entry added).
void addGenerated(Scene& scene, const nlohmann::json& generated,
                  const std::map<std::string, uint32_t>& materialIndex, float scale,
                  const std::string& at, const InputLimits& limits = {});

}  // namespace penumbra::scene
