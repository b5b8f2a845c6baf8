#pragma once
// Reading glTF accessors into plain arrays, with every offset, stride and
// index checked against the buffers first: a bad file is a penumbra::Error
// naming the file and the accessor, never an out-of-bounds read.
#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/scene/input_limits.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

// Accessor `index` as `components` floats per element (its type must have
// exactly that many components), in element order. Normalised integers map
// to [0, 1] / [-1, 1] by the glTF rules (signed: max(c / (2^(n-1) - 1), -1));
// sparse substitutions are applied; an accessor without a buffer view is
// zeros. `where` prefixes every error ("glTF 'a.gltf': mesh 'm' primitive 0 NORMAL").
// The element count is checked against `limits` first (decodedBytes).
std::vector<float> readFloats(const tinygltf::Model& model, int index, int components,
                              const std::string& where, const InputLimits& limits);

// An index accessor: SCALAR unsigned byte, short or int, not normalised.
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, const std::string& where,
                                  const InputLimits& limits);

// The bytes readFloats or readIndices would return for accessor `index`
// (elements x components x 4), after checking its element count against
// limits.maxAccessorElements and, without a buffer view (zeros, free to
// declare), limits.maxZeroFilledElements. Allocates nothing; throws
// penumbra::Error naming the accessor and the limit.
uint64_t decodedBytes(const tinygltf::Model& model, int index, const InputLimits& limits,
                      const std::string& where);

// Element count of accessor `index` (checked to exist).
size_t accessorCount(const tinygltf::Model& model, int index, const std::string& where);

}  // namespace penumbra::scene::gltf
