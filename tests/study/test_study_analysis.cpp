// The study's answers on synthetic results whose answers are known: the
// Pareto front, the budget and target-error answers, convergence slopes,
// confidence intervals, and results.csv read back.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "penumbra/study/study_analysis.h"
#include "penumbra/study/study_plan.h"
#include "penumbra/study/study_results.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using Catch::Approx;

namespace {

study::Measurement row(const char* technique, uint32_t spp, double ms, double relMse,
                       uint32_t seed = 1, double bias = 0.0) {
  study::Measurement m;
  m.technique = technique;
  m.spp = spp;
  m.seed = seed;
  m.gpuMs = ms;
  m.relMse = relMse;
  m.bias = bias;
  m.ssim = 0.9;
  return m;
}

}  // namespace

TEST_CASE("study analysis: Pareto front, budget and target answers on a known case", "[study]") {
  // "fast" is cheap and noisy, "good" costly and precise, "bad" dominated by
  // "good" at every point (slower and worse).
  const std::vector<study::Measurement> rows = {
      row("fast", 1, 1.0, 0.50), row("fast", 4, 4.0, 0.125), row("fast", 16, 16.0, 0.031),
      row("good", 1, 2.0, 0.10), row("good", 4, 8.0, 0.025), row("good", 16, 32.0, 0.006),
      row("bad", 1, 3.0, 0.20),  row("bad", 4, 12.0, 0.05)};
  const auto points = study::summarize(rows);
  REQUIRE(points.size() == 8u);
  const auto front = study::paretoFront(points);
  std::vector<std::string> names;
  for (size_t i : front) names.push_back(points[i].technique + "@" + std::to_string(points[i].spp));
  CHECK(names == std::vector<std::string>{"fast@1", "good@1", "good@4", "good@16"});
  const auto budget = study::bestWithinBudget(points, 10.0);
  REQUIRE(budget);
  CHECK(points[*budget].technique == "good");
  CHECK(points[*budget].spp == 4u);
  CHECK_FALSE(study::bestWithinBudget(points, 0.5));
  const auto target = study::fastestForError(points, 0.03);
  REQUIRE(target);
  CHECK(points[*target].technique == "good");
  CHECK(points[*target].spp == 4u);
  CHECK_FALSE(study::fastestForError(points, 1e-4));
}

TEST_CASE("study analysis: convergence slopes of 1/spp and of a biased floor", "[study]") {
  std::vector<study::Measurement> rows;
  for (uint32_t spp : {1u, 4u, 16u, 64u}) {
    rows.push_back(row("unbiased", spp, spp, 0.5 / spp));
    rows.push_back(row("floored", spp, spp, 0.5 / spp + 0.05));
  }
  const auto slopes = study::convergenceSlopes(study::summarize(rows));
  REQUIRE(slopes.size() == 2u);
  CHECK(slopes[0].technique == "unbiased");
  CHECK(slopes[0].slope == Approx(-1.0).margin(1e-12));
  CHECK(slopes[0].intercept == Approx(std::log(0.5)).margin(1e-12));
  CHECK(slopes[0].points == 4u);
  CHECK(slopes[1].slope == Approx(-0.543).margin(0.002));  // flattens (least squares by hand)
}

TEST_CASE("study analysis: means and 95 % intervals over seeds", "[study]") {
  const study::Estimate e = study::estimate({1.0, 2.0, 3.0});
  CHECK(e.mean == Approx(2.0));
  // sd 1, t(2 dof) = 4.303: 4.303 / sqrt(3).
  CHECK(e.halfWidth == Approx(4.303 / std::sqrt(3.0)).epsilon(1e-9));
  CHECK(e.excludesZero() == false);
  CHECK(study::estimate({5.0, 5.1, 4.9, 5.0}).excludesZero());
  CHECK(std::isnan(study::estimate({1.0}).halfWidth));
  CHECK_FALSE(study::estimate({1.0}).excludesZero());
  // Grouped by technique and spp, over their seeds.
  const auto points = study::summarize(
      {row("a", 1, 1.0, 0.1, 1, 0.01), row("a", 1, 3.0, 0.3, 2, 0.03), row("a", 4, 4.0, 0.05)});
  REQUIRE(points.size() == 2u);
  CHECK(points[0].seeds == 2u);
  CHECK(points[0].gpuMs.mean == Approx(2.0));
  CHECK(points[0].relMse.mean == Approx(0.2));
  CHECK(points[0].bias.mean == Approx(0.02));
  CHECK(points[0].efficiency() == Approx(1.0 / (0.2 * 2.0)));
}

