#include "penumbra/scene/gltf_draco.h"

#include <fmt/format.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "penumbra/scene/gltf_container.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

#ifdef PENUMBRA_HAVE_DRACO
#include <draco/compression/decode.h>
#endif

namespace penumbra::scene::gltf {

bool dracoSupported() {
#ifdef PENUMBRA_HAVE_DRACO
  return true;
#else
  return false;
#endif
}

namespace {
constexpr const char* kExtension = "KHR_draco_mesh_compression";
}  // namespace

bool giveDracoIndicesAView(nlohmann::json& doc) {
  if (!usesExtension(doc, kExtension)) return false;
  auto meshes = doc.find("meshes");
  auto accessors = doc.find("accessors");
  if (meshes == doc.end() || !meshes->is_array() || accessors == doc.end() ||
      !accessors->is_array())
    return false;
  bool changed = false;
  for (auto& mesh : *meshes) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      continue;
    for (auto& primitive : mesh["primitives"]) {
      if (!primitive.is_object()) continue;
      const auto indices = primitive.find("indices");
      const auto exts = primitive.find("extensions");
      if (indices == primitive.end() || !indices->is_number_unsigned() || exts == primitive.end() ||
          !exts->is_object())
        continue;
      const auto ext = exts->find(kExtension);
      if (ext == exts->end() || !ext->is_object()) continue;
      const auto view = ext->find("bufferView");
      const size_t index = indices->get<size_t>();
      if (view == ext->end() || !view->is_number_unsigned() || index >= accessors->size()) continue;
      auto& accessor = (*accessors)[index];
      if (!accessor.is_object() || accessor.contains("bufferView")) continue;
      accessor["bufferView"] = *view;
      changed = true;
    }
  }
  return changed;
}

#ifdef PENUMBRA_HAVE_DRACO
namespace {

// Appends `bytes` as a buffer with one view, and an accessor like `like` over
// it; returns the accessor's index.
int appendAccessor(tinygltf::Model& model, std::vector<unsigned char> bytes,
                   const tinygltf::Accessor& like, const std::string& name) {
  tinygltf::Buffer buffer;
  buffer.name = name;
  buffer.data = std::move(bytes);
  tinygltf::BufferView view;
  view.buffer = int(model.buffers.size());
  view.byteLength = buffer.data.size();
  model.buffers.push_back(std::move(buffer));
  tinygltf::Accessor accessor = like;
  accessor.bufferView = int(model.bufferViews.size());
  accessor.byteOffset = 0;
  accessor.sparse = {};
  model.bufferViews.push_back(view);
  model.accessors.push_back(std::move(accessor));
  return int(model.accessors.size() - 1);
}

template <typename T>
bool convertAll(const draco::Mesh& mesh, const draco::PointAttribute& attribute, int components,
                std::vector<unsigned char>& out) {
  T values[16] = {};
  for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
    if (!attribute.ConvertValue<T>(attribute.mapped_index(i), int8_t(components), values))
      return false;
    std::memcpy(out.data() + size_t(i.value()) * sizeof(T) * size_t(components), values,
                sizeof(T) * size_t(components));
  }
  return true;
}

bool convertAttribute(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                      int componentType, int components, std::vector<unsigned char>& out) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return convertAll<int8_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return convertAll<uint8_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return convertAll<int16_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return convertAll<uint16_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return convertAll<uint32_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return convertAll<float>(mesh, attribute, components, out);
    default:
      return false;
  }
}

class PrimitiveDecoder {
 public:
  PrimitiveDecoder(tinygltf::Model& model, uint64_t& decoded, const InputLimits& limits,
                   std::string where)
      : model_(model), decoded_(decoded), limits_(limits), where_(std::move(where)) {}

  void run(tinygltf::Primitive& primitive, const tinygltf::Value& ext) {
    const tinygltf::Value& viewValue = ext.Get("bufferView");
    const tinygltf::Value& attributes = ext.Get("attributes");
    if (!viewValue.IsInt() || !attributes.IsObject())
      throw Error(fmt::format("{}: {} needs a bufferView and attributes", where_, kExtension));
    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(viewValue.Get<int>());
    for (const auto& name : attributes.Keys()) {
      const tinygltf::Value& id = attributes.Get(name);
      auto found = primitive.attributes.find(name);
      if (!id.IsInt() || found == primitive.attributes.end())
        throw Error(fmt::format("{}: {} attribute {} has no id or no accessor of the primitive",
                                where_, kExtension, name));
      found->second = attribute(*mesh, name, id.Get<int>(), accessor(found->second, name));
    }
    primitive.indices = indices(*mesh, primitive.indices);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;  // Draco decodes strips as lists too
  }

