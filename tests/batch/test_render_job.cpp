// The render settings record (engine/penumbra/batch/render_job.h) that viewer
// screenshots leave and `penumbra render --settings` reads.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <nlohmann/json.hpp>

#include "penumbra/batch/render_job.h"
#include "penumbra/util/error.h"

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
  CHECK(job.camera->position == glm::dvec3(0.5, 1.25, -3.0));
  CHECK(job.camera->verticalFovDegrees == 30.0f);
  CHECK_FALSE(job.camera->orthographic());  // no "orthographicHeight": perspective
  CHECK(job.width == 320u);
  CHECK(job.height == 200u);
  CHECK(job.spp == 48u);
  CHECK(job.settings.sppPerFrame == 4u);
  CHECK(job.settings.tracer.integrator == render::Integrator::Whitted);
  CHECK(job.settings.tracer.strategy == render::SamplingStrategy::Nee);
  CHECK(job.settings.tracer.misHeuristic == render::MisHeuristic::Balance);
  CHECK(job.settings.tracer.maxDepth == 5u);
  CHECK_FALSE(job.settings.tracer.russianRoulette);
  CHECK(job.settings.tracer.rouletteStartDepth == 2u);
  CHECK(job.settings.tracer.radianceClamp == 8.0f);
  CHECK(job.settings.tracer.seed == 11u);
  CHECK(job.settings.toneMapping.exposure == 1.5f);
  CHECK(job.settings.toneMapping.toneOperator == render::ToneMapOperator::Reinhard);
  CHECK(job.settings.allEffects);
}

TEST_CASE("render job: floats survive the round trip bit for bit", "[render]") {
  render::RenderJob job;
  scene::Camera camera;
  // Values with no short decimal form: a lossy writer would change them.
  camera.position = {0.1f, 1.0f / 3.0f, -2.7182817f};
  camera.forward = {0.5773503f, 0.5773503f, 0.5773503f};
  camera.verticalFovDegrees = 39.3077f;
  job.camera = camera;
  job.settings.tracer.radianceClamp = 0.3f;
  const auto back = render::renderJobFromJson(render::renderJobToJson(job), "round trip");
  REQUIRE(back.camera.has_value());
  CHECK(back.camera->position == camera.position);
  CHECK(back.camera->forward == camera.forward);
  CHECK(back.camera->verticalFovDegrees == camera.verticalFovDegrees);
  CHECK(back.settings.tracer.radianceClamp == 0.3f);
  CHECK_FALSE(render::renderJobFromJson(R"({"format":"penumbra-render","version":1})", "x").camera);
}

