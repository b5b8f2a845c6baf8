// The mapping from the viewer's settings (menus, scripts) to what the renderer
// gets, and the record a screenshot leaves (apps/viewer/viewer_settings.h).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "penumbra/util/error.h"
#include "render_scale.h"
#include "script.h"
#include "viewer_settings.h"

using namespace penumbra;
using viewer::SettingEffect;

TEST_CASE("viewer settings: each script setting reaches the renderer's parameter", "[viewer]") {
  viewer::ViewerSettings s;
  CHECK(viewer::applySetting(s, "spp-per-frame", "4") == SettingEffect::ResetAccumulation);
  CHECK(s.render.sppPerFrame == 4u);
  CHECK(viewer::applySetting(s, "max-depth", "3") == SettingEffect::ResetAccumulation);
  CHECK(s.render.tracer.maxDepth == 3u);
  CHECK(viewer::applySetting(s, "integrator", "whitted") == SettingEffect::ResetAccumulation);
  CHECK(s.render.tracer.integrator == render::Integrator::Whitted);
  CHECK(viewer::applySetting(s, "strategy", "nee") == SettingEffect::ResetAccumulation);
  CHECK(s.render.tracer.strategy == render::SamplingStrategy::Nee);
  CHECK(viewer::applySetting(s, "mis-heuristic", "balance") == SettingEffect::ResetAccumulation);
  CHECK(s.render.tracer.misHeuristic == render::MisHeuristic::Balance);
  CHECK(viewer::applySetting(s, "russian-roulette", "off") == SettingEffect::ResetAccumulation);
  CHECK_FALSE(s.render.tracer.russianRoulette);
  CHECK(viewer::applySetting(s, "clamp", "10") == SettingEffect::ResetAccumulation);
  CHECK(s.render.tracer.radianceClamp == 10.0f);
  CHECK(viewer::applySetting(s, "seed", "7") == SettingEffect::ResetAccumulation);
  CHECK(s.render.tracer.seed == 7u);
  // Display-only settings leave the accumulation alone.
  CHECK(viewer::applySetting(s, "exposure", "2.5") == SettingEffect::None);
  CHECK(s.render.toneMapping.exposure == 2.5f);
  CHECK(viewer::applySetting(s, "tonemap", "aces") == SettingEffect::None);
  CHECK(s.render.toneMapping.toneOperator == render::ToneMapOperator::AcesFitted);
  CHECK(viewer::applySetting(s, "all-effects", "on") == SettingEffect::RebuildRenderer);
  CHECK(s.render.allEffects);
  // A fixed render scale turns the automatic one off.
  CHECK(viewer::applySetting(s, "render-scale", "0.5") == SettingEffect::Resize);
  CHECK(s.renderScale == 0.5f);
  CHECK_FALSE(s.autoRenderScale);
  CHECK(viewer::applySetting(s, "max-samples", "64") == SettingEffect::None);
  CHECK(s.maxSamples == 64u);
  CHECK(viewer::applySetting(s, "ui", "off") == SettingEffect::None);
  CHECK_FALSE(s.showUi);
  // Setting a value it already has changes nothing.
  CHECK(viewer::applySetting(s, "seed", "7") == SettingEffect::None);
}

TEST_CASE("viewer settings: bad names and values are errors that name them", "[viewer]") {
  viewer::ViewerSettings s;
  REQUIRE_THROWS_WITH(viewer::applySetting(s, "spp-per-frame", "17"),
                      "setting 'spp-per-frame': '17' is not an integer in 1..16");
  REQUIRE_THROWS_WITH(viewer::applySetting(s, "strategy", "best"),
                      "setting 'strategy': 'best' is not one of uniform, cosine, bsdf, nee, mis");
  REQUIRE_THROWS_WITH(viewer::applySetting(s, "colour", "red"), "unknown setting 'colour'");
  CHECK(s.render.sppPerFrame == 1u);  // untouched by the failures
}

TEST_CASE("viewer settings: the screenshot record reproduces the frames rendered", "[viewer]") {
  viewer::ViewerSettings s;
  s.render.sppPerFrame = 4;
  s.render.tracer.seed = 9;
  s.render.tracer.maxDepth = 5;
  s.render.toneMapping.exposure = 2.0f;
  scene::Camera camera;
  camera.position = {0.1f, 0.2f, 0.3f};
  const auto job =
      viewer::makeRenderJob(s, "material-test", "metallic", "roughness=0.3", camera, {160, 90}, 32);
  CHECK(job.scene == "material-test");
  CHECK(job.vary == "metallic");
  CHECK(job.set == "roughness=0.3");
  REQUIRE(job.camera.has_value());
  CHECK(job.camera->position == camera.position);
  CHECK(job.width == 160u);
  CHECK(job.height == 90u);
  CHECK(job.spp == 32u);         // what has accumulated
  CHECK(job.settings.sppPerFrame ==
        4u);  // in frames of the same size (stratification is per frame)
  CHECK(job.settings.tracer.seed == 9u);
  CHECK(job.settings.tracer.maxDepth == 5u);
  CHECK(job.settings.toneMapping.exposure == 2.0f);
}

