#pragma once
// EXT_meshopt_compression: buffer views stored with meshoptimizer's codecs
// (vertex, index and index-sequence streams, with the octahedral,
// quaternion and exponential filters), as gltfpack and most web pipelines
// write them. Decoded by Debian's libmeshoptimizer; a build without it
// (PENUMBRA_HAVE_MESHOPT undefined: the mingw cross build) refuses files that
// require the extension and reads an optional one's uncompressed fallback.
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

// Whether this build decodes the extension.
bool meshoptSupported();

// A file that uses the extension may give buffers without data of their own
// ("fallback": only loaders without the extension read them), which tinygltf
// refuses. Makes each such buffer a one-byte data URI in the file's JSON
// (gltf_container.h's editJson); returns whether anything changed.
bool emptyMeshoptFallbacks(nlohmann::json& doc, bool binary);

// Decodes every compressed buffer view into a buffer of its own appended to
// the model, and points the view at it, so accessors read plain bytes. The
// decoded bytes of all views together are bounded by
// InputLimits::maxDecodedBytes (as the accessors' are); a stream that does
// not decode, or a view that lies outside its buffer, is an error naming the
// view.
void decodeMeshoptViews(tinygltf::Model& model, const InputLimits& limits, const std::string& at);

}  // namespace penumbra::scene::gltf
