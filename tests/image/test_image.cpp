// The CPU sRGB encoding of study previews against the sRGB transfer
// function's values (IEC 61966-2-1).
#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "penumbra/image/image.h"

using namespace penumbra;

TEST_CASE("image: encodeSrgb8 is the sRGB transfer function, clipped", "[image]") {
  image::Image img(6, 1);
  const float values[6] = {0.0f, 0.002f, 0.5f, 1.0f, 4.0f, NAN};
  for (int x = 0; x < 6; ++x)
    for (int c = 0; c < 4; ++c) img.pixel(x, 0)[c] = values[x];
  const image::Image8 out = image::encodeSrgb8(img);
  REQUIRE(out.width == 6u);
  // 0.002 is in the linear segment: 12.92 x 0.002 x 255 = 6.6; 0.5 encodes
  // to 0.7354 (187.5); above 1 clips; NaN is black.
  const int expected[6] = {0, 7, 188, 255, 255, 0};
  for (int x = 0; x < 6; ++x) {
    CHECK(int(out.rgba[4 * x]) == expected[x]);
    CHECK(int(out.rgba[4 * x + 2]) == expected[x]);
    CHECK(int(out.rgba[4 * x + 3]) == 255);
  }
}

TEST_CASE("image: centreCrop copies the centre pixels at the image's aspect ratio", "[image]") {
  // Each pixel holds its own coordinates, so the crop's origin is readable.
  image::Image img(16, 8);
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      img.pixel(x, y)[0] = float(x);
      img.pixel(x, y)[1] = float(y);
    }
  const image::Image crop = image::centreCrop(img, 4);
  REQUIRE(crop.width == 4u);
  REQUIRE(crop.height == 2u);  // 16:8 kept
  // The centre 4x2 of 16x8 starts at (6, 3).
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      CHECK(crop.pixel(x, y)[0] == float(6 + x));
      CHECK(crop.pixel(x, y)[1] == float(3 + y));
    }
  const image::Image same = image::centreCrop(img, 16);
  CHECK(same.width == 16u);
  CHECK(same.rgba == img.rgba);
}
