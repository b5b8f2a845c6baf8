#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>

#include "image/image_compare.h"
#include "util/error.h"

using namespace penumbra;
using Catch::Approx;

TEST_CASE("identical images compare as identical", "[image][compare]") {
  image::Image a{8, 8};
  for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = float(i % 7) * 0.1f;
  auto s = image::compareImages(a, a, 1e-3);
  REQUIRE(s.meanAbsoluteDifference == 0.0);
  REQUIRE(s.maxAbsoluteDifference == 0.0);
  REQUIRE(s.pixelsBeyondTolerance == 0u);
  REQUIRE(std::isinf(s.psnr));
}

TEST_CASE("an injected difference is measured exactly", "[image][compare]") {
  image::Image a{10, 10}, b{10, 10};
  for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = b.rgba[i] = 1.0f;
  // 5 of 100 pixels differ by 0.5 in red only.
  for (uint32_t x = 0; x < 5; ++x) b.pixel(x, 3)[0] = 1.5f;
  auto s = image::compareImages(a, b, 1e-3);
  REQUIRE(s.maxAbsoluteDifference == Approx(0.5));
  REQUIRE(s.meanAbsoluteDifference == Approx(5 * 0.5 / 300.0));
  REQUIRE(s.pixelsBeyondTolerance == 5u);
  REQUIRE(s.fractionBeyondTolerance == Approx(0.05));
  // MSE = 5 * 0.25 / 300; peak = 1.
  REQUIRE(s.psnr == Approx(10.0 * std::log10(1.0 / (1.25 / 300.0))));
  // relMSE with b (1.5 in the changed channels) as the reference:
  // 5 of 300 channels contribute 0.25 / (1.5^2 + 1e-2).
  REQUIRE(s.relativeMse == Approx(5 * 0.25 / (2.25 + 0.01) / 300.0));
  // A tolerance above the relative difference (0.5 / 1.5) accepts them.
  REQUIRE(image::compareImages(a, b, 0.4).pixelsBeyondTolerance == 0u);
}

TEST_CASE("non-finite pixels and size mismatches are reported", "[image][compare]") {
  image::Image a{2, 2}, b{2, 2};
  b.pixel(1, 1)[2] = std::numeric_limits<float>::quiet_NaN();
  REQUIRE(image::compareImages(a, b, 1e-3).nonFiniteB == 1u);
  image::Image c{3, 2};
  REQUIRE_THROWS_AS(image::compareImages(a, c, 1e-3), Error);
}

TEST_CASE("SSIM: 1 for equal images, the closed form for two flat ones, lower with more noise",
          "[image][compare]") {
  image::Image a{24, 16}, b{24, 16};
  for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = b.rgba[i] = 0.2f + 0.01f * float(i % 37);
  CHECK(image::ssim(a, b) == 1.0);
  // Flat images: no variance, so SSIM = (2 x y + C1) / (x^2 + y^2 + C1) of
  // the display values x = 0.25^(1/2.2), y = 0.5^(1/2.2).
  image::Image flatA{8, 8}, flatB{8, 8};
  for (size_t i = 0; i < flatA.rgba.size(); ++i) {
    flatA.rgba[i] = 0.25f;
    flatB.rgba[i] = 0.5f;
  }
  const double x = std::pow(0.25, 1 / 2.2), y = std::pow(0.5, 1 / 2.2), c1 = 1e-4;
  CHECK(std::abs(image::ssim(flatA, flatB) - (2 * x * y + c1) / (x * x + y * y + c1)) < 1e-6);
  CHECK(image::ssim(flatA, flatB) == image::ssim(flatB, flatA));
  // Deterministic noise of growing amplitude lowers it.
  double previous = 1.0;
  for (float amplitude : {0.02f, 0.05f, 0.2f}) {
    image::Image noisy = a;
    uint32_t state = 12345;
    for (size_t i = 0; i < noisy.rgba.size(); ++i) {
      state = state * 1664525u + 1013904223u;
      noisy.rgba[i] += amplitude * (float(state >> 8) / 16777216.0f - 0.5f);
    }
    const double s = image::ssim(noisy, a);
    INFO("noise amplitude " << amplitude << ": SSIM " << s);
    CHECK(s < previous);
    previous = s;
  }
  CHECK_THROWS(image::ssim(a, flatA));
}