// Every field the record holds, each away from its default, written and
// read back: a field the writer forgets or the reader skips comes back as
// its default and fails here.
TEST_CASE("render job: the writer round trips every field", "[render]") {
  render::RenderJob job;
  job.scene = "material-test";
  job.vary = "sheen";
  job.set = "metallic=1";
  job.variant = "midnight";
  job.animation = {"Walk", 1.0 / 3.0};  // not exact in decimal: read back bit for bit
  scene::Camera camera;
  camera.position = {0.25, -1.5, 3.75};
  camera.forward = {0.0f, -0.6f, 0.8f};
  camera.up = {0.0f, 0.8f, 0.6f};
  camera.verticalFovDegrees = 33.0f;
  camera.aspectRatio = 2.25f;
  camera.apertureRadius = 0.015f;
  camera.focusDistance = 2.5f;
  camera.apertureBlades = 7;
  job.camera = camera;
  job.width = 321;
  job.height = 123;
  job.spp = 77;
  job.settings.sppPerFrame = 7;
  auto& t = job.settings.tracer;
  t.integrator = render::Integrator::Whitted;
  t.strategy = render::SamplingStrategy::Cosine;
  t.misHeuristic = render::MisHeuristic::Balance;
  t.sampler = render::Sampler::Random;  // not the default
  t.maxDepth = 13;
  t.russianRoulette = false;
  t.rouletteStartDepth = 5;
  t.radianceClamp = 4.5f;
  t.seed = 99;
  t.writeGuides = true;
  job.settings.toneMapping.exposure = 0.75f;
  job.settings.toneMapping.toneOperator = render::ToneMapOperator::AcesFitted;
  job.settings.allEffects = true;
  job.environment.map = "sky.hdr";
  job.environment.rotationDegrees = -35.0f;
  job.environment.intensity = 2.25f;
  job.environment.visibleBackground = false;
  const auto back = render::renderJobFromJson(render::renderJobToJson(job), "round trip");
  CHECK(back.scene == job.scene);
  CHECK(back.vary == job.vary);
  CHECK(back.set == job.set);
  CHECK(back.variant == job.variant);
  CHECK(back.animation.animation == job.animation.animation);
  CHECK(back.animation.seconds == job.animation.seconds);
  REQUIRE(back.camera.has_value());
  CHECK(back.camera->position == camera.position);
  CHECK(back.camera->forward == camera.forward);
  CHECK(back.camera->up == camera.up);
  CHECK(back.camera->verticalFovDegrees == camera.verticalFovDegrees);
  CHECK(back.camera->aspectRatio == camera.aspectRatio);
  CHECK(back.camera->apertureRadius == camera.apertureRadius);
  CHECK(back.camera->focusDistance == camera.focusDistance);
  CHECK(back.camera->apertureBlades == camera.apertureBlades);
  CHECK(back.camera->orthographicHeight == 0.0f);
  // An orthographic camera's height comes back too.
  render::RenderJob orthoJob = job;
  orthoJob.camera->orthographicHeight = 2.75f;
  const auto orthoBack =
      render::renderJobFromJson(render::renderJobToJson(orthoJob), "orthographic round trip");
  CHECK(orthoBack.camera->orthographicHeight == 2.75f);
  CHECK(back.width == job.width);
  CHECK(back.height == job.height);
  CHECK(back.spp == job.spp);
  CHECK(back.settings.sppPerFrame == job.settings.sppPerFrame);
  CHECK(back.settings.tracer.integrator == t.integrator);
  CHECK(back.settings.tracer.strategy == t.strategy);
  CHECK(back.settings.tracer.misHeuristic == t.misHeuristic);
  CHECK(back.settings.tracer.sampler == t.sampler);
  CHECK(back.settings.tracer.maxDepth == t.maxDepth);
  CHECK(back.settings.tracer.russianRoulette == t.russianRoulette);
  CHECK(back.settings.tracer.rouletteStartDepth == t.rouletteStartDepth);
  CHECK(back.settings.tracer.radianceClamp == t.radianceClamp);
  CHECK(back.settings.tracer.seed == t.seed);
  CHECK(back.settings.tracer.writeGuides == t.writeGuides);
  CHECK(back.settings.toneMapping.exposure == job.settings.toneMapping.exposure);
  CHECK(back.settings.toneMapping.toneOperator == job.settings.toneMapping.toneOperator);
  CHECK(back.settings.allEffects == job.settings.allEffects);
  CHECK(back.environment.map == "sky.hdr");
  CHECK(back.environment.rotationDegrees == -35.0f);
  CHECK(back.environment.intensity == 2.25f);
  CHECK(back.environment.visibleBackground == false);
  // Nothing given, nothing recorded: the scene's own environment stays.
  CHECK(render::renderJobToJson(render::RenderJob{}).find("environment") == std::string::npos);
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
                      "c.json: \"sppPerFrame\" 32 is not a whole number in 1..16");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(
          R"({"format":"penumbra-render","version":1,"camera":{"position":[1,2]}})", "d.json"),
      "d.json: \"camera.forward\" is missing");
}

TEST_CASE("render job: material overrides round trip bit for bit", "[render]") {
  render::RenderJob job;
  scene::Material m = scene::Material::lambert("white", glm::vec3(0.1f, 1.0f / 3.0f, 0.7f));
  m.model = scene::MaterialModel::Phong;
  m.roughness = 0.2f;
  m.ior = 1.4142135f;
  m.exponent = 77.7f;
  m.transparency = 0.3f;
  m.thin = true;
  job.materials.push_back({2, m});
  const std::string text = render::renderJobToJson(job);
  CHECK_THAT(text, Catch::Matchers::ContainsSubstring("\"materials\""));
  const auto back = render::renderJobFromJson(text, "round trip");
  REQUIRE(back.materials.size() == 1);
  const auto& o = back.materials[0];
  CHECK(o.index == 2u);
  CHECK(o.material.name == "white");
  CHECK(o.material.model == scene::MaterialModel::Phong);
  CHECK(o.material.baseColor == m.baseColor);
  CHECK(o.material.roughness == 0.2f);
  CHECK(o.material.ior == 1.4142135f);
  CHECK(o.material.exponent == 77.7f);
  CHECK(o.material.transparency == 0.3f);
  CHECK(o.material.thin);
  // No edits: no "materials" key, and a record without one (older) loads.
  CHECK_THAT(render::renderJobToJson(render::RenderJob{}),
             !Catch::Matchers::ContainsSubstring("materials"));
  CHECK(render::renderJobFromJson(R"({"format":"penumbra-render","version":1})", "old.json")
            .materials.empty());
}

