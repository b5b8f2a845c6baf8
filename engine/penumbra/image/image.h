#pragma once
// CPU-side images: linear float RGBA (what the renderer accumulates) and
// 8-bit RGBA (display-encoded, for PNG).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::image {

struct Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;  // row-major, top row first, 4 floats a pixel

  Image() = default;
  Image(uint32_t w, uint32_t h) : width(w), height(h), rgba(size_t(w) * h * 4, 0.0f) {}
  float* pixel(uint32_t x, uint32_t y) { return &rgba[(size_t(y) * width + x) * 4]; }
  const float* pixel(uint32_t x, uint32_t y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

struct Image8 {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;
};

// A linear image as 8-bit sRGB, values above 1 clipped: the display transform
// of the default PNG output (ToneMapOperator::Clamp at exposure 1) on the
// CPU, for previews of images that live on the host (a study's report).
Image8 encodeSrgb8(const Image& image);

// The centre of an image, at most maxWidth pixels wide and as high as the
// image's aspect ratio gives that width; pixels are copied, not filtered, so
// the crop shows the noise the full image has (a study's previews).
Image centreCrop(const Image& image, uint32_t maxWidth);

// Pixels with a NaN or infinite channel.
uint64_t countNonFinite(const Image& image);
// Mean of each RGB channel over the rectangle [x0, x1) x [y0, y1).
struct Rgb {
  double r = 0, g = 0, b = 0;
};
Rgb meanRgb(const Image& image, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1);
Rgb meanRgb(const Image& image);

}  // namespace penumbra::image
