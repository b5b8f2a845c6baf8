#include "penumbra/scene/gltf_accessors.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"

namespace penumbra::scene::gltf {
namespace {

size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

template <class T>
T load(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));  // glTF data is little-endian, as are the targets
  return v;
}

float decodeFloat(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = float(load<int8_t>(p));
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float v = float(load<uint8_t>(p));
      return normalized ? v / 255.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = float(load<int16_t>(p));
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = float(load<uint16_t>(p));
      return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return float(load<uint32_t>(p));
    default:
      return load<float>(p);
  }
}

uint32_t decodeIndex(const uint8_t* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<uint16_t>(p);
    default:
      return load<uint32_t>(p);
  }
}

// The first byte of `count` elements of `elementSize` bytes, `stride` apart,
// starting `byteOffset` into buffer view `viewIndex`, after checking that they
// lie inside the view and the view inside its buffer.
const uint8_t* viewData(const tinygltf::Model& model, int viewIndex, size_t byteOffset,
                        size_t stride, size_t count, size_t elementSize, const std::string& where) {
  if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
    throw Error(fmt::format("{}: buffer view {} does not exist ({} buffer views)", where, viewIndex,
                            model.bufferViews.size()));
  const auto& view = model.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    throw Error(fmt::format("{}: buffer view {} refers to buffer {} of {}", where, viewIndex,
                            view.buffer, model.buffers.size()));
  const auto& buffer = model.buffers[size_t(view.buffer)];
  const size_t size = buffer.data.size();
  if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
    throw Error(fmt::format("{}: buffer view {} spans bytes {}..{} but buffer {} holds {} bytes",
                            where, viewIndex, view.byteOffset, view.byteOffset + view.byteLength,
                            view.buffer, size));
  if (count == 0) return buffer.data.data() + view.byteOffset;
  // count <= byteLength keeps stride * (count - 1) far from overflowing.
  if (byteOffset > view.byteLength || count > view.byteLength ||
      stride * (count - 1) + elementSize > view.byteLength - byteOffset)
    throw Error(
        fmt::format("{}: {} elements of {} bytes, {} apart, from byte {} do not fit in "
                    "buffer view {} ({} bytes)",
                    where, count, elementSize, stride, byteOffset, viewIndex, view.byteLength));
  return buffer.data.data() + view.byteOffset + byteOffset;
}

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int index,
                                     const std::string& where) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    throw Error(fmt::format("{}: accessor {} does not exist ({} accessors)", where, index,
                            model.accessors.size()));
  return model.accessors[size_t(index)];
}

// Decodes every component of an accessor, sparse substitution included.
template <class T, class Decode>
std::vector<T> readComponents(const tinygltf::Model& model, const tinygltf::Accessor& a,
                              const std::string& where, Decode decode) {
  const size_t csize = componentSize(a.componentType);
  const int comps = componentCount(a.type);
  const size_t elementSize = csize * size_t(comps);
  std::vector<T> out;
  if (a.bufferView >= 0) {
    size_t stride = elementSize;
    if (size_t(a.bufferView) < model.bufferViews.size()) {
      const size_t declared = model.bufferViews[size_t(a.bufferView)].byteStride;
      if (declared != 0) {
        if (declared < elementSize || declared % csize != 0)
          throw Error(
              fmt::format("{}: byte stride {} of buffer view {} does not fit {}-byte elements",
                          where, declared, a.bufferView, elementSize));
        stride = declared;
      }
    }
    const uint8_t* base =
        viewData(model, a.bufferView, a.byteOffset, stride, a.count, elementSize, where);
    out.reserve(a.count * size_t(comps));
    for (size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < comps; ++c) out.push_back(decode(base + i * stride + size_t(c) * csize));
  } else {
    // No buffer view: zeros, possibly overridden by sparse values (glTF
    // 3.6.2.3); decodedBytes has bounded the count.
    out.assign(a.count * size_t(comps), T(0));
  }
  if (!a.sparse.isSparse) return out;

  const auto& sp = a.sparse;
  if (sp.count < 1 || size_t(sp.count) > a.count)
    throw Error(fmt::format("{}: sparse count {} is not in 1..{}", where, sp.count, a.count));
  const int indexType = sp.indices.componentType;
  if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw Error(fmt::format("{}: sparse indices have component type {}, not an unsigned integer",
                            where, indexType));
  const size_t indexSize = componentSize(indexType);
  const size_t n = size_t(sp.count);
  const uint8_t* indices =
      viewData(model, sp.indices.bufferView, size_t(std::max(0, sp.indices.byteOffset)), indexSize,
               n, indexSize, where + " sparse indices");
  const uint8_t* values =
      viewData(model, sp.values.bufferView, size_t(std::max(0, sp.values.byteOffset)), elementSize,
               n, elementSize, where + " sparse values");
  for (size_t i = 0; i < n; ++i) {
    const uint32_t target = decodeIndex(indices + i * indexSize, indexType);
    if (target >= a.count)
      throw Error(fmt::format("{}: sparse index {} is outside the accessor's {} elements", where,
                              target, a.count));
    for (int c = 0; c < comps; ++c)
      out[size_t(target) * size_t(comps) + size_t(c)] =
          decode(values + i * elementSize + size_t(c) * csize);
  }
  return out;
}