TEST_CASE("render job: overrides apply the edited parameters and keep the rest", "[render]") {
  scene::Scene loaded;
  loaded.name = "box";
  loaded.materials = {scene::Material::lambert("white", glm::vec3(0.8f)),
                      scene::Material::lambert("red", glm::vec3(0.6f, 0.05f, 0.05f))};
  loaded.materials[1].baseColorTexture = 4;
  loaded.materials[1].alpha = 0.5f;
  auto edited = loaded.materials;
  render::setEditableParameter(edited[1], "baseColor", {0.2f, 0.3f, 0.4f});
  render::setEditableParameter(edited[1], "metallic", {1.0f});
  const auto overrides = render::materialOverrides(loaded.materials, edited);
  REQUIRE(overrides.size() == 1);
  CHECK(overrides[0].index == 1u);

  scene::Scene box = loaded;
  render::applyMaterialOverrides(box, overrides, "shot.json");
  CHECK(box.materials[1].baseColor == glm::vec3(0.2f, 0.3f, 0.4f));
  CHECK(box.materials[1].metallic == 1.0f);
  CHECK(box.materials[1].baseColorTexture == 4u);
  CHECK(box.materials[1].alpha == 0.5f);
  CHECK(box.materials[0].baseColor == glm::vec3(0.8f));
  REQUIRE_THROWS_WITH(render::setEditableParameter(edited[0], "baseColor", {1.0f}),
                      "material parameter 'baseColor' takes 3 number(s), got 1");
  REQUIRE_THROWS_WITH(render::setEditableParameter(edited[0], "sheenColor", {2.0f, 0.0f, 0.0f}),
                      "material parameter 'sheenColor' takes values in [0, 1], got 2");
  REQUIRE_THROWS_WITH(render::setEditableParameter(edited[0], "specularColor", {3.0f, -1.0f, 0.0f}),
                      "material parameter 'specularColor' takes values >= 0, got -1");
  render::setEditableParameter(edited[0], "specularColor", {3.0f, 1.0f, 0.0f});
  CHECK(edited[0].specularColor == glm::vec3(3.0f, 1.0f, 0.0f));
}

