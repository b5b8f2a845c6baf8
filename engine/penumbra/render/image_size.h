#pragma once
// The one limit on a rendered image's size, for every pass, the CLI, render
// settings and the viewer: 16384 per side, D3D12's guaranteed 2D texture
// size (D3D12_REQ_TEXTURE2D_U_OR_V_DIMENSION), which every Vulkan device
// with ray tracing meets too.
#include <fmt/format.h>

#include <cstdint>

#include "penumbra/util/error.h"

namespace penumbra::render {

inline constexpr uint32_t kMaxImageSide = 16384;

constexpr bool isValidImageSize(uint64_t width, uint64_t height) {
  return width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide;
}

// Throws penumbra::Error "<who>: image size WxH is outside 1..16384".
inline void requireValidImageSize(const char* who, uint64_t width, uint64_t height) {
  if (!isValidImageSize(width, height))
    throw Error(
        fmt::format("{}: image size {}x{} is outside 1..{}", who, width, height, kMaxImageSide));
}

}  // namespace penumbra::render