const char* typeName(int components) {
  switch (components) {
    case 1:
      return "SCALAR";
    case 2:
      return "VEC2";
    case 3:
      return "VEC3";
    case 4:
      return "VEC4";
    default:
      return "a matrix";
  }
}

}  // namespace

size_t accessorCount(const tinygltf::Model& model, int index, const std::string& where) {
  return accessorAt(model, index, where).count;
}

uint64_t decodedBytes(const tinygltf::Model& model, int index, const InputLimits& limits,
                      const std::string& where) {
  const std::string at = fmt::format("{} (accessor {})", where, index);
  const auto& a = accessorAt(model, index, at);
  if (a.bufferView < 0)
    requireAtMost(a.count, limits.maxZeroFilledElements, "maxZeroFilledElements",
                  at + " element count without a buffer view");
  requireAtMost(a.count, limits.maxAccessorElements, "maxAccessorElements", at + " element count");
  return uint64_t(a.count) * uint64_t(componentCount(a.type)) * 4;
}

std::vector<float> readFloats(const tinygltf::Model& model, int index, int components,
                              const std::string& where, const InputLimits& limits) {
  const std::string at = fmt::format("{} (accessor {})", where, index);
  decodedBytes(model, index, limits, where);
  const auto& a = accessorAt(model, index, at);
  if (componentSize(a.componentType) == 0)
    throw Error(fmt::format("{}: unknown component type {}", at, a.componentType));
  if (componentCount(a.type) != components)
    throw Error(fmt::format("{}: is {}, expected {}", at, typeName(componentCount(a.type)),
                            typeName(components)));
  if (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    throw Error(fmt::format("{}: only 8- and 16-bit integers can be normalized", at));
  const int type = a.componentType;
  const bool normalized = a.normalized;
  return readComponents<float>(model, a, at, [type, normalized](const uint8_t* p) {
    return decodeFloat(p, type, normalized);
  });
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, const std::string& where,
                                  const InputLimits& limits) {
  const std::string at = fmt::format("{} (accessor {})", where, index);
  decodedBytes(model, index, limits, where);
  const auto& a = accessorAt(model, index, at);
  const int type = a.componentType;
  if (a.type != TINYGLTF_TYPE_SCALAR || a.normalized ||
      (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
       type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
       type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    throw Error(
        fmt::format("{}: indices must be unnormalized unsigned byte, short or int scalars", at));
  return readComponents<uint32_t>(model, a, at,
                                  [type](const uint8_t* p) { return decodeIndex(p, type); });
}

}  // namespace penumbra::scene::gltf