TEST_CASE(
    "render job: parameters made editable later (glTF anisotropy, sheen roughness, diffuse "
    "transmission, the colours) are recorded; a record written before them keeps the scene's",
    "[render]") {
  scene::Scene loaded;
  loaded.name = "brushed";
  loaded.materials = {scene::Material::lambert("steel", glm::vec3(0.8f))};
  loaded.materials[0].model = scene::MaterialModel::Disney;
  loaded.materials[0].anisotropyStrength = 0.25f;
  loaded.materials[0].anisotropyRotation = 0.5f;
  auto edited = loaded.materials;
  render::setEditableParameter(edited[0], "anisotropyStrength", {0.75f});
  render::setEditableParameter(edited[0], "anisotropyRotation", {-1.25f});
  render::setEditableParameter(edited[0], "sheenRoughness", {0.4f});
  render::setEditableParameter(edited[0], "diffuseTransmission", {0.3f});
  render::setEditableParameter(edited[0], "specularColor", {2.0f, 1.0f, 0.5f});
  render::setEditableParameter(edited[0], "sheenColor", {0.9f, 0.5f, 0.1f});
  render::setEditableParameter(edited[0], "diffuseTransmissionColor", {0.2f, 0.8f, 0.4f});
  render::setEditableParameter(edited[0], "iridescence", {0.6f});
  render::setEditableParameter(edited[0], "iridescenceIor", {1.45f});
  render::setEditableParameter(edited[0], "iridescenceThickness", {510.0f});
  render::setEditableParameter(edited[0], "dispersion", {0.7f});
  render::RenderJob job;
  job.materials = render::materialOverrides(loaded.materials, edited);
  REQUIRE(job.materials.size() == 1);
  const std::string text = render::renderJobToJson(job);
  scene::Scene applied = loaded;
  render::applyMaterialOverrides(applied, render::renderJobFromJson(text, "new.json").materials,
                                 "new.json");
  CHECK(applied.materials[0].anisotropyStrength == 0.75f);
  CHECK(applied.materials[0].anisotropyRotation == -1.25f);
  CHECK(applied.materials[0].sheenRoughness == 0.4f);
  CHECK(applied.materials[0].diffuseTransmission == 0.3f);
  CHECK(applied.materials[0].specularColor == glm::vec3(2.0f, 1.0f, 0.5f));
  CHECK(applied.materials[0].sheenColor == glm::vec3(0.9f, 0.5f, 0.1f));
  CHECK(applied.materials[0].diffuseTransmissionColor == glm::vec3(0.2f, 0.8f, 0.4f));
  CHECK(applied.materials[0].iridescence == 0.6f);
  CHECK(applied.materials[0].iridescenceIor == 1.45f);
  CHECK(applied.materials[0].iridescenceThicknessMaximum == 510.0f);
  CHECK(applied.materials[0].dispersion == 0.7f);

  // The same record as written before the fields were editable: the other
  // edits apply, the scene's anisotropy stays, and writing it again does
  // not invent values for the fields it lacks.
  nlohmann::json old = nlohmann::json::parse(text);
  nlohmann::json& override0 = old.at("materials").at(0);
  override0.erase("anisotropyStrength");
  override0.erase("anisotropyRotation");
  override0.erase("sheenRoughness");
  override0.erase("diffuseTransmission");
  override0.erase("specularColor");
  override0.erase("sheenColor");
  override0.erase("diffuseTransmissionColor");
  override0.erase("iridescence");
  override0.erase("iridescenceIor");
  override0.erase("iridescenceThickness");
  override0.erase("dispersion");
  override0.at("metallic") = 1.0;
  const auto oldJob = render::renderJobFromJson(old.dump(), "old.json");
  scene::Scene fromOld = loaded;
  render::applyMaterialOverrides(fromOld, oldJob.materials, "old.json");
  CHECK(fromOld.materials[0].metallic == 1.0f);
  CHECK(fromOld.materials[0].anisotropyStrength == 0.25f);
  CHECK(fromOld.materials[0].anisotropyRotation == 0.5f);
  CHECK(fromOld.materials[0].sheenRoughness == 0.0f);
  CHECK(fromOld.materials[0].diffuseTransmission == 0.0f);
  CHECK(fromOld.materials[0].specularColor == glm::vec3(1.0f));
  CHECK(fromOld.materials[0].sheenColor == glm::vec3(1.0f));
  CHECK(fromOld.materials[0].diffuseTransmissionColor == glm::vec3(1.0f));
  CHECK(fromOld.materials[0].iridescence == 0.0f);
  CHECK(fromOld.materials[0].iridescenceThicknessMaximum == 400.0f);
  CHECK(fromOld.materials[0].dispersion == 0.0f);
  const std::string rewritten = render::renderJobToJson(oldJob);
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("anisotropy"));
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("sheenRoughness"));
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("diffuseTransmission"));
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("specularColor"));
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("sheenColor"));
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("iridescence"));
  CHECK_THAT(rewritten, !Catch::Matchers::ContainsSubstring("dispersion"));
  // Fields there from the start stay required.
  override0.erase("sheen");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(old.dump(), "older.json"),
                      "older.json: \"materials[0].sheen\" is missing");
}

TEST_CASE("render job: bad material overrides name the file and the field", "[render]") {
  scene::Scene box;
  box.name = "box";
  box.materials = {scene::Material::lambert("white", glm::vec3(0.8f))};
  render::MaterialOverride outOfRange{3, box.materials[0]};
  REQUIRE_THROWS_WITH(
      render::applyMaterialOverrides(box, {outOfRange}, "e.json"),
      "e.json: \"materials[0].index\" 3 is out of range: scene 'box' has 1 materials");
  render::MaterialOverride renamed{0, box.materials[0]};
  renamed.material.name = "floor";
  REQUIRE_THROWS_WITH(
      render::applyMaterialOverrides(box, {renamed}, "f.json"),
      "f.json: \"materials[0].name\" 'floor' does not match material 0 of scene 'box' ('white')");

  // A valid override's JSON with one field broken at a time.
  render::RenderJob job;
  job.materials.push_back({0, box.materials[0]});
  const std::string good = render::renderJobToJson(job);
  auto broken = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
  };
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(broken("\"roughness\": 1.0", "\"roughness\": 1e39"), "g.json"),
      "g.json: \"materials[0].roughness\" must be a finite number");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(broken("\"metallic\": 0.0", "\"metallic\": null"), "h.json"),
      "h.json: \"materials[0].metallic\" must be a number");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(broken("\"index\": 0", "\"index\": -1"), "i.json"),
                      "i.json: \"materials[0].index\" must be a whole number >= 0");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(broken("\"lambert\"", "\"glass\""), "j.json"),
      "j.json: \"materials[0].model\" must be one of disney, lambert, phong, unlit");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(broken("\"thin\": false,", ""), "k.json"),
                      "k.json: \"materials[0].thin\" is missing");
}