 private:
  std::unique_ptr<draco::Mesh> decodeMesh(int viewIndex) {
    if (viewIndex < 0 || size_t(viewIndex) >= model_.bufferViews.size())
      throw Error(fmt::format("{}: {} buffer view {} does not exist ({} buffer views)", where_,
                              kExtension, viewIndex, model_.bufferViews.size()));
    const auto& view = model_.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
      throw Error(fmt::format("{}: {} buffer view {} uses buffer {} of {}", where_, kExtension,
                              viewIndex, view.buffer, model_.buffers.size()));
    const auto& data = model_.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
      throw Error(fmt::format("{}: {} buffer view {} lies outside its buffer", where_, kExtension,
                              viewIndex));
    draco::DecoderBuffer in;
    in.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&in);
    if (!result.ok())
      throw Error(fmt::format("{}: {} data does not decode (Draco: {})", where_, kExtension,
                              result.status().error_msg_string()));
    return std::move(result).value();
  }

  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
      throw Error(fmt::format("{}: {} accessor {} does not exist ({} accessors)", where_, what,
                              index, model_.accessors.size()));
    return model_.accessors[size_t(index)];
  }

  void count(uint64_t bytes) {
    if (bytes > limits_.maxDecodedBytes || decoded_ + bytes > limits_.maxDecodedBytes)
      throw Error(fmt::format(
          "{}: {} decodes to {} bytes, which brings the file's decoded data past the limit {} "
          "(InputLimits::maxDecodedBytes; docs/security.md)",
          where_, kExtension, bytes, limits_.maxDecodedBytes));
    decoded_ += bytes;
  }

  int attribute(const draco::Mesh& mesh, const std::string& name, int id,
                const tinygltf::Accessor& like) {
    const draco::PointAttribute* source = mesh.GetAttributeByUniqueId(uint32_t(id));
    if (!source)
      throw Error(fmt::format("{}: {} has no attribute {} (for {})", where_, kExtension, id, name));
    if (like.count != size_t(mesh.num_points()))
      throw Error(fmt::format("{}: {} accessor has {} elements, the Draco mesh {} points", where_,
                              name, like.count, mesh.num_points()));
    const int components = tinygltf::GetNumComponentsInType(uint32_t(like.type));
    const int size = tinygltf::GetComponentSizeInBytes(uint32_t(like.componentType));
    if (components <= 0 || components > 16 || size <= 0)
      throw Error(fmt::format("{}: {} accessor has an invalid type", where_, name));
    count(uint64_t(like.count) * uint64_t(components) * uint64_t(size));
    std::vector<unsigned char> bytes(like.count * size_t(components) * size_t(size));
    if (!convertAttribute(mesh, *source, like.componentType, components, bytes))
      throw Error(fmt::format("{}: {} attribute {} ({}) does not convert to its accessor's type",
                              where_, kExtension, id, name));
    return appendAccessor(model_, std::move(bytes), like, fmt::format("{} {}", kExtension, name));
  }

  int indices(const draco::Mesh& mesh, int declared) {
    tinygltf::Accessor like;
    like.type = TINYGLTF_TYPE_SCALAR;
    like.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    if (declared >= 0) like = accessor(declared, "indices");
    const size_t n = size_t(mesh.num_faces()) * 3;
    if (declared >= 0 && like.count != n)
      throw Error(fmt::format("{}: indices accessor has {} elements, the Draco mesh {} triangles",
                              where_, like.count, mesh.num_faces()));
    like.count = n;
    const int size = tinygltf::GetComponentSizeInBytes(uint32_t(like.componentType));
    if (size != 1 && size != 2 && size != 4)
      throw Error(fmt::format("{}: indices accessor has an invalid component type", where_));
    count(uint64_t(n) * uint64_t(size));
    std::vector<unsigned char> bytes(n * size_t(size));
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.face(f)[k].value();
        if (size < 4 && v >= (1u << (8 * size)))
          throw Error(fmt::format("{}: Draco vertex {} does not fit the indices accessor's type",
                                  where_, v));
        std::memcpy(bytes.data() + (size_t(f.value()) * 3 + size_t(k)) * size_t(size), &v,
                    size_t(size));  // little-endian, as the targets
      }
    return appendAccessor(model_, std::move(bytes), like, fmt::format("{} indices", kExtension));
  }

  tinygltf::Model& model_;
  uint64_t& decoded_;
  const InputLimits& limits_;
  std::string where_;
};

}  // namespace
#endif

void decodeDracoPrimitives(tinygltf::Model& model, const InputLimits& limits,
                           const std::string& at) {
#ifdef PENUMBRA_HAVE_DRACO
  uint64_t decoded = 0;
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      auto& primitive = model.meshes[m].primitives[p];
      const auto ext = primitive.extensions.find(kExtension);
      if (ext == primitive.extensions.end()) continue;
      PrimitiveDecoder(model, decoded, limits, fmt::format("{}: mesh {} primitive {}", at, m, p))
          .run(primitive, ext->second);
    }
#else
  // An optional extension's primitives keep their uncompressed accessors (a
  // file that requires it was refused before it was read).
  (void)model, (void)limits, (void)at;
#endif
}

}  // namespace penumbra::scene::gltf
