#pragma once
// Penumbra's scene files (JSON). Built-in scenes are embedded in the binary
// and found by name; anything else is read from a path.
//
// Format (version 1):
//   { "format": "penumbra-scene", "version": 1, "name": "...",
//     "unitScale": 0.001,                        // file units -> metres
//     "camera": { "position": [x,y,z], "forward": [x,y,z], "up": [x,y,z],
//                 "verticalFovDegrees": 39.3077 },  // or "orthographicHeight": 2
//                                                   // (file units; a parallel view)
//     "materials": { "white": { "model": "lambert", "albedo": [r,g,b],
//                               "emission": [r,g,b] }, ... },
//       model "disney" (default): baseColor, metallic, roughness, anisotropic,
//         specular, specularTint, specularColor, specularF90, sheen, sheenTint,
//         sheenColor, clearcoat, clearcoatGloss, specTrans, ior, subsurface,
//         thin, attenuationColor, attenuationDistance, diffuseTransmission,
//         diffuseTransmissionColor, iridescence, iridescenceIor,
//         iridescenceThickness (nm), dispersion, anisotropyStrength and
//         anisotropyRotation (radians; glTF's anisotropy, along the mesh's
//         tangents); docs/materials.md says what each does; "lambert": albedo
//         (= baseColor), the same parameters with glTF's coat and sheen
//         (sheenRoughness: its fibres' roughness);
//       "phong": baseColor (kd), ks, exponent, reflectivity, transparency, ior;
//       "unlit": baseColor, the radiance seen (glTF KHR_materials_unlit)
//     "lights": [ { "type": "point", "position": [..], "intensity": [..],  // W/sr
//                   "range": 10 },                       // optional: no light beyond
//                 { "type": "spot", ..., "direction": [..], "outerConeDegrees": 30,
//                   "innerConeDegrees": 25 },            // falloff as KHR_lights_punctual
//                 { "type": "directional", "direction": [..],  // the way the light travels
//                   "intensity": [..] } ],               // irradiance, W/m^2; optional
//     "camera": { ..., "apertureRadius": 0, "focusDistance": 1 },  // optional thin lens
//     "ambient": [r,g,b],                               // optional, Whitted
//     "meshes": [ { "name": "floor", "material": "white",
//                   "quads": [ [[x,y,z],[x,y,z],[x,y,z],[x,y,z]], ... ] } ],
//     "implicits": [ { "name": "ball", "kind": "sphere", "material": "white",
//                      "radius": 0.5,
//                      "transform": { "translate": [x,y,z],
//                                     "rotate": { "axis": [x,y,z], "degrees": 30 },
//                                     "scale": 2 } }, ... ] }
// "meshes" and "implicits" are each optional; a scene needs one of them.
// Each quad is split into two counter-clockwise triangles (v0 v1 v2, v0 v2 v3);
// each mesh becomes one instance with the identity transform.
//     "generated": [ ... ]   procedural terrain, sphere grids and implicit-object
//       grids (scene/scene_generators.h); optional.
//     "materialTest": { "material": "base", "vary": "roughness", "count": 7,
//                       "radius": 0.4, "first": [x,y,z], "last": [x,y,z] }
//       a row of spheres from `first` to `last` (centres) sharing material
//       "base", with `vary` from 0 to 1 (scene/material_row.h); optional.
//
// glTF files merge into the scene (engine/penumbra/scene/gltf_loader.h):
//     "gltf": [ { "file": "models/x.glb",        // relative to the scene file
//                 "transform": [16 numbers],    // column-major 4x4, as glTF's "matrix"
//                 "translation": [x,y,z], "rotation": [x,y,z,w], "scale": [x,y,z],
//                 "camera": "NAME",             // all optional but "file"
//                 "animation": "NAME" or index, "time": seconds } ]  // AnimationChoice
//   "transform" and translation/rotation/scale are alternatives (T * R * S),
//   applied on top of the file's own node transforms; glTF files are in
//   metres, so "unitScale" does not apply to them. With a "gltf" list,
//   "materials" and "meshes" may be left out, and so may "camera": the view
//   is then the first file's camera "NAME", or its default camera. Every
//   file's cameras join Scene::cameras (for `--camera NAME`).
//
// Implicit objects (scene/implicit_object.h), shape parameters in object space:
//   "sphere": radius; "plane": the plane y = 0 facing +y, infinite, or
//   bounded by "halfExtents": [x, z]; "box": halfExtents [x,y,z];
//   "torus": majorRadius, minorRadius (around the y axis);
//   "roundedBox": halfExtents, cornerRadius; "mandelbulb": power (default 8),
//   iterations (default 12); "blend": blendRadius and "primitives": 2-4 of
//   { "kind": sphere|box|torus|roundedBox, shape keys, "offset": [x,y,z] }.
// Torus, roundedBox, blend and mandelbulb are sphere traced: "maxSteps"
// (default 256, >= 1) and "tolerance" (object-space distance, default 1e-4).
// "transform" is optional: object to world = translate * rotate * scale
// (then unitScale); "scale" is a number or [x,y,z], and only the analytic
// kinds (sphere, plane, box) accept non-uniform scale. Unknown keys are errors.
// Emissive materials work on implicit objects; they emit from the outside
// (the +y side of a plane) and are found by BSDF sampling only, not by NEE.
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// `nameOrPath`: a built-in scene name ("cornell-box"), a path to a .json
// scene file, or a glTF file (.gltf, .glb) loaded as a scene on its own.
// `access`: what the glTF files it loads may read besides themselves.
// `limits`: what the file may make the loader allocate (input_limits.h);
// the glTF files it names are held to them too. `animation`: the moment of
// every glTF file's animations to draw, over a "gltf" entry's own; a scene
// with no glTF file to animate is an error.
Scene loadScene(const std::string& nameOrPath, const FileAccess& access = {},
                const InputLimits& limits = {}, const AnimationChoice& animation = {});
// `baseDirectory`: where the "gltf" files' relative paths start.
Scene parseScene(std::string_view json, const std::string& source,
                 const std::string& baseDirectory = "", const FileAccess& access = {},
                 const InputLimits& limits = {}, const AnimationChoice& animation = {});
std::vector<std::string> builtInSceneNames();

}  // namespace penumbra::scene