// Every field's type and range is checked before it is converted
// (docs/security.md): 1e300 as an unsigned integer was undefined behaviour
// that rendered with 0, 1e39 as a float infinity.
TEST_CASE("render job: out-of-range numbers and wrong types name the file and the field",
          "[render]") {
  auto record = [](const std::string& fields) {
    return R"({"format":"penumbra-render","version":1,)" + fields + "}";
  };
  using Catch::Matchers::ContainsSubstring;
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("seed":1e300)"), "s.json"),
                      "s.json: \"seed\" 1e+300 is not a whole number in 0..4294967295");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("maxDepth":1e300)"), "s.json"),
                      "s.json: \"maxDepth\" 1e+300 is not a whole number in 0..1024");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("maxDepth":-1)"), "s.json"),
                      "s.json: \"maxDepth\" -1 is not a whole number in 0..1024");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("spp":2.5)"), "s.json"),
                      "s.json: \"spp\" 2.5 is not a whole number in 1..1048576");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("width":"wide")"), "s.json"),
                      "s.json: \"width\" is not a whole number (got a string)");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("radianceClamp":1e39)"), "s.json"),
                      "s.json: \"radianceClamp\" must be a finite number");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("radianceClamp":-1)"), "s.json"),
                      ContainsSubstring("s.json: \"radianceClamp\" -1 is outside 0.."));
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("time":"soon")"), "s.json"),
                      "s.json: \"time\" must be a finite number (seconds)");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("scene":["a"])"), "s.json"),
                      "s.json: \"scene\" must be a string (got an array)");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("allEffects":"yes")"), "s.json"),
                      "s.json: \"allEffects\" must be true or false (got a string)");
  REQUIRE_THROWS_WITH(render::renderJobFromJson(record(R"("exposure":1e400)"), "s.json"),
                      ContainsSubstring("s.json: not valid JSON") &&
                          ContainsSubstring("number overflow parsing '1e400'"));
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(record(R"("camera":{"position":[0,0,0],"forward":[0,0,0],
                                                    "up":[0,1,0]})"),
                                "s.json"),
      "s.json: \"camera.forward\" must be a non-zero direction of finite length");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(record(R"("camera":{"position":[0,0,0],"forward":[0,0,1],
                                                    "up":[0,0,2]})"),
                                "s.json"),
      "s.json: \"camera.up\" must be non-zero and not parallel to camera.forward");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(record(R"("camera":{"position":[1e39,0,0],"forward":[0,0,1],
                                                    "up":[0,1,0]})"),
                                "s.json"),
      "s.json: \"camera.position\" must be a finite number");
  REQUIRE_THROWS_WITH(
      render::renderJobFromJson(record(R"("camera":{"position":[0,0,0],"forward":[0,0,1],
                                                    "up":[0,1,0],"apertureBlades":1e300})"),
                                "s.json"),
      "s.json: \"camera.apertureBlades\" 1e+300 is not a whole number in 0..32");
  REQUIRE_THROWS_WITH(render::renderJobFromJson("[1]", "s.json"),
                      ContainsSubstring("s.json: not a penumbra render settings file"));
  REQUIRE_THROWS_WITH(render::renderJobFromJson(R"({"format":7,"version":1})", "s.json"),
                      ContainsSubstring("s.json: not a penumbra render settings file"));

  // The ends of each range still load.
  const auto job = render::renderJobFromJson(
      record(R"("seed":4294967295,"maxDepth":1024,"spp":1048576,"sppPerFrame":16.0)"), "s.json");
  CHECK(job.settings.tracer.seed == 4294967295u);
  CHECK(job.settings.tracer.maxDepth == 1024u);
  CHECK(job.spp == 1048576u);
  CHECK(job.settings.sppPerFrame == 16u);
}

TEST_CASE("render job: records nested past the JSON depth limit are refused unparsed", "[render]") {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  REQUIRE_THROWS_WITH(render::renderJobFromJson(
                          R"({"format":"penumbra-render","version":1,"x":)" + deep + "}", "s.json"),
                      Catch::Matchers::ContainsSubstring("s.json: JSON nests") &&
                          Catch::Matchers::ContainsSubstring("InputLimits::maxJsonDepth"));
  // 255 levels below the document's own still load.
  const std::string ok = std::string(255, '[') + std::string(255, ']');
  REQUIRE_NOTHROW(render::renderJobFromJson(
      R"({"format":"penumbra-render","version":1,"x":)" + ok + "}", "s.json"));
}
