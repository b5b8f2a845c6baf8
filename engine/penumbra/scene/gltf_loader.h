#pragma once
// glTF 2.0 files (.gltf with external or data-URI buffers, .glb) as scenes,
// read with tinygltf.
//
// - The default scene (or the first; without scenes, every root node) is
//   flattened: node TRS or matrices compose into world transforms.
// - Each triangle primitive of a glTF mesh becomes one scene Mesh (one BLAS),
//   and every node that references the glTF mesh adds one Instance of each of
//   its primitives' Meshes, so a mesh used by many nodes is stored once.
// - TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN are read (strips and fans as
//   triangle lists); points and lines are skipped with a warning.
// - Without NORMAL a primitive gets flat normals (its vertices are unshared);
//   without TANGENT, tangents are generated from TEXCOORD_0
//   (scene/mesh_attributes.h).
// - Skinned meshes follow their joints (gltf_skin.h); nodes and morph
//   weights take an animation's values at a chosen time (AnimationChoice,
//   gltf_animation.h). A mesh drawn with other morph weights, or skinned, is
//   a scene Mesh of its own.
// - Perspective and orthographic cameras become Scene::cameras; the scene's
//   view is the camera of the lowest-numbered node in the scene, or, without
//   one, a three-quarter view that frames the scene's bounds
//   (camera_placement.h).
// - Materials map onto the Disney parameters with the Lambert diffuse
//   (scene/gltf_materials.h, docs/materials.md); emissive primitives are
//   area lights.
// - An extension in extensionsRequired that is not supported is an error; an
//   unsupported one that is only used gives a warning naming it.
// Every failure on bad input is one penumbra::Error line naming the file and
// the part of it at fault.
#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// Which files a glTF file may read besides itself (its buffers' and images'
// URIs). By default only files inside the glTF file's own folder (and its
// subfolders), after resolving "..", links and absolute paths, so a scene
// someone else made cannot read other files of the user's; data: URIs and
// .glb chunks are always fine.
struct FileAccess {
  bool allowOutsideFolder = false;  // --allow-external-files
};

// The moment of the file's animations to draw. By default none: the
// nodes' own transforms and morph weights (skins follow their joints there,
// the rest pose). With `seconds` and no `animation`, the file's first
// animation; with `animation` and no `seconds`, its time 0.
struct AnimationChoice {
  // Name, or index ("0" the first) where no animation has that name; "all":
  // every animation at once (later ones win on shared targets).
  std::string animation;
  std::optional<double> seconds;
  bool empty() const { return animation.empty() && !seconds; }
};

struct GltfImport {
  Scene scene;
  std::vector<std::string> warnings;  // one line each, already naming the file
};

// Reads a .gltf or .glb file; returns warnings instead of printing them.
// `limits` bound what the file may make it allocate (input_limits.h): JSON
// nesting, accessor element counts, decoded bytes, triangles, instances,
// node visits and image sizes (read from each image's header first).
// `animation`: the moment drawn (AnimationChoice).
GltfImport importGltf(const std::string& path, const FileAccess& access = {},
                      const InputLimits& limits = {}, const AnimationChoice& animation = {});

// importGltf, with its warnings written to the log.
Scene loadGltf(const std::string& path, const FileAccess& access = {},
               const InputLimits& limits = {}, const AnimationChoice& animation = {});

// Whether `path` names a glTF file by its extension (.gltf, .glb; any case).
bool isGltfPath(const std::string& path);

}  // namespace penumbra::scene
