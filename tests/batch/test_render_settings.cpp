// The settings table (engine/penumbra/batch/render_settings.h): every field of the
// settings structs is described, every described setting reaches the
// split-render hash, the render record and its own field, and names parse
// back to the values they format.
#include <fmt/format.h>

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <set>
#include <string>

#include "penumbra/batch/partial_render.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/batch/render_settings.h"
#include "penumbra/util/field_count.h"

using namespace penumbra;

namespace {

// A value other than the setting's default that it accepts.
double otherValue(const render::Setting& s) {
  const double v = s.get(render::RenderSettings{});
  switch (s.type) {
    case render::SettingType::Flag:
      return v != 0.0 ? 0.0 : 1.0;
    case render::SettingType::Count:
      return v + 1 <= s.max ? v + 1 : v - 1;
    case render::SettingType::Number:
      return v + 0.5;
    case render::SettingType::Choice:
      return double((size_t(v) + 1) % s.choices.size());
  }
  return v;
}

}  // namespace

TEST_CASE("settings table: every field of the path tracer and tone settings has one entry",
          "[render][settings]") {
  // Flip each setting and see which struct it moved; a field added to a
  // struct without a table entry makes its count exceed the entries'.
  size_t tracer = 0, toneMapping = 0, job = 0, denoiser = 0;
  for (const auto& s : render::renderSettingsTable()) {
    render::RenderSettings flipped;
    s.set(flipped, otherValue(s));
    const render::RenderSettings defaults;
    const int moved = int(!(flipped.tracer == defaults.tracer)) +
                      int(!(flipped.toneMapping == defaults.toneMapping)) +
                      int(flipped.sppPerFrame != defaults.sppPerFrame) +
                      int(flipped.allEffects != defaults.allEffects) +
                      int(flipped.denoiser.mode != defaults.denoiser.mode) +
                      int(flipped.denoiser.fireflyClamp != defaults.denoiser.fireflyClamp);
    INFO(s.key);
    REQUIRE(moved == 1);
    tracer += !(flipped.tracer == defaults.tracer);
    toneMapping += !(flipped.toneMapping == defaults.toneMapping);
    job += flipped.sppPerFrame != defaults.sppPerFrame || flipped.allEffects != defaults.allEffects;
    denoiser += flipped.denoiser.mode != defaults.denoiser.mode ||
                flipped.denoiser.fireflyClamp != defaults.denoiser.fireflyClamp;
  }
  CHECK(tracer == fieldCount<render::PathTracerSettings>());
  CHECK(toneMapping == fieldCount<render::ToneMapping>());
  // RenderSettings: tracer, sppPerFrame, allEffects, toneMapping, denoiser.
  STATIC_CHECK(fieldCount<render::RenderSettings>() == 5);
  CHECK(job == 2);
  CHECK(denoiser == 2);  // mode and firefly clamp; the rest are the filter's tuning
}

TEST_CASE("settings table: names and keys are unique, values format and parse back",
          "[render][settings]") {
  std::set<std::string> names, keys;
  for (const auto& s : render::renderSettingsTable()) {
    INFO(s.key);
    CHECK(names.insert(std::string(s.name)).second);
    CHECK(keys.insert(std::string(s.key)).second);
    CHECK(render::findSetting(s.name) == &s);
    CHECK(render::findSetting(s.key) == &s);
    for (double v : {s.get(render::RenderSettings{}), otherValue(s)}) {
      REQUIRE(s.accepts(v));
      CHECK(s.parse(s.format(v)) == v);
    }
  }
  const auto& depth = *render::findSetting("max-depth");
  CHECK_FALSE(depth.parse("1025"));
  CHECK_FALSE(depth.parse("2.5"));
  CHECK_FALSE(depth.parse("-1"));
  CHECK(depth.expected() == "an integer in 0..1024");
  CHECK_FALSE(render::findSetting("clamp")->parse("-0.5"));
  CHECK_FALSE(render::findSetting("clamp")->parse("nan"));
  CHECK(render::findSetting("strategy")->expected() == "one of uniform, cosine, bsdf, nee, mis");
  // The CLI spells the side that is not the default.
  CHECK(render::findSetting("russianRoulette")->commandLineFlag() == "--no-russian-roulette");
  CHECK(render::findSetting("allEffects")->commandLineFlag() == "--all-effects");
  REQUIRE_THROWS_WITH(depth.parseOrThrow("deep", "--max-depth"),
                      "--max-depth 'deep': not an integer in 0..1024");
}

TEST_CASE("settings table: the enums' names are the table's choices", "[render][settings]") {
  CHECK(std::string(render::integratorName(render::Integrator::Whitted)) == "whitted");
  CHECK(std::string(render::strategyName(render::SamplingStrategy::Nee)) == "nee");
  CHECK(std::string(render::misHeuristicName(render::MisHeuristic::Balance)) == "balance");
  CHECK(std::string(render::samplerName(render::Sampler::Sobol)) == "sobol");
  CHECK(std::string(render::toneMapOperatorName(render::ToneMapOperator::AcesFitted)) == "aces");
  CHECK(std::string(render::denoiseModeName(render::DenoiseMode::Svgf)) == "svgf");
  CHECK(render::parseDenoiseMode("atrous") == render::DenoiseMode::Atrous);
  CHECK_FALSE(render::parseToneMapOperator("filmic"));
}

TEST_CASE("settings table: each identity setting changes the split-render hash, no other does",
          "[render][settings]") {
  const scene::Camera camera;
  const std::string base = render::splitSettingsHash(render::RenderSettings{}, camera, 64, 48);
  std::set<std::string> seen{base};
  for (const auto& s : render::renderSettingsTable()) {
    INFO(s.key);
    render::RenderSettings flipped;
    s.set(flipped, otherValue(s));
    const std::string hash = render::splitSettingsHash(flipped, camera, 64, 48);
    if (s.identity) {
      CHECK(seen.insert(hash).second);  // differs from the defaults' and every other flip's
    } else {
      CHECK(hash == base);
    }
  }
  CHECK(render::splitSettingsHash(render::RenderSettings{}, camera, 64, 49) != base);
}

TEST_CASE("settings table: each recorded setting round trips through a render record",
          "[render][settings]") {
  for (const auto& s : render::renderSettingsTable()) {
    INFO(s.key);
    render::RenderJob job;
    s.set(job.settings, otherValue(s));
    const std::string text = render::renderJobToJson(job);
    const render::RenderJob back = render::renderJobFromJson(text, "record.json");
    const std::string quotedKey = fmt::format("\"{}\"", s.key);
    if (s.recorded) {
      CHECK(s.get(back.settings) == otherValue(s));
      CHECK(text.find(quotedKey) != std::string::npos);
    } else {
      CHECK(s.get(back.settings) == s.get(render::RenderSettings{}));
      CHECK(text.find(quotedKey) == std::string::npos);
    }
  }
}
