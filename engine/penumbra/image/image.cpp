#include "penumbra/image/image.h"

#include <algorithm>
#include <cmath>

namespace penumbra::image {

Image8 encodeSrgb8(const Image& image) {
  std::vector<uint8_t> bytes(image.rgba.size(), 255);
  for (size_t i = 0; i < image.rgba.size(); ++i) {
    if (i % 4 == 3) continue;  // opaque
    // NaN clips to 0 like the shader's saturate; the sRGB transfer function.
    const float v = image.rgba[i];
    const float x = std::isnan(v) ? 0.0f : std::min(std::max(v, 0.0f), 1.0f);
    const float e = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
    bytes[i] = uint8_t(std::lround(e * 255.0f));
  }
  Image8 out;
  out.width = image.width;
  out.height = image.height;
  out.rgba = std::move(bytes);
  return out;
}

Image centreCrop(const Image& image, uint32_t maxWidth) {
  if (image.width <= maxWidth) return image;
  const uint32_t height =
      std::max(1u, uint32_t((uint64_t(maxWidth) * image.height + image.width / 2) / image.width));
  Image out(maxWidth, height);
  const uint32_t x0 = (image.width - maxWidth) / 2, y0 = (image.height - height) / 2;
  for (uint32_t y = 0; y < height; ++y)
    std::copy_n(image.pixel(x0, y0 + y), size_t(maxWidth) * 4, out.pixel(0, y));
  return out;
}

uint64_t countNonFinite(const Image& image) {
  uint64_t count = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    if (!std::isfinite(image.rgba[i]) || !std::isfinite(image.rgba[i + 1]) ||
        !std::isfinite(image.rgba[i + 2]) || !std::isfinite(image.rgba[i + 3]))
      ++count;
  return count;
}

Rgb meanRgb(const Image& image, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
  Rgb sum;
  uint64_t n = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) {
      const float* p = image.pixel(x, y);
      sum.r += p[0];
      sum.g += p[1];
      sum.b += p[2];
      ++n;
    }
  if (n > 0) {
    sum.r /= double(n);
    sum.g /= double(n);
    sum.b /= double(n);
  }
  return sum;
}

Rgb meanRgb(const Image& image) {
  return meanRgb(image, 0, 0, image.width, image.height);
}

}  // namespace penumbra::image
