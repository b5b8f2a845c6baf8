#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>

#include "penumbra/image/image_compare.h"
#include "penumbra/util/error.h"

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
  // MSE = 5 * 0.25 / 300; peak = 1.5, b's.
  REQUIRE(s.psnr == Approx(10.0 * std::log10(1.5 * 1.5 / (1.25 / 300.0))));
  // relMSE with b (1.5 in the changed channels) as the reference:
  // 5 of 300 channels contribute 0.25 / (1.5^2 + 1e-2).
  REQUIRE(s.relativeMse == Approx(5 * 0.25 / (2.25 + 0.01) / 300.0));
  // A tolerance above the relative difference (0.5 / 1.5) accepts them.
  REQUIRE(image::compareImages(a, b, 0.4).pixelsBeyondTolerance == 0u);
}

TEST_CASE("the mean difference and its standard error, computed by hand", "[image][compare]") {
  // Four pixels; red differs by +0.1, +0.3, -0.1, +0.1 (b - a): mean 0.1,
  // sample standard deviation sqrt((0 + 0.04 + 0.04 + 0) / 3), standard
  // error that / sqrt(4). Green and blue are equal.
  image::Image a{2, 2}, b{2, 2};
  const float redA[4] = {1.0f, 2.0f, 3.0f, 4.0f}, redB[4] = {1.1f, 2.3f, 2.9f, 4.1f};
  for (uint32_t i = 0; i < 4; ++i) {
    a.pixel(i % 2, i / 2)[0] = redA[i];
    b.pixel(i % 2, i / 2)[0] = redB[i];
  }
  const auto s = image::compareImages(a, b, 1e-3);
  CHECK(s.meanDifference[0] == Approx(0.1).epsilon(1e-6));
  CHECK(s.meanDifferenceStandardError[0] == Approx(std::sqrt(0.08 / 3.0) / 2.0).epsilon(1e-5));
  CHECK(s.meanA[0] == Approx(2.5));
  CHECK(s.meanDifference[1] == 0.0);
  CHECK(s.meanDifferenceStandardError[2] == 0.0);
  // 0.1 is 1.22 standard errors: systematic at 1 sigma, not at 2.
  CHECK(image::meanDifferenceIsSystematic(s, 1.0, 0.0));
  CHECK_FALSE(image::meanDifferenceIsSystematic(s, 2.0, 0.0));
  // The floor: 0.1 is 4 % of red's mean 2.5.
  CHECK_FALSE(image::meanDifferenceIsSystematic(s, 0.0, 0.05));
  CHECK(image::meanDifferenceIsSystematic(s, 0.0, 0.03));
}

TEST_CASE("parted paths pass the bias test, a 2 % loss of light does not", "[image][compare]") {
  // 64x64 pixels of "renders": b equals a except in 10 % of the pixels,
  // where it is an independent draw of the same distribution (a path that
  // parted by rounding). Then b scaled by 0.98 everywhere.
  image::Image a{64, 64}, b{64, 64};
  uint32_t state = 12345u;
  auto uniform = [&] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (size_t i = 0; i < size_t(64) * 64; ++i)
    for (int c = 0; c < 3; ++c) {
      a.rgba[i * 4 + c] = uniform();
      b.rgba[i * 4 + c] = a.rgba[i * 4 + c];
    }
  for (size_t i = 0; i < size_t(64) * 64; ++i)
    if (uniform() < 0.1f)
      for (int c = 0; c < 3; ++c) b.rgba[i * 4 + c] = uniform();
  CHECK_FALSE(image::meanDifferenceIsSystematic(image::compareImages(a, b, 1e-3), 4.0, 1e-5));
  for (size_t i = 0; i < b.rgba.size(); ++i) b.rgba[i] *= 0.98f;
  CHECK(image::meanDifferenceIsSystematic(image::compareImages(a, b, 1e-3), 4.0, 1e-5));
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

TEST_CASE("PSNR takes its peak from the reference: a firefly lowers the score",
          "[image][compare]") {
  image::Image reference{10, 10}, clean{10, 10}, firefly{10, 10};
  for (size_t i = 0; i < reference.rgba.size(); ++i) {
    reference.rgba[i] = 1.0f;
    clean.rgba[i] = 1.1f;  // every channel 0.1 off
    firefly.rgba[i] = 1.0f;
  }
  firefly.pixel(4, 4)[0] = 100.0f;  // one channel 99 off
  const auto c = image::compareImages(clean, reference, 1e-3);
  const auto f = image::compareImages(firefly, reference, 1e-3);
  // peak 1 (the reference's): MSE 0.01 -> 20 dB; MSE 99^2 / 300 -> -15.2 dB.
  CHECK(c.psnr == Approx(20.0).epsilon(1e-5));
  CHECK(f.psnr == Approx(10.0 * std::log10(1.0 / (99.0 * 99.0 / 300.0))));
  CHECK(f.psnr < c.psnr);
}
