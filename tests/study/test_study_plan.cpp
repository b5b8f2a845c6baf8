// The sweep a study renders: the product of its lists, Whitted's options
// collapsed, bad lists refused.
#include <catch2/catch_test_macros.hpp>
#include <set>
#include <string_view>
#include <vector>

#include "penumbra/study/study_plan.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using render::DenoiseMode;
using render::Integrator;
using render::SamplingStrategy;

TEST_CASE("study plan: the points are the product of the lists, seeds innermost", "[study]") {
  study::StudySpec spec;
  spec.sweep("strategy",
             std::vector{SamplingStrategy::Bsdf, SamplingStrategy::Nee, SamplingStrategy::Mis});
  spec.sweep("maxDepth", std::vector{4, 8});
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
  t.settings.tracer.strategy = SamplingStrategy::Bsdf;
  t.settings.tracer.radianceClamp = 10.0f;
  t.settings.tracer.russianRoulette = false;
  t.settings.denoiser.mode = DenoiseMode::Svgf;
  t.settings.allEffects = true;
  CHECK(t.label() == "bsdf rr=off clamp=10 denoise=svgf full");
  CHECK(t.frameSettings(7).writeGuides);
  CHECK(t.frameSettings(7).seed == 7u);
  CHECK(t.frameSettings(7).radianceClamp == 10.0f);
  t = {};
  t.settings.tracer.misHeuristic = render::MisHeuristic::Balance;
  t.settings.tracer.sampler = render::Sampler::Random;  // Sobol is the default
  t.settings.tracer.maxDepth = 4;
  CHECK(t.label() == "mis balance random depth=4");
}

TEST_CASE("study plan: Whitted takes no sampling options and no denoiser", "[study]") {
  study::StudySpec spec;
  spec.sweep("integrator", std::vector{Integrator::Path, Integrator::Whitted});
  spec.sweep("strategy", std::vector{SamplingStrategy::Bsdf, SamplingStrategy::Mis});
  spec.sweep("denoise", std::vector{DenoiseMode::Off, DenoiseMode::Atrous});
  const auto techniques = study::studyTechniques(spec);
  // 2 strategies x 2 denoisers for the path tracer, one Whitted.
  REQUIRE(techniques.size() == 5u);
  CHECK(techniques.back().label() == "whitted");
}

TEST_CASE("study plan: empty lists, spp 0 and no seeds are refused", "[study]") {
  study::StudySpec spec;
  spec.sweep("strategy", std::vector<SamplingStrategy>{});
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
  CHECK_THROWS_AS(spec.sweep("exposure", std::vector{1.0}), Error);   // no study axis
  CHECK_THROWS_AS(spec.sweep("maxDepth", std::vector{-1.0}), Error);  // out of range
  spec = {};
  spec.spp = {1, 0};
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
  spec = {};
  spec.seeds = 0;
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
  spec = {};
  spec.sweep("integrator", std::vector{Integrator::Whitted});
  spec.sweep("denoise", std::vector{DenoiseMode::Svgf});
  CHECK_THROWS_AS(study::expandStudy(spec), Error);
}

TEST_CASE("study plan: every axis is a settings-table entry with its own column", "[study]") {
  std::set<std::string_view> columns, options;
  for (const study::StudyAxis& axis : study::studyAxes()) {
    REQUIRE(axis.setting != nullptr);
    CHECK(render::findSetting(axis.setting->key) == axis.setting);
    CHECK(columns.insert(axis.csvColumn).second);
    CHECK(options.insert(axis.option).second);
    // Each value an axis spells reads back as itself.
    const double v = axis.setting->get(render::RenderSettings{});
    CHECK(axis.parse(axis.spell(v)) == v);
  }
  CHECK(study::findStudyAxis("pipeline") == study::findStudyAxis("allEffects"));
  CHECK(study::findStudyAxis("max-depth")->csvColumn == "max_depth");
  CHECK(study::findStudyAxis("exposure") == nullptr);  // a display setting: no axis
}
