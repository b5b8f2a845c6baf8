// The sweep a study renders: the product of its lists, Whitted's options
// collapsed, bad lists refused.
#include <catch2/catch_test_macros.hpp>

#include "penumbra/study/study_plan.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using render::DenoiseMode;
using render::Integrator;
using render::SamplingStrategy;

TEST_CASE("study plan: the points are the product of the lists, seeds innermost", "[study]") {
  study::StudySpec spec;
  spec.strategies = {SamplingStrategy::Bsdf, SamplingStrategy::Nee, SamplingStrategy::Mis};
  spec.maxDepths = {4, 8};
  spec.spp = {1, 4, 16};
  spec.seeds = 2;
  spec.firstSeed = 5;
  const auto points = study::expandStudy(spec);
  REQUIRE(points.size() == 3u * 2u * 3u * 2u);
  CHECK(points[0].technique.label() == "bsdf depth=4");
  CHECK(points[0].spp == 1u);
  CHECK(points[0].seed == 5u);
  CHECK(points[1].seed == 6u);
  CHECK(points[2].spp == 4u);
  CHECK(points.back().technique.label() == "mis");
  CHECK(points.back().spp == 16u);
}

TEST_CASE("study plan: labels name what differs from the defaults", "[study]") {
  study::Technique t;
  CHECK(t.label() == "mis");
  t.strategy = SamplingStrategy::Bsdf;
  t.clamp = 10.0f;
  t.russianRoulette = false;
  t.denoise = DenoiseMode::Svgf;
  t.allEffects = true;
  CHECK(t.label() == "bsdf rr=off clamp=10 denoise=svgf full");
  CHECK(t.settings(7).writeGuides);
  CHECK(t.settings(7).seed == 7u);
  CHECK(t.settings(7).radianceClamp == 10.0f);
}

TEST_CASE("study plan: Whitted takes no sampling options and no denoiser", "[study]") {
  study::StudySpec spec;
  spec.integrators = {Integrator::Path, Integrator::Whitted};
  spec.strategies = {SamplingStrategy::Bsdf, SamplingStrategy::Mis};
  spec.denoise = {DenoiseMode::Off, DenoiseMode::Atrous};
  const auto techniques = study::studyTechniques(spec);
  // 2 strategies x 2 denoisers for the path tracer, one Whitted.
  REQUIRE(techniques.size() == 5u);
  CHECK(techniques.back().label() == "whitted");
}

TEST_CASE("study plan: empty lists, spp 0 and no seeds are refused", "[study]") {
  study::StudySpec spec;
  spec.strategies.clear();
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
  spec = {};
  spec.spp = {1, 0};
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
  spec = {};
  spec.seeds = 0;
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
  spec = {};
  spec.integrators = {Integrator::Whitted};
  spec.denoise = {DenoiseMode::Svgf};
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
}
