// Hard cases far from the origin: a scene translated anywhere up to 1e6 m
// renders as it does at the origin (camera-relative rendering,
// docs/ARCHITECTURE.md "Precision"). Before it, the Cornell box at 1e4 m lost
// its light (0.1 mm under the ceiling, beyond float precision there) and
// rendered at 27 % of its brightness; at 1e6 m the GPU rendered NaN pixels.
#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "render_test_utils.h"
#include "scene/scene_loader.h"

using namespace penumbra;

namespace {

// The scene moved by `offset`: every instance, implicit object, light and
// camera, in double as a loader composes a root transform.
scene::Scene translated(scene::Scene s, const glm::dvec3& offset) {
  const glm::dmat4 t = glm::translate(glm::dmat4(1.0), offset);
  for (auto& instance : s.instances) instance.transform = t * instance.transform;
  for (auto& object : s.implicits) object.transform = t * object.transform;
  for (auto& light : s.pointLights) light.position += offset;
  s.camera.position += offset;
  for (auto& named : s.cameras) named.camera.position += offset;
  return s;
}

double luminance(const float* p) {
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

double meanLuminance(const image::Image& img) {
  double sum = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) sum += luminance(img.pixel(x, y));
  return sum / (double(img.width) * img.height);
}

// Median over 8x8 blocks of |mean(a) - mean(b)| / mean(b): what a displaced,
// missing or wrongly shaded object changes, insensitive to single pixels.
double blockMedianDifference(const image::Image& a, const image::Image& b) {
  std::vector<double> differences;
  for (uint32_t by = 0; by + 8 <= a.height; by += 8)
    for (uint32_t bx = 0; bx + 8 <= a.width; bx += 8) {
      double sa = 0, sb = 0;
      for (uint32_t y = by; y < by + 8; ++y)
        for (uint32_t x = bx; x < bx + 8; ++x) {
          sa += luminance(a.pixel(x, y));
          sb += luminance(b.pixel(x, y));
        }
      differences.push_back(std::abs(sa - sb) / std::max(sb, 1e-6));
    }
  std::nth_element(differences.begin(), differences.begin() + differences.size() / 2,
                   differences.end());
  return differences[differences.size() / 2];
}

// Pixels at least half as bright as the brightest: the light seen directly.
std::vector<uint32_t> brightPixels(const image::Image& img, double peak) {
  std::vector<uint32_t> pixels;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x)
      if (luminance(img.pixel(x, y)) >= 0.5 * peak) pixels.push_back(y * img.width + x);
  return pixels;
}

double peakLuminance(const image::Image& img) {
  double peak = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) peak = std::max(peak, luminance(img.pixel(x, y)));
  return peak;
}

// Renders `scene` at the origin and moved by each offset, with one seed;
// another seed at the origin measures the noise of the sample count. Each
// moved image must match the one at the origin: mean within 1 %, the 8x8
// block median difference no larger than between two independent renders at
// the origin (so it lets through only what sample noise could hide), no
// NaN/Inf, and the directly seen light in the same pixels.
void checkOffsets(const scene::Scene& scene, uint32_t size, uint32_t spp,
                  const std::vector<glm::dvec3>& offsets) {
  auto device = test::makeTestDevice();
  render::PathTracerSettings settings;
  settings.seed = 1;
  const image::Image atOrigin = test::renderScene(*device, scene, size, size, spp, settings);
  settings.seed = 2;
  const image::Image independent = test::renderScene(*device, scene, size, size, spp, settings);
  const double noise = blockMedianDifference(independent, atOrigin);
  const double mean = meanLuminance(atOrigin);
  const double peak = peakLuminance(atOrigin);
  const std::vector<uint32_t> light = brightPixels(atOrigin, peak);
  INFO("at the origin: mean " << mean << ", block median difference of another seed " << noise
                              << ", " << light.size() << " pixels see the light");
  REQUIRE(mean > 0.0);
  REQUIRE(!light.empty());
  settings.seed = 1;
  for (const glm::dvec3& offset : offsets) {
    const image::Image moved =
        test::renderScene(*device, translated(scene, offset), size, size, spp, settings);
    INFO("offset (" << offset.x << ", " << offset.y << ", " << offset.z << ")");
    CHECK(image::countNonFinite(moved) == 0);
    const double movedMean = meanLuminance(moved);
    INFO("mean " << movedMean << ", block median difference "
                 << blockMedianDifference(moved, atOrigin));
    CHECK(std::abs(movedMean / mean - 1.0) <= 0.01);
    CHECK(blockMedianDifference(moved, atOrigin) <= noise);
    CHECK(brightPixels(moved, peak) == light);
  }
}

const std::vector<glm::dvec3> kOffsets = {{1e3, 1e3, 1e3}, {1e4, 1e4, 1e4},  {1e5, 1e5, 1e5},
                                          {1e6, 1e6, 1e6}, {-1e6, 2e5, 1e6}, {0.0, -1e6, 0.0}};

}  // namespace

TEST_CASE("large worlds: the Cornell box renders the same image from 0 to 1e6 m from the origin",
          "[render][gpu][precision]") {
  checkOffsets(scene::loadScene("cornell-box"), 48, 64, kOffsets);
}

TEST_CASE(
    "large worlds: implicit surfaces and point lights render the same image 1e4 and 1e6 m away",
    "[render][gpu][precision]") {
  checkOffsets(scene::loadScene("implicit-surfaces"), 32, 16, {{1e4, 1e4, 1e4}, {-1e6, 2e5, 1e6}});
}