TEST_CASE("study results: results.csv reads back, any column order, and bad files name the line",
          "[study]") {
  const std::string csv =
      "spp,technique,seed,gpu_ms,relmse,mape,ssim,bias,extra\n"
      "4,mis,1,2.5,0.125,0.2,0.8,-0.01,x\n"
      "16,mis,1,10,0.03125,0.1,0.9,0.002,y\n";
  const auto rows = study::parseResultsCsv(csv, "r.csv");
  REQUIRE(rows.size() == 2u);
  CHECK(rows[0].technique == "mis");
  CHECK(rows[0].spp == 4u);
  CHECK(rows[0].gpuMs == 2.5);
  CHECK(rows[1].relMse == 0.03125);
  CHECK(rows[1].bias == 0.002);
  auto message = [](const std::string& text) {
    try {
      study::parseResultsCsv(text, "r.csv");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message("technique,spp,seed\n") == "r.csv: line 1: the header has no 'gpu_ms' column");
  CHECK(message(study::resultsCsvHeader() + "\n") == "r.csv: no rows after the header");
  CHECK(message("technique,spp,seed,gpu_ms,relmse,mape,ssim,bias\nmis,4,1,2.5,nan,0,0,0\n") ==
        "r.csv: line 2: relmse 'nan' is not a finite number");
  CHECK(message("technique,spp,seed,gpu_ms,relmse,mape,ssim,bias\nmis,4,1,2.5\n") ==
        "r.csv: line 2: 4 fields, the header has 8");
  CHECK(message("technique,spp,seed,gpu_ms,relmse,mape,ssim,bias\nmis,0,1,2,1,0,0,0\n") ==
        "r.csv: line 2: spp '0' is not a whole number >= 1");
  CHECK(message("technique,spp,seed,gpu_ms,relmse,mape,ssim,bias\nmis,1e300,1,2,1,0,0,0\n") ==
        "r.csv: line 2: spp '1e300' is not a whole number >= 1");
}

// A split study's parts (`penumbra study --points`) are gathered from their
// results.csv rows: every column written is read back bit for bit and
// matched to its point; a row of no point of the study is refused.
TEST_CASE("study results: a part's rows read back exactly and match their points", "[study]") {
  study::StudySpec spec;
  spec.sweep("strategy",
             std::vector{render::SamplingStrategy::Mis, render::SamplingStrategy::Bsdf});
  spec.spp = {1, 4};
  spec.seeds = 2;
  const std::vector<study::StudyPoint> points = study::expandStudy(spec);
  REQUIRE(points.size() == 8u);
  std::vector<study::StudyRow> rows;
  for (size_t i = 3; i < 6; ++i) {
    study::StudyRow r;
    r.point = points[i];
    r.gpuMs = 1.0 / 3.0 + double(i);
    r.denoiseMs = 0.1 * double(i);
    r.rays = (uint64_t(1) << 40) + i;
    r.error = {0.1 / double(i), 1e-17 * double(i), 0.9, -0.01 * double(i)};
    r.belowReferenceNoise = i == 4;
    rows.push_back(r);
  }
  const auto back = study::parseStudyRows(study::resultsCsv(rows), "part.csv", points);
  REQUIRE(back.size() == rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    CHECK(back[k].point.technique == rows[k].point.technique);
    CHECK(back[k].point.spp == rows[k].point.spp);
    CHECK(back[k].point.seed == rows[k].point.seed);
    CHECK(back[k].gpuMs == rows[k].gpuMs);
    CHECK(back[k].denoiseMs == rows[k].denoiseMs);
    CHECK(back[k].rays == rows[k].rays);
    CHECK(back[k].error.relMse == rows[k].error.relMse);
    CHECK(back[k].error.mape == rows[k].error.mape);
    CHECK(back[k].error.ssim == rows[k].error.ssim);
    CHECK(back[k].error.bias == rows[k].error.bias);
    CHECK(back[k].belowReferenceNoise == rows[k].belowReferenceNoise);
  }
  // Another study's point (16 spp is not swept here).
  std::vector<study::StudyRow> foreign{rows[0]};
  foreign[0].point.spp = 16;
  try {
    study::parseStudyRows(study::resultsCsv(foreign), "part.csv", points);
    FAIL("a row of no point was taken");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) ==
          "part.csv: line 2: '" + foreign[0].point.technique.label() + "' at 16 spp, seed " +
              std::to_string(foreign[0].point.seed) + " is not a point of this study");
  }
}
