#pragma once
// Edits of a glTF file's JSON before tinygltf reads it, for extensions whose
// valid files tinygltf would refuse (EXT_meshopt_compression's fallback
// buffers without data, KHR_draco_mesh_compression's index accessors without
// a buffer view).
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace penumbra::scene::gltf {

// Parses the JSON of `data` (a .gltf, or a .glb's JSON chunk), hands it to
// `edit`, and if `edit` returns true writes it back (rebuilding a .glb's
// container around the new chunk). JSON that does not parse is left for
// tinygltf to report.
void editJson(std::vector<unsigned char>& data, bool binary,
              const std::function<bool(nlohmann::json&)>& edit, const std::string& at);

// Whether the document lists `extension` in extensionsUsed.
bool usesExtension(const nlohmann::json& doc, const char* extension);

}  // namespace penumbra::scene::gltf
