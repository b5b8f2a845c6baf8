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
