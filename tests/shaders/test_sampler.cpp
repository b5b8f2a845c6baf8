// The path tracer's samplers (shaders/shared/rng.hlsli), run on the test
// device through harness/sampler_harness.comp: the Sobol sampler's nets
// (exact), its uniformity and independence across pixels and across
// dimension pairs (chi-square), and its integration error against the random
// sampler's on an integrand with a known value.
#include <boost/math/special_functions/gamma.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#include "compute_harness.h"
#include "path_tracer_shared.h"
#include "test_device.h"

using namespace penumbra;

namespace {

constexpr uint32_t kRandom = RNG_SAMPLER_RANDOM, kSobol = RNG_SAMPLER_SOBOL;

struct Draw {
  uint32_t sampler = kSobol;
  uint32_t seed = 0;
  uint32_t firstIndex = 0;
  uint32_t samples = 1;  // per pixel
  uint32_t firstPixelX = 0, firstPixelY = 0;
  uint32_t pixels = 1;  // along x from the first
  uint32_t dimensions = 2;
};

// value(pixel, sample, dimension), pixel and sample counted from the draw's first.
class Samples {
 public:
  Samples(const Draw& d, std::vector<float> v) : draw_(d), values_(std::move(v)) {}
  float operator()(uint32_t pixel, uint32_t sample, uint32_t dimension) const {
    return values_[(size_t(pixel) * draw_.samples + sample) * draw_.dimensions + dimension];
  }

 private:
  Draw draw_;
  std::vector<float> values_;
};

Samples draw(test::ComputeHarness& harness, const Draw& d) {
  struct {
    uint32_t sampler, seed, firstIndex, samples, pixelX, pixelY, count, dimensions;
  } push{d.sampler,     d.seed,        d.firstIndex,         d.samples,
         d.firstPixelX, d.firstPixelY, d.pixels * d.samples, d.dimensions};
  const uint64_t bytes = uint64_t(push.count) * d.dimensions * sizeof(float);
  const auto raw = harness.run(&push, sizeof(push), {}, bytes, (push.count + 63) / 64);
  std::vector<float> values(bytes / sizeof(float));
  std::memcpy(values.data(), raw.data(), bytes);
  return Samples(d, std::move(values));
}

// Samples [first, first + 2^m) of pixel 0, dimensions (dx, dy): a (0,m,2)-net
// when every elementary interval of area 2^-m (2^a x 2^(m-a) cells, any a)
// holds exactly one point. Returns the number of intervals that do not.
int netViolations(const Samples& s, uint32_t first, uint32_t m, uint32_t dx, uint32_t dy) {
  int violations = 0;
  const uint32_t n = 1u << m;
  for (uint32_t a = 0; a <= m; ++a) {
    std::vector<int> count(n, 0);
    for (uint32_t i = first; i < first + n; ++i) {
      const uint32_t cx = uint32_t(s(0, i, dx) * float(1u << a));
      const uint32_t cy = uint32_t(s(0, i, dy) * float(1u << (m - a)));
      count[(cy << a) | cx] += 1;
    }
    for (int c : count) violations += c != 1;
  }
  return violations;
}

double chiSquarePValue(const std::vector<double>& observed, double expectedPerCell) {
  double statistic = 0;
  for (double o : observed)
    statistic += (o - expectedPerCell) * (o - expectedPerCell) / expectedPerCell;
  const double dof = double(observed.size() - 1);
  return boost::math::gamma_q(dof / 2.0, statistic / 2.0);
}

}  // namespace

