#pragma once
// The limits on what a file may make Penumbra allocate or recurse into: one
// definition for every loader of files others make (scene files, render
// settings, glTF), checked before the allocation or the recursion happens,
// so a hostile or broken file ends in one penumbra::Error line naming the
// file, the field and the limit instead of a crash, bad_alloc or an
// out-of-memory kill. docs/security.md tables them with their reasons.
//
// To raise a limit, pass an InputLimits with the field changed to the loader
// (loadScene, parseScene, importGltf, loadGltf, render::renderJobFromJson,
// render::loadRenderJob); the apps use the defaults below, so for them
// raising one means changing it here.
#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "penumbra/scene/scene.h"
#include "penumbra/util/error.h"
#include "penumbra/util/json_nesting.h"

namespace penumbra::scene {

struct InputLimits {
  // JSON text: scene files, render settings, .gltf files and .glb JSON chunks.
  // Nesting is measured before parsing (util/json_nesting.h): the parsers and
  // the code walking their trees recurse per level. Real files nest < 20.
  uint64_t maxJsonDepth = 256;
  // Scene files and render settings (not glTF, whose data URIs may be large):
  // a parsed JSON tree takes ten or more times its text in memory.
  uint64_t maxJsonBytes = uint64_t(256) << 20;

  // The whole scene, whichever loader builds it.
  // Triangles stored in meshes (before instancing): some 40 bytes each on
  // the host in a smooth mesh with every attribute, 150 flat-shaded (glTF
  // without normals: vertices unshared); 2^25 (33.5 million) is 1.3 to 5 GB.
  uint64_t maxTriangles = uint64_t(1) << 25;
  // Mesh instances (each a double 4x4 on the host, a TLAS entry on the GPU).
  uint64_t maxInstances = uint64_t(1) << 22;
  // Implicit objects (each a few hundred bytes and one procedural instance).
  uint64_t maxImplicitObjects = uint64_t(1) << 16;

  // Scene-file generators (scene_generators.h) and the material-test row.
  // A terrain of resolution r has 2 (r - 1)^2 triangles: 4096 is 33.5 million.
  uint64_t maxTerrainResolution = 4096;
  // An icosphere of s subdivisions has 20 * 4^s triangles: 9 is 5.2 million.
  uint64_t maxSphereSubdivisions = 9;

  // glTF (gltf_loader.h). Elements of one accessor, checked before it is
  // decoded into floats or 32-bit indices (4 to 64 bytes an element).
  uint64_t maxAccessorElements = uint64_t(1) << 26;
  // An accessor without a buffer view is zeros by the spec, free to declare:
  // a 232-byte file could ask for gigabytes. Penumbra reads no morph targets,
  // the usual reason for one, so these stay small.
  uint64_t maxZeroFilledElements = uint64_t(1) << 20;
  // Bytes of accessor data decoded (as floats and 32-bit indices) for all
  // primitives of one file together, an accessor counted each time it is
  // read: maxTriangles of a smooth mesh with every attribute fit.
  uint64_t maxDecodedBytes = uint64_t(1) << 31;
  // Nodes visited while flattening the node graph (a DAG reached through
  // many parents multiplies); each visit may add an instance, camera, light.
  uint64_t maxNodeVisits = uint64_t(1) << 22;
  // Images, from their headers before decoding: the largest texture side
  // D3D12 guarantees (as render/image_size.h); pixels of one image (8192^2,
  // 256 MiB as RGBA8) and of all images of one file (1 GiB as RGBA8).
  uint64_t maxImageSide = 16384;
  uint64_t maxImagePixels = uint64_t(1) << 26;
  uint64_t maxTexturePixels = uint64_t(1) << 28;
};

// Throws penumbra::Error "<what> <value> exceeds the limit <limit>
// (InputLimits::<name>; docs/security.md)" if value > limit. `what` names
// the file and the field ("scene 'a.json' generated[0] \"resolution\"").
inline void requireAtMost(uint64_t value, uint64_t limit, const char* name,
                          const std::string& what) {
  if (value > limit)
    throw Error(fmt::format("{} {} exceeds the limit {} (InputLimits::{}; docs/security.md)", what,
                            value, limit, name));
}

// Checks JSON text against maxJsonDepth before it is parsed; `what` names
// the file ("scene 'a.json'").
inline void requireJsonDepth(std::string_view text, const InputLimits& limits,
                             const std::string& what) {
  if (auto at = json_nesting::firstTooDeep(text, limits.maxJsonDepth))
    throw Error(
        fmt::format("{}: JSON nests arrays and objects deeper than the limit {} at byte {} "
                    "(InputLimits::maxJsonDepth; docs/security.md)",
                    what, limits.maxJsonDepth, *at));
}

// Sizes computed from file values saturate: an overflow must not wrap round
// to a small count that passes a limit.
inline uint64_t saturatingAdd(uint64_t a, uint64_t b) {
  return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}
inline uint64_t saturatingMul(uint64_t a, uint64_t b) {
  return b != 0 && a > UINT64_MAX / b ? UINT64_MAX : a * b;
}

// Triangles of makeIcosphere(subdivisions, ...): 20 * 4^subdivisions.
inline uint64_t icosphereTriangles(uint64_t subdivisions) {
  return subdivisions > 29 ? UINT64_MAX : uint64_t(20) << (2 * subdivisions);
}

// Triangles stored in the scene's meshes, before instancing (what
// maxTriangles bounds; Scene::triangleCount counts instanced ones).
inline uint64_t storedTriangles(const Scene& scene) {
  uint64_t n = 0;
  for (const auto& mesh : scene.meshes) n += mesh.indices.size() / 3;
  return n;
}

}  // namespace penumbra::scene
