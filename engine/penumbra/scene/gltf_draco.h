#pragma once
// KHR_draco_mesh_compression: primitives whose attributes and indices are
// one Draco-compressed mesh in a buffer view. Decoded by Debian's libdraco; a
// build without it (PENUMBRA_HAVE_DRACO undefined: the mingw cross build)
// refuses files that require the extension and reads an optional one's
// uncompressed accessors.
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

// Whether this build decodes the extension.
bool dracoSupported();

// Exporters give a compressed primitive's index accessor no buffer view (its
// data is in the Draco mesh), which tinygltf refuses. Points each such
// accessor at the primitive's Draco buffer view in the file's JSON
// (gltf_container.h's editJson; decodeDracoPrimitives replaces the accessor);
// returns whether anything changed.
bool giveDracoIndicesAView(nlohmann::json& doc);

// Decodes each compressed primitive and gives it new accessors over the
// decoded values (in buffers appended to the model), of the component types
// and counts its own accessors declare, so the primitive reader reads plain
// data. Attributes the extension does not name keep their accessors. The
// decoded bytes of all primitives together are bounded by
// InputLimits::maxDecodedBytes; data that does not decode, or that disagrees
// with the accessors, is an error naming the primitive. (Draco sizes its own
// allocations from the compressed stream.)
void decodeDracoPrimitives(tinygltf::Model& model, const InputLimits& limits,
                           const std::string& at);

}  // namespace penumbra::scene::gltf