TEST_CASE("Sobol sampler: every aligned run of 2^m samples is a (0,m,2)-net in each dimension pair",
          "[shaders][sampler][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  test::ComputeHarness harness(*device, "sampler_harness.comp");
  Draw d;
  d.seed = 5;
  d.firstPixelX = 3;
  d.firstPixelY = 7;
  d.samples = 1024;
  d.dimensions = 8;
  const Samples sobol = draw(harness, d);
  for (uint32_t pair = 0; pair < 4; ++pair)
    for (uint32_t m : {2u, 4u, 6u, 8u, 10u})
      for (uint32_t run = 0; run < (1024u >> m); run += std::max(1u, (1024u >> m) / 3u)) {
        INFO("dimensions " << 2 * pair << "," << 2 * pair + 1 << ", samples " << (run << m) << ".."
                           << ((run + 1) << m) - 1);
        CHECK(netViolations(sobol, run << m, m, 2 * pair, 2 * pair + 1) == 0);
      }
  // The check has teeth: random numbers are no net.
  d.sampler = kRandom;
  CHECK(netViolations(draw(harness, d), 0, 6, 0, 1) > 0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// Across 4096 pixels at one sample index, each dimension is uniform and a
// pixel's value is independent of its neighbour's: a sampler that forgot to
// decorrelate pixels (one scramble for all) puts every pixel in one cell.
// p > 1e-3 (chi-square 61 on 31 degrees of freedom) lets through about a
// 25 % excess or shortfall in four of the 32 cells (128 expected in each).
TEST_CASE("Sobol sampler: pixels are uniform and independent of their neighbours (chi-square)",
          "[shaders][sampler][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  test::ComputeHarness harness(*device, "sampler_harness.comp");
  Draw d;
  d.seed = 11;
  d.firstIndex = 37;
  d.pixels = 4096;
  d.dimensions = 6;
  const Samples s = draw(harness, d);
  for (uint32_t dim = 0; dim < d.dimensions; ++dim) {
    std::vector<double> single(32, 0.0), neighbours(64, 0.0);
    for (uint32_t p = 0; p < d.pixels; ++p) single[uint32_t(s(p, 0, dim) * 32.0f)] += 1;
    for (uint32_t p = 0; p + 1 < d.pixels; p += 2)
      neighbours[uint32_t(s(p, 0, dim) * 8.0f) * 8 + uint32_t(s(p + 1, 0, dim) * 8.0f)] += 1;
    INFO("dimension " << dim);
    CHECK(chiSquarePValue(single, d.pixels / 32.0) > 1e-3);
    CHECK(chiSquarePValue(neighbours, d.pixels / 2 / 64.0) > 1e-3);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// Within one pixel, a dimension of one pair is independent of every
// dimension of another pair: each pair's sample order is shuffled with its
// own seed. Without the shuffle (or with one seed for all pairs), dimension 0
// and dimension 2 are functions of each other and the 16x16 histogram of
// 4096 samples has empty and doubled cells.
TEST_CASE("Sobol sampler: dimension pairs are independent of each other (chi-square)",
          "[shaders][sampler][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  test::ComputeHarness harness(*device, "sampler_harness.comp");
  Draw d;
  d.seed = 23;
  d.firstPixelX = 100;
  d.firstPixelY = 200;
  d.samples = 4096;
  d.dimensions = 8;
  const Samples s = draw(harness, d);
  for (uint32_t a = 0; a < d.dimensions; ++a)
    for (uint32_t b = a + 1; b < d.dimensions; ++b) {
      if (a / 2 == b / 2) continue;  // one pair: stratified together, not independent
      std::vector<double> cells(256, 0.0);
      for (uint32_t i = 0; i < d.samples; ++i)
        cells[uint32_t(s(0, i, a) * 16.0f) * 16 + uint32_t(s(0, i, b) * 16.0f)] += 1;
      INFO("dimensions " << a << " and " << b);
      CHECK(chiSquarePValue(cells, d.samples / 256.0) > 1e-3);
    }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

// The quarter disc x^2 + y^2 < 1 over the unit square (pi / 4), estimated in
// 512 pixels from 256 samples each. Random sampling's RMS error is
// sqrt(p (1 - p) / 256) = 0.0257 (checked within 15 %, so the harness measures
// what it should); Owen-scrambled Sobol on an edge converges as N^-3/4
// (Owen 1997), about 0.004 here: the check at a third of random's fails a
// sampler that lost its stratification. Both are unbiased: the mean over
// pixels is within 4 standard errors of pi / 4.
TEST_CASE("Sobol sampler: an unbiased estimate with a third of random's error on a disc",
          "[shaders][sampler][gpu][spirv-only]") {
  auto device = test::makeTestDevice();
  test::ComputeHarness harness(*device, "sampler_harness.comp");
  const double exact = std::acos(-1.0) / 4.0;
  const double randomRms = std::sqrt(exact * (1.0 - exact) / 256.0);
  Draw d;
  d.seed = 3;
  d.samples = 256;
  d.pixels = 512;
  d.dimensions = 6;
  auto errors = [&](uint32_t sampler, uint32_t dx, uint32_t dy) {
    d.sampler = sampler;
    const Samples s = draw(harness, d);
    double sum = 0, squares = 0;
    for (uint32_t p = 0; p < d.pixels; ++p) {
      double inside = 0;
      for (uint32_t i = 0; i < d.samples; ++i) {
        const double x = s(p, i, dx), y = s(p, i, dy);
        inside += x * x + y * y < 1.0;
      }
      const double error = inside / d.samples - exact;
      sum += error;
      squares += error * error;
    }
    const double mean = sum / d.pixels, rms = std::sqrt(squares / d.pixels);
    return std::pair{mean, rms};
  };
  const auto [randomMean, randomRmsMeasured] = errors(kRandom, 0, 1);
  INFO("random: mean error " << randomMean << ", RMS " << randomRmsMeasured);
  CHECK(std::abs(randomRmsMeasured / randomRms - 1.0) < 0.15);
  CHECK(std::abs(randomMean) < 4.0 * randomRms / std::sqrt(512.0));
  for (uint32_t pair = 0; pair < 3; ++pair) {
    const auto [mean, rms] = errors(kSobol, 2 * pair, 2 * pair + 1);
    INFO("sobol dimensions " << 2 * pair << "," << 2 * pair + 1 << ": mean error " << mean
                             << ", RMS " << rms);
    CHECK(rms < randomRms / 3.0);
    CHECK(std::abs(mean) < 4.0 * rms / std::sqrt(512.0) + 1e-6);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