TEST_CASE("viewer settings: render size follows the scale, never below one pixel", "[viewer]") {
  CHECK(viewer::renderSize(1280, 720, 0.5f).width == 640u);
  CHECK(viewer::renderSize(1280, 720, 0.5f).height == 360u);
  CHECK(viewer::renderSize(3, 1, 0.125f).width == 1u);
  CHECK(viewer::renderSize(3, 1, 0.125f).height == 1u);
}

TEST_CASE("render scale: a slow device gets fewer pixels, a fast one goes back up", "[viewer]") {
  viewer::RenderScaleController scale(1.0f, true, 1.0 / 30.0);
  // Frames four times too slow: time ~ pixels ~ scale^2, so the scale halves.
  bool changed = false;
  for (int i = 0; i < viewer::RenderScaleController::kSettleFrames; ++i)
    changed = scale.update(4.0 / 30.0);
  REQUIRE(changed);
  CHECK(scale.scale() == 0.5f);
  // On target: stays put (each change restarts the accumulation).
  for (int i = 0; i < 50; ++i) REQUIRE_FALSE(scale.update(1.0 / 30.0));
  // Much faster than needed: back to full resolution, not beyond.
  for (int i = 0; i < 50; ++i) scale.update(0.1 / 30.0);
  CHECK(scale.scale() == 1.0f);
  // Manual mode never moves it.
  viewer::RenderScaleController manual(0.25f, false);
  for (int i = 0; i < 50; ++i) REQUIRE_FALSE(manual.update(1.0));
  CHECK(manual.scale() == 0.25f);
}

TEST_CASE("viewer script: commands parse with their arguments, errors name the line", "[viewer]") {
  const auto script = viewer::parseScript(
      "# a comment\n"
      "set spp-per-frame 4\n"
      "move 0 0 -0.5   # back half a metre\n"
      "wait-samples 8\n"
      "screenshot out.exr\n"
      "quit\n",
      "test.script");
  REQUIRE(script.size() == 5);
  using Kind = viewer::ScriptCommand::Kind;
  CHECK(script[0].kind == Kind::Set);
  CHECK(script[0].args == std::vector<std::string>{"spp-per-frame", "4"});
  CHECK(script[1].kind == Kind::Move);
  CHECK(script[1].numbers == std::vector<float>{0.0f, 0.0f, -0.5f});
  CHECK(script[1].line == 3);
  CHECK(script[2].kind == Kind::WaitSamples);
  CHECK(script[2].numbers[0] == 8.0f);
  CHECK(script[3].args[0] == "out.exr");
  CHECK(script[4].kind == Kind::Quit);
  REQUIRE_THROWS_WITH(viewer::parseScript("move 1 2\n", "s"),
                      "s:1: 'move' takes 3 argument(s), got 2");
  REQUIRE_THROWS_WITH(viewer::parseScript("\nfly 1\n", "s"), "s:2: unknown command 'fly'");
  REQUIRE_THROWS_WITH(viewer::parseScript("wait-frames 1.5\n", "s"),
                      "s:1: 'wait-frames' needs a whole number >= 0");
}

TEST_CASE("viewer script: material edits parse, errors name the line", "[viewer]") {
  const auto script = viewer::parseScript(
      "material white roughness 0.2\n"
      "material red baseColor 0.9 0.5 0.25\n",
      "m.script");
  REQUIRE(script.size() == 2);
  using Kind = viewer::ScriptCommand::Kind;
  CHECK(script[0].kind == Kind::Material);
  CHECK(script[0].args[0] == "white");
  CHECK(script[0].args[1] == "roughness");
  CHECK(script[0].numbers == std::vector<float>{0.2f});
  CHECK(script[1].numbers == std::vector<float>{0.9f, 0.5f, 0.25f});
  CHECK(script[1].line == 2);
  REQUIRE_THROWS_WITH(viewer::parseScript("material white roughness\n", "s"),
                      "s:1: 'material' takes 3 or more argument(s), got 2");
  REQUIRE_THROWS_WITH(viewer::parseScript("\nmaterial white roughness x\n", "s"),
                      "s:2: 'x' is not a number");
  REQUIRE_THROWS_WITH(viewer::parseScript("material white baseColor 1 0\n", "s"),
                      "s:1: material parameter 'baseColor' takes 3 number(s), got 2");
  REQUIRE_THROWS_WITH(viewer::parseScript("material white shininess 3\n", "s"),
                      Catch::Matchers::StartsWith("s:1: unknown material parameter 'shininess'"));
}
