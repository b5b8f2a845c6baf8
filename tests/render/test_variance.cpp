// Variance of the sampling strategies on the Cornell box: at equal samples
// per pixel, NEE + MIS must beat BSDF sampling and uniform directions, which
// find the small ceiling light only by chance. Broken MIS weights show up
// here: weights that do not sum to 1 bias the image away from the reference,
// and weights that favour the worse technique for each light path lose the
// variance advantage, both of which raise its relative MSE.
#include <catch2/catch_test_macros.hpp>
#include <chrono>
#include <cmath>
#include <iostream>

#include "penumbra/image/image_compare.h"
#include "penumbra/scene/scene_loader.h"
#include "render_test_utils.h"

using namespace penumbra;

namespace {
// 32 x 32: the 4096-spp reference takes ~35 s on lavapipe with 2 cores (up
// to 70 s while other builds share them); relative MSE averages over 3072
// channel values, enough to rank strategies that differ 30-fold.
constexpr uint32_t kSize = 32;
constexpr uint32_t kReferenceSpp = 4096;
constexpr uint32_t kSpp = 16;

render::PathTracerSettings withStrategy(render::SamplingStrategy strategy, uint32_t seed) {
  render::PathTracerSettings settings;
  settings.strategy = strategy;
  settings.seed = seed;
  return settings;
}
}  // namespace

TEST_CASE("variance: NEE + MIS has lower relative MSE than BSDF and uniform sampling",
          "[render][gpu][variance]") {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadScene("cornell-box");

  // The reference is NEE without MIS: unbiased whatever the MIS weights are,
  // and, with a light this small, the least noisy technique that does not use
  // them. A reference rendered with MIS would share a bias of broken weights
  // and hide it. Its own error, ~1/256 of a 16-spp NEE image's, adds to every
  // candidate's relative MSE equally.
  const auto start = std::chrono::steady_clock::now();
  const auto reference = test::renderScene(*device, scene, kSize, kSize, kReferenceSpp,
                                           withStrategy(render::SamplingStrategy::Nee, 1000));
  const double referenceSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(image::countNonFinite(reference) == 0);

  auto relMse = [&](render::SamplingStrategy strategy) {
    const auto img =
        test::renderScene(*device, scene, kSize, kSize, kSpp, withStrategy(strategy, 1));
    REQUIRE(image::countNonFinite(img) == 0);
    return image::compareImages(img, reference, 0.05).relativeMse;
  };
  const double mis = relMse(render::SamplingStrategy::Mis);
  const double bsdf = relMse(render::SamplingStrategy::Bsdf);
  const double uniform = relMse(render::SamplingStrategy::Uniform);
  std::cout << "variance test (" << kSize << "x" << kSize << ", " << kSpp << " spp vs a "
            << kReferenceSpp << "-spp NEE reference rendered in " << referenceSeconds
            << " s): relative MSE mis " << mis << ", bsdf " << bsdf << ", uniform " << uniform
            << "\n";
  INFO("relative MSE: mis " << mis << ", bsdf " << bsdf << ", uniform " << uniform);
  // Measured over candidate seeds 1-4 (reference fixed): mis 0.019-0.042,
  // bsdf 1.27-1.34, uniform 1.64-2.10, i.e. MIS 30-66x below BSDF sampling
  // and 39-100x below uniform directions. Requiring 10x keeps a 3x margin
  // for the random streams and still fails for broken weights, measured:
  // the light sample's MIS arguments swapped 0.235 (biased), the BSDF hit's
  // swapped 1.97, both swapped 1.68 (unbiased, but each technique weighted
  // where it is worse), BSDF hits of lights counted fully beside NEE 1.97.
  REQUIRE(10.0 * mis < bsdf);
  REQUIRE(10.0 * mis < uniform);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
