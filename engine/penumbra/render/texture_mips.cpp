#include "penumbra/render/texture_mips.h"

#include <algorithm>
#include <cmath>

namespace penumbra::render {
float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float c) {
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

namespace {

struct Tap {
  uint32_t source;
  float weight;
};

// The box filter from `from` texels to `to` along one axis: destination
// texel i covers source [i s, (i + 1) s), s = from / to, and weighs each
// source texel by its overlap over s. Every source texel's weights sum to
// 1 / s, so the mean is kept.
std::vector<std::vector<Tap>> boxTaps(uint32_t from, uint32_t to) {
  std::vector<std::vector<Tap>> taps(to);
  const double s = double(from) / double(to);
  for (uint32_t i = 0; i < to; ++i) {
    const double begin = i * s, end = (i + 1) * s;
    for (auto j = uint32_t(std::floor(begin)); j < from && double(j) < end; ++j) {
      const double overlap = std::min(end, double(j + 1)) - std::max(begin, double(j));
      if (overlap > 0.0) taps[i].push_back({j, float(overlap / s)});
    }
  }
  return taps;
}

// One level from the one above it: rows first, then columns.
std::vector<float> downsample(const std::vector<float>& src, uint32_t width, uint32_t height,
                              uint32_t toWidth, uint32_t toHeight) {
  const auto across = boxTaps(width, toWidth), down = boxTaps(height, toHeight);
  std::vector<float> rows(size_t(toWidth) * height * 4, 0.0f);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < toWidth; ++x)
      for (const Tap& t : across[x])
        for (int c = 0; c < 4; ++c)
          rows[(size_t(y) * toWidth + x) * 4 + c] +=
              t.weight * src[(size_t(y) * width + t.source) * 4 + c];
  std::vector<float> out(size_t(toWidth) * toHeight * 4, 0.0f);
  for (uint32_t y = 0; y < toHeight; ++y)
    for (const Tap& t : down[y])
      for (uint32_t x = 0; x < toWidth; ++x)
        for (int c = 0; c < 4; ++c)
          out[(size_t(y) * toWidth + x) * 4 + c] +=
              t.weight * rows[(size_t(t.source) * toWidth + x) * 4 + c];
  return out;
}

}  // namespace

std::vector<uint8_t> mipChainRgba8(const uint8_t* rgba8, uint32_t width, uint32_t height,
                                   bool srgb) {
  const size_t texels = size_t(width) * height;
  std::vector<uint8_t> chain(rgba8, rgba8 + texels * 4);
  std::vector<float> level(texels * 4);
  for (size_t i = 0; i < texels * 4; ++i) {
    const float v = rgba8[i] / 255.0f;
    level[i] = srgb && i % 4 != 3 ? srgbToLinear(v) : v;
  }
  while (width > 1 || height > 1) {
    const uint32_t toWidth = std::max(1u, width >> 1), toHeight = std::max(1u, height >> 1);
    level = downsample(level, width, height, toWidth, toHeight);
    width = toWidth;
    height = toHeight;
    for (size_t i = 0; i < level.size(); ++i) {
      const float v = std::clamp(level[i], 0.0f, 1.0f);
      chain.push_back(uint8_t(std::lround((srgb && i % 4 != 3 ? linearToSrgb(v) : v) * 255.0f)));
    }
  }
  return chain;
}

}  // namespace penumbra::render
