// The render settings record (engine/render/render_job.h) that viewer
// screenshots leave and `penumbra render --settings` reads.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "render/render_job.h"
#include "util/error.h"

using namespace penumbra;

TEST_CASE("render job: a written record reads back with every field", "[render]") {
  const std::string text = R"({
    "format": "penumbra-render", "version": 1,
    "scene": "material-test", "vary": "metallic", "set": "roughness=0.25",
    "camera": { "position": [0.5, 1.25, -3], "forward": [0, 0, 1], "up": [0, 1, 0],
                "verticalFovDegrees": 30 },
    "width": 320, "height": 200, "spp": 48, "sppPerFrame": 4,
    "integrator": "whitted", "strategy": "nee", "misHeuristic": "balance",
    "maxDepth": 5, "russianRoulette": false, "rouletteStartDepth": 2,
    "radianceClamp": 8, "seed": 11, "exposure": 1.5, "toneMapping": "reinhard",
    "allEffects": true })";
  const auto job = render::renderJobFromJson(text, "shot.json");
  CHECK(job.scene == "material-test");
  CHECK(job.vary == "metallic");
  CHECK(job.set == "roughness=0.25");
  REQUIRE(job.camera.has_value());
  CHECK(job.camera->position == glm::vec3(0.5f, 1.25f, -3.0f));
  CHECK(job.camera->verticalFovDegrees == 30.0f);
  CHECK(job.width == 320u);
  CHECK(job.height == 200u);
  CHECK(job.spp == 48u);
  CHECK(job.sppPerFrame == 4u);
  CHECK(job.settings.integrator == render::Integrator::Whitted);
  CHECK(job.settings.strategy == render::SamplingStrategy::Nee);
  CHECK(job.settings.misHeuristic == render::MisHeuristic::Balance);
  CHECK(job.settings.maxDepth == 5u);
  CHECK_FALSE(job.settings.russianRoulette);
  CHECK(job.settings.rouletteStartDepth == 2u);
  CHECK(job.settings.radianceClamp == 8.0f);
  CHECK(job.settings.seed == 11u);
  CHECK(job.toneMapping.exposure == 1.5f);
  CHECK(job.toneMapping.toneOperator == render::ToneMapOperator::Reinhard);
  CHECK(job.allEffects);
}

TEST_CASE("render job: floats survive the round trip bit for bit", "[render]") {
  render::RenderJob job;
  scene::Camera camera;
  // Values with no short decimal form: a lossy writer would change them.
  camera.position = {0.1f, 1.0f / 3.0f, -2.7182817f};
  camera.forward = {0.5773503f, 0.5773503f, 0.5773503f};
  camera.verticalFovDegrees = 39.3077f;
  job.camera = camera;
  job.settings.radianceClamp = 0.3f;
  const auto back = render::renderJobFromJson(render::renderJobToJson(job), "round trip");
  REQUIRE(back.camera.has_value());
  CHECK(back.camera->position == camera.position);
  CHECK(back.camera->forward == camera.forward);
  CHECK(back.camera->verticalFovDegrees == camera.verticalFovDegrees);
  CHECK(back.settings.radianceClamp == 0.3f);
  CHECK_FALSE(render::renderJobFromJson(R"({"format":"penumbra-render","version":1})", "x").camera);
}

TEST_CASE("render job: malformed records name the file and the field", "[render]") {
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(R"({"format":"penumbra-scene","version":1})", "a.json"),
      "a.json: not a penumbra render settings file (\"format\": \"penumbra-render\")");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(R"({"format":"penumbra-render","version":1,"strategy":"best"})",
                                "b.json"),
      "b.json: \"strategy\" 'best' is not a known value");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(
                          R"({"format":"penumbra-render","version":1,"sppPerFrame":32})", "c.json"),
                      "c.json: \"sppPerFrame\" must be 1..16");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(
          R"({"format":"penumbra-render","version":1,"camera":{"position":[1,2]}})", "d.json"),
      "d.json: \"camera.forward\" is missing");
}
