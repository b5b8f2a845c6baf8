#include "penumbra/scene/gltf_meshopt.h"

#include <fmt/format.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "penumbra/scene/gltf_container.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

#ifdef PENUMBRA_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif

namespace penumbra::scene::gltf {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

// The view's extension object, read with the spec's defaults.
struct CompressedView {
  int buffer = -1;
  size_t byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
  std::string mode, filter = "NONE";
};

size_t unsignedMember(const tinygltf::Value& ext, const char* name, bool required,
                      const std::string& where) {
  const tinygltf::Value& v = ext.Get(name);
  if (!v.IsNumber()) {
    if (!required) return 0;
    throw Error(fmt::format("{}: {} has no {}", where, kExtension, name));
  }
  const double d = v.GetNumberAsDouble();
  if (!(d >= 0.0 && d <= 9.0e15) || double(size_t(d)) != d)
    throw Error(fmt::format("{}: {} {} {} is not a byte count", where, kExtension, name, d));
  return size_t(d);
}

CompressedView readView(const tinygltf::Value& ext, const std::string& where) {
  CompressedView v;
  v.buffer = int(unsignedMember(ext, "buffer", true, where));
  v.byteOffset = unsignedMember(ext, "byteOffset", false, where);
  v.byteLength = unsignedMember(ext, "byteLength", true, where);
  v.byteStride = unsignedMember(ext, "byteStride", true, where);
  v.count = unsignedMember(ext, "count", true, where);
  if (!ext.Get("mode").IsString())
    throw Error(fmt::format("{}: {} has no mode", where, kExtension));
  v.mode = ext.Get("mode").Get<std::string>();
  if (ext.Get("filter").IsString()) v.filter = ext.Get("filter").Get<std::string>();
  return v;
}

}  // namespace

bool meshoptSupported() {
#ifdef PENUMBRA_HAVE_MESHOPT
  return true;
#else
  return false;
#endif
}

bool emptyMeshoptFallbacks(nlohmann::json& doc, bool binary) {
  if (!usesExtension(doc, kExtension)) return false;
  auto buffers = doc.find("buffers");
  if (buffers == doc.end() || !buffers->is_array()) return false;
  bool changed = false;
  size_t index = 0;
  for (auto& buffer : *buffers) {
    // A .glb's first buffer without a URI is its BIN chunk, never a fallback.
    const bool binChunk = binary && index++ == 0;
    if (binChunk || !buffer.is_object() || buffer.contains("uri")) continue;
    const auto ext = buffer.find("extensions");
    if (ext == buffer.end() || !ext->is_object() || !ext->contains(kExtension)) continue;
    // One zero byte: tinygltf refuses an empty data URI.
    buffer["uri"] = "data:application/octet-stream;base64,AA==";
    buffer["byteLength"] = 1;
    changed = true;
  }
  return changed;
}

void decodeMeshoptViews(tinygltf::Model& model, const InputLimits& limits, const std::string& at) {
  // Without the decoder an optional extension's views keep their fallback
  // bytes (a file that requires it was refused before it was read).
  if (!meshoptSupported()) return;
  uint64_t decoded = 0;
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    auto found = model.bufferViews[i].extensions.find(kExtension);
    if (found == model.bufferViews[i].extensions.end()) continue;
    const std::string where = fmt::format("{}: buffer view {}", at, i);
    const CompressedView v = readView(found->second, where);
    if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size())
      throw Error(fmt::format("{}: {} buffer {} does not exist ({} buffers)", where, kExtension,
                              v.buffer, model.buffers.size()));
    const auto& source = model.buffers[size_t(v.buffer)].data;
    if (v.byteOffset > source.size() || v.byteLength > source.size() - v.byteOffset)
      throw Error(fmt::format("{}: {} bytes {} to {} lie outside buffer {} ({} bytes)", where,
                              kExtension, v.byteOffset, v.byteOffset + v.byteLength, v.buffer,
                              source.size()));
    const bool attributes = v.mode == "ATTRIBUTES";
    if (attributes ? (v.byteStride == 0 || v.byteStride % 4 != 0 || v.byteStride > 256)
                   : (v.byteStride != 2 && v.byteStride != 4))
      throw Error(fmt::format("{}: {} byteStride {} is not valid for mode {}", where, kExtension,
                              v.byteStride, v.mode));
    if (v.count > limits.maxDecodedBytes / v.byteStride ||
        decoded + v.count * v.byteStride > limits.maxDecodedBytes)
      throw Error(fmt::format(
          "{}: {} decodes to {} x {} bytes, which brings the file's decoded data past the limit "
          "{} (InputLimits::maxDecodedBytes; docs/security.md)",
          where, kExtension, v.count, v.byteStride, limits.maxDecodedBytes));
    decoded += v.count * v.byteStride;
    tinygltf::Buffer out;
    out.name = fmt::format("{} of buffer view {}", kExtension, i);
    out.data.resize(v.count * v.byteStride);
#ifdef PENUMBRA_HAVE_MESHOPT
    const unsigned char* bytes = source.data() + v.byteOffset;
    int status = -1;
    if (attributes)
      status =
          meshopt_decodeVertexBuffer(out.data.data(), v.count, v.byteStride, bytes, v.byteLength);
    else if (v.mode == "TRIANGLES")
      status = v.count % 3 == 0 ? meshopt_decodeIndexBuffer(out.data.data(), v.count, v.byteStride,
                                                            bytes, v.byteLength)
                                : -1;
    else if (v.mode == "INDICES")
      status =
          meshopt_decodeIndexSequence(out.data.data(), v.count, v.byteStride, bytes, v.byteLength);
    else
      throw Error(fmt::format("{}: {} mode '{}' is not ATTRIBUTES, TRIANGLES or INDICES", where,
                              kExtension, v.mode));
    if (status != 0)
      throw Error(
          fmt::format("{}: {} data does not decode as {} of {} x {} bytes (meshoptimizer: {})",
                      where, kExtension, v.mode, v.count, v.byteStride, status));
    if (v.filter == "OCTAHEDRAL" && attributes && (v.byteStride == 4 || v.byteStride == 8))
      meshopt_decodeFilterOct(out.data.data(), v.count, v.byteStride);
    else if (v.filter == "QUATERNION" && attributes && v.byteStride == 8)
      meshopt_decodeFilterQuat(out.data.data(), v.count, v.byteStride);
    else if (v.filter == "EXPONENTIAL" && attributes && v.byteStride % 4 == 0)
      meshopt_decodeFilterExp(out.data.data(), v.count, v.byteStride);
    else if (v.filter != "NONE")
      throw Error(fmt::format("{}: {} filter '{}' does not apply to mode {} with byteStride {}",
                              where, kExtension, v.filter, v.mode, v.byteStride));
#endif
    auto& view = model.bufferViews[i];
    view.buffer = int(model.buffers.size());
    view.byteOffset = 0;
    view.byteLength = out.data.size();
    model.buffers.push_back(std::move(out));
  }
}

}  // namespace penumbra::scene::gltf
