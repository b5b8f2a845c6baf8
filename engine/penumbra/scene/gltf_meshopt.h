#pragma once
// EXT_meshopt_compression: buffer views stored with meshoptimizer's codecs
// (vertex, index and index-sequence streams, with the octahedral,
// quaternion and exponential filters), as gltfpack and most web pipelines
// write them. Decoded by Debian's libmeshoptimizer; a build without it
// (PENUMBRA_HAVE_MESHOPT undefined: the mingw cross build) refuses files that
// require the extension and reads an optional one's uncompressed fallback.
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

// Whether this build decodes the extension.
bool meshoptSupported();

// A file that uses the extension may give buffers without data of their own
// ("fallback": only loaders without the extension read them), which tinygltf
// refuses. Makes each such buffer an empty data URI in the JSON (rewriting a
// .glb's container around it); files without the extension are unchanged.
void emptyMeshoptFallbacks(std::vector<unsigned char>& data, bool binary, const std::string& at);

// Decodes every compressed buffer view into a buffer of its own appended to
// the model, and points the view at it, so accessors read plain bytes. The
// decoded bytes of all views together are bounded by
// InputLimits::maxDecodedBytes (as the accessors' are); a stream that does
// not decode, or a view that lies outside its buffer, is an error naming the
// view.
void decodeMeshoptViews(tinygltf::Model& model, const InputLimits& limits, const std::string& at);

}  // namespace penumbra::scene::gltf
