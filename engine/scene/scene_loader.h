#pragma once
// Penumbra's scene files (JSON). Built-in scenes are embedded in the binary
// and found by name; anything else is read from a path.
//
// Format (version 1):
//   { "format": "penumbra-scene", "version": 1, "name": "...",
//     "unitScale": 0.001,                        // file units -> metres
//     "camera": { "position": [x,y,z], "forward": [x,y,z], "up": [x,y,z],
//                 "verticalFovDegrees": 39.3077 },
//     "materials": { "white": { "model": "lambert", "albedo": [r,g,b],
//                               "emission": [r,g,b] }, ... },
//       model "disney" (default): baseColor, metallic, roughness, anisotropic,
//         specular, specularTint, sheen, sheenTint, clearcoat, clearcoatGloss,
//         specTrans, ior, subsurface, thin; "lambert": albedo (= baseColor);
//       "phong": baseColor (kd), ks, exponent, reflectivity, transparency, ior
//     "lights": [ { "type": "point", "position": [..], "intensity": [..] },
//                 { "type": "spot", ..., "direction": [..], "outerConeDegrees": 30,
//                   "innerConeDegrees": 25 } ],          // optional
//     "ambient": [r,g,b],                               // optional, Whitted
//     "meshes": [ { "name": "floor", "material": "white",
//                   "quads": [ [[x,y,z],[x,y,z],[x,y,z],[x,y,z]], ... ] } ] }
// Each quad is split into two counter-clockwise triangles (v0 v1 v2, v0 v2 v3);
// each mesh becomes one instance with the identity transform.
//     "materialTest": { "material": "base", "vary": "roughness", "count": 7,
//                       "radius": 0.4, "first": [x,y,z], "last": [x,y,z] }
//       a row of spheres from `first` to `last` (centres) sharing material
//       "base", with `vary` from 0 to 1 (scene/material_row.h); optional.
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace penumbra::scene {

// `nameOrPath`: a built-in scene name ("cornell-box") or a path to a .json file.
Scene loadScene(const std::string& nameOrPath);
Scene parseScene(std::string_view json, const std::string& source);
std::vector<std::string> builtInSceneNames();

}  // namespace penumbra::scene
