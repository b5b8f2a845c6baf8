#include <fmt/format.h>
#include <unistd.h>

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gltf_test_files.h"
#include "penumbra/image/image_io.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/mesh_builders.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"
#include "penumbra/util/json_nesting.h"
#include "test_data.h"

using namespace penumbra;
using Catch::Approx;
using Catch::Matchers::ContainsSubstring;

TEST_CASE("the Cornell box matches the canonical data", "[scene]") {
  const auto s = scene::loadScene("cornell-box");
  REQUIRE(s.name == "cornell-box");
  // 5 room quads + light + 2 blocks of 5 quads = 16 quads.
  REQUIRE(s.triangleCount() == 32u);
  REQUIRE(s.camera.position.x == Approx(0.278f));
  REQUIRE(s.camera.position.y == Approx(0.273f));
  REQUIRE(s.camera.position.z == Approx(-0.800f));
  REQUIRE(s.camera.verticalFovDegrees == Approx(39.3077f));

  const scene::Mesh* light = nullptr;
  for (const auto& m : s.meshes)
    if (m.name == "light") light = &m;
  REQUIRE(light != nullptr);
  const auto& lm = s.materials[light->material];
  REQUIRE(lm.emission == glm::vec3(17, 12, 4));
  REQUIRE(lm.baseColor == glm::vec3(0.0f));
  REQUIRE(lm.model == scene::MaterialModel::Lambert);
  // Light: x in [213, 343] mm, z in [227, 332] mm, 0.1 mm below the ceiling,
  // and its counter-clockwise face points down.
  for (const auto& p : light->positions) {
    REQUIRE(p.y == Approx(0.5487f));
    REQUIRE(p.x >= 0.213f - 1e-6f);
    REQUIRE(p.x <= 0.343f + 1e-6f);
  }
  for (size_t t = 0; t < light->indices.size(); t += 3) {
    auto a = light->positions[light->indices[t]];
    auto b = light->positions[light->indices[t + 1]];
    auto c = light->positions[light->indices[t + 2]];
    REQUIRE(glm::cross(b - a, c - a).y < 0.0f);
  }
  for (const auto& m : s.materials) {
    if (m.name == "red") REQUIRE(m.baseColor == glm::vec3(0.63f, 0.065f, 0.05f));
    if (m.name == "green") REQUIRE(m.baseColor == glm::vec3(0.14f, 0.45f, 0.091f));
    if (m.name == "white") REQUIRE(m.baseColor == glm::vec3(0.725f, 0.71f, 0.68f));
  }
}

TEST_CASE("bad scene input gives one clear error", "[scene]") {
  REQUIRE_THROWS_WITH(scene::loadScene("no-such-scene"),
                      ContainsSubstring("no built-in scene") && ContainsSubstring("cornell-box"));
  REQUIRE_THROWS_WITH(scene::parseScene("{ not json", "t.json"), ContainsSubstring("invalid JSON"));
  REQUIRE_THROWS_WITH(scene::parseScene(R"({"format":"other"})", "t.json"),
                      ContainsSubstring("not a penumbra scene"));
  const char* unknownMaterial = R"({"format":"penumbra-scene","version":1,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
    "materials":{"white":{"albedo":[0.5,0.5,0.5]}},
    "meshes":[{"name":"q","material":"blue","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
  REQUIRE_THROWS_WITH(
      scene::parseScene(unknownMaterial, "t.json"),
      ContainsSubstring("mesh 'q'") && ContainsSubstring("unknown material 'blue'"));
  const char* badAlbedo = R"({"format":"penumbra-scene","version":1,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
    "materials":{"white":{"albedo":[1.5,0.5,0.5]}},
    "meshes":[{"name":"q","material":"white","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
  REQUIRE_THROWS_WITH(scene::parseScene(badAlbedo, "t.json"), ContainsSubstring("baseColor"));
}

TEST_CASE("the furnace sphere is closed and faces inwards", "[scene]") {
  auto mesh = scene::makeIcosphere(2, 2.0f, true, 0);
  REQUIRE(mesh.triangleCount() == 20u * 16u);
  for (const auto& p : mesh.positions) REQUIRE(glm::length(p) == Approx(2.0f));
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    auto a = mesh.positions[mesh.indices[t]];
    auto b = mesh.positions[mesh.indices[t + 1]];
    auto c = mesh.positions[mesh.indices[t + 2]];
    // The counter-clockwise normal points towards the centre.
    REQUIRE(glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0f);
  }
}

TEST_CASE("glTF files in a scene file bring their textures, indices offset", "[scene]") {
  // A scene-file material and floor, then textured_quad.gltf (one texture,
  // one reference) and alpha_mask_quad.gltf (likewise).
  const auto s = scene::loadScene(test::dataPath("gltf/textured_merged.json"));
  REQUIRE(s.textures.size() == 2u);
  REQUIRE(s.textureRefs.size() == 2u);
  REQUIRE(s.materials.size() == 3u);
  REQUIRE(s.materials[0].name == "white");
  REQUIRE(s.materials[0].baseColorTexture == scene::Material::kNoTexture);
  REQUIRE(s.materials[0].emissiveTexture == scene::Material::kNoTexture);
  // The checker: emissive, reference 0 -> texture 0.
  REQUIRE(s.materials[1].emissiveTexture == 0u);
  REQUIRE(s.textureRefs[0].texture == 0u);
  // The alpha mask: its reference 0 became 1, its texture 0 became 1.
  const auto& mask = s.materials[2];
  REQUIRE(mask.alphaMode == scene::AlphaMode::Mask);
  REQUIRE(mask.baseColorTexture == 1u);
  REQUIRE(mask.emissiveTexture == scene::Material::kNoTexture);
  REQUIRE(s.textureRefs[1].texture == 1u);
  // Texel (1, 0) of the alpha mask is transparent, of the checker opaque blue-ish.
  REQUIRE(s.textures[1].rgba8[4 + 3] == 0);
  REQUIRE(s.textures[0].rgba8[4 + 3] == 255);
  REQUIRE_NOTHROW(scene::validate(s));
}

TEST_CASE("scene-file lights: point with range, spot, directional; bad cones refused", "[scene]") {
  auto withLights = [](const std::string& lights) {
    return R"({"format":"penumbra-scene","version":1,"unitScale":0.5,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
    "materials":{"white":{"albedo":[0.5,0.5,0.5]}},
    "lights":[)" +
           lights + R"(],
    "meshes":[{"name":"q","material":"white","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
  };
  const auto scene = scene::parseScene(
      withLights(R"({"type":"point","position":[0,4,0],"intensity":[1,1,1],"range":6},
                    {"type":"spot","position":[0,4,0],"intensity":[1,1,1],"direction":[0,-2,0],
                     "outerConeDegrees":30,"innerConeDegrees":10},
                    {"type":"directional","direction":[0,-1,0],"intensity":[2,2,2]})"),
      "t.json");
  REQUIRE(scene.pointLights.size() == 3u);
  CHECK(scene.pointLights[0].type == scene::LightType::Point);
  CHECK(scene.pointLights[0].position.y == 2.0);  // unit scale 0.5
  CHECK(scene.pointLights[0].range == 3.0f);      // scaled as positions are
  CHECK(scene.pointLights[1].type == scene::LightType::Spot);
  CHECK(scene.pointLights[1].direction.y == -1.0f);
  CHECK(scene.pointLights[1].innerConeDegrees == 10.0f);
  CHECK(scene.pointLights[2].type == scene::LightType::Directional);
  CHECK(scene.pointLights[2].intensity.r == 2.0f);
  REQUIRE_THROWS_WITH(
      scene::parseScene(withLights(R"({"type":"spot","position":[0,4,0],"intensity":[1,1,1],
        "direction":[0,-1,0],"outerConeDegrees":10,"innerConeDegrees":30})"),
                        "t.json"),
      ContainsSubstring("t.json' light") && ContainsSubstring("innerConeDegrees 30"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(withLights(R"({"type":"area","position":[0,4,0],"intensity":[1,1,1]})"),
                        "t.json"),
      ContainsSubstring("unknown light type 'area'"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(
          withLights(R"({"type":"directional","direction":[0,0,0],"intensity":[1,1,1]})"),
          "t.json"),
      ContainsSubstring("direction: must not be zero"));
}

TEST_CASE("scene files: a soft sun, a lens by f-number with blades, an environment", "[scene]") {
  auto scene = [](const std::string& camera, const std::string& extra) {
    return R"({"format":"penumbra-scene","version":1,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":39.6)" +
           camera + R"(},
    "materials":{"white":{"albedo":[0.5,0.5,0.5]}},)" +
           extra + R"(
    "meshes":[{"name":"q","material":"white","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
  };
  const auto s = scene::parseScene(
      scene(R"(,"fNumber":2,"focusDistance":3,"apertureBlades":7)",
            R"("lights":[{"type":"directional","direction":[0,-1,0],"intensity":[2,2,2],
                          "angularRadiusDegrees":0.27}],
               "environment":{"color":[0.2,0.3,0.4],"rotation":45,"intensity":2,"background":false},)"),
      "t.json");
  CHECK(std::abs(s.camera.apertureRadius - 0.0083f) < 0.0001f);  // 33 mm / (2 x 2)
  CHECK(s.camera.apertureBlades == 7u);
  CHECK(s.pointLights.at(0).angularRadiusDegrees == 0.27f);
  REQUIRE(s.environment.present());
  CHECK(s.environment.radiance[0].b == 0.4f);
  CHECK(s.environment.rotationDegrees == 45.0f);
  CHECK(s.environment.intensity == 2.0f);
  CHECK_FALSE(s.environment.visibleBackground);
  REQUIRE_THROWS_WITH(
      scene::parseScene(scene("", R"("environment":{"file":"missing.hdr"},)"), "t.json"),
      ContainsSubstring("missing.hdr") && ContainsSubstring("no such file"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(scene("", R"("environment":{"color":[1,1,1],"file":"a.exr"},)"), "t.json"),
      ContainsSubstring("exactly one of"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(scene("", R"("environment":{"color":[1,1,1],"intensity":-2},)"), "t.json"),
      ContainsSubstring("t.json' environment") && ContainsSubstring("intensity -2"));
  REQUIRE_THROWS_WITH(scene::parseScene(scene(R"(,"fNumber":0)", ""), "t.json"),
                      ContainsSubstring("fNumber 0"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(scene("", R"("lights":[{"type":"directional","direction":[0,-1,0],
          "intensity":[1,1,1],"angularRadiusDegrees":95}],)"),
                        "t.json"),
      ContainsSubstring("angularRadiusDegrees"));
}

TEST_CASE("scene files: an orthographic camera, its height in file units", "[scene][camera]") {
  auto scene = [](const std::string& camera) {
    return R"({"format":"penumbra-scene","version":1,"unitScale":0.001,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0])" +
           camera + R"(},
    "materials":{"white":{"albedo":[0.5,0.5,0.5]}},
    "meshes":[{"name":"q","material":"white","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
  };
  const auto s = scene::parseScene(scene(R"(,"orthographicHeight":1500)"), "t.json");
  CHECK(s.camera.orthographic());
  CHECK(s.camera.orthographicHeight == Approx(1.5f));  // 1500 mm
  CHECK_FALSE(
      scene::parseScene(scene(R"(,"verticalFovDegrees":40)"), "t.json").camera.orthographic());
  REQUIRE_THROWS_WITH(scene::parseScene(scene(""), "t.json"),
                      ContainsSubstring("t.json' camera: give \"verticalFovDegrees\"") &&
                          ContainsSubstring("exactly one"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(scene(R"(,"verticalFovDegrees":40,"orthographicHeight":2)"), "t.json"),
      ContainsSubstring("exactly one"));
  REQUIRE_THROWS_WITH(scene::parseScene(scene(R"(,"orthographicHeight":-2)"), "t.json"),
                      ContainsSubstring("\"orthographicHeight\" -2 must be finite and > 0"));
  REQUIRE_THROWS_WITH(scene::parseScene(scene(R"(,"orthographicHeight":2,"fNumber":4)"), "t.json"),
                      ContainsSubstring("no focal length for \"fNumber\""));
}

TEST_CASE("scene-file materials: an absorbing medium, scaled; a bad one refused", "[scene]") {
  auto withGlass = [](const std::string& glass) {
    return R"({"format":"penumbra-scene","version":1,"unitScale":0.001,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
    "materials":{"glass":)" +
           glass + R"(},
    "meshes":[{"name":"q","material":"glass","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
  };
  const auto scene = scene::parseScene(
      withGlass(R"({"specTrans":1,"attenuationColor":[0.5,0.8,1],"attenuationDistance":250})"),
      "t.json");
  CHECK(scene.materials[0].attenuationDistance == Catch::Approx(0.25f));  // millimetres
  CHECK(scene.materials[0].attenuationColor.r == 0.5f);
  REQUIRE_THROWS_WITH(
      scene::parseScene(withGlass(R"({"specTrans":1,"attenuationDistance":0})"), "t.json"),
      ContainsSubstring("attenuationDistance 0 must be > 0"));
  REQUIRE_THROWS_WITH(
      scene::parseScene(withGlass(R"({"specTrans":1,"attenuationColor":[2,1,1]})"), "t.json"),
      ContainsSubstring("attenuationColor must lie in [0, 1]"));
  // Diffuse transmission (a leaf), with its colour; outside [0, 1] refused.
  const auto leaf = scene::parseScene(
      withGlass(
          R"({"diffuseTransmission":0.4,"diffuseTransmissionColor":[0.2,0.9,0.1],"specularF90":0.5})"),
      "t.json");
  CHECK(leaf.materials[0].specularF90 == 0.5f);
  CHECK(leaf.materials[0].diffuseTransmission == 0.4f);
  CHECK(leaf.materials[0].diffuseTransmissionColor == glm::vec3(0.2f, 0.9f, 0.1f));
  REQUIRE_THROWS_WITH(
      scene::parseScene(withGlass(R"({"diffuseTransmissionColor":[1.5,1,1]})"), "t.json"),
      ContainsSubstring("diffuseTransmissionColor must lie in [0, 1]"));
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"diffuseTransmission":2})"), "t.json"),
                      ContainsSubstring("a parameter is outside [0, 1]"));
  // A thin film (its thickness in nm); an index below air's or a negative
  // thickness refused.
  const auto bubble = scene::parseScene(
      withGlass(R"({"iridescence":0.9,"iridescenceIor":1.33,"iridescenceThickness":520})"),
      "t.json");
  CHECK(bubble.materials[0].iridescence == 0.9f);
  CHECK(bubble.materials[0].iridescenceIor == 1.33f);
  CHECK(bubble.materials[0].iridescenceThicknessMaximum == 520.0f);
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"iridescenceIor":0.5})"), "t.json"),
                      ContainsSubstring("iridescenceIor must lie in [1, 4]"));
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"iridescenceThickness":-1})"), "t.json"),
                      ContainsSubstring("iridescence thicknesses must lie in [0, 1e5] nm"));
  // Dispersion (20 / Abbe number); a negative one refused.
  CHECK(scene::parseScene(withGlass(R"({"dispersion":0.33})"), "t.json").materials[0].dispersion ==
        0.33f);
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"dispersion":-0.1})"), "t.json"),
                      ContainsSubstring("dispersion must lie in [0, 10]"));
  // glTF's anisotropy, in scene files too.
  const auto brushed = scene::parseScene(
      withGlass(R"({"metallic":1,"anisotropyStrength":0.6,"anisotropyRotation":-2})"), "t.json");
  CHECK(brushed.materials[0].anisotropyStrength == 0.6f);
  CHECK(brushed.materials[0].anisotropyRotation == -2.0f);
  REQUIRE_THROWS_WITH(
      scene::parseScene(withGlass(R"({"metallic":1,"anisotropyStrength":1.5})"), "t.json"),
      ContainsSubstring("a parameter is outside [0, 1]"));
  // The dielectric F0's colour (unbounded above) and the sheen's (in [0, 1]).
  const auto coloured = scene::parseScene(
      withGlass(R"({"specularColor":[12.5,3,0.2],"sheen":1,"sheenColor":[1,0.5,0]})"), "t.json");
  CHECK(coloured.materials[0].specularColor == glm::vec3(12.5f, 3.0f, 0.2f));
  CHECK(coloured.materials[0].sheenColor == glm::vec3(1.0f, 0.5f, 0.0f));
  const auto velvet = scene::parseScene(
      withGlass(R"({"model":"lambert","sheen":1,"sheenRoughness":0.3})"), "t.json");
  CHECK(velvet.materials[0].sheenRoughness == 0.3f);
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"sheenRoughness":1.5})"), "t.json"),
                      ContainsSubstring("a parameter is outside [0, 1]"));
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"specularColor":[1,-1,1]})"), "t.json"),
                      ContainsSubstring("specularColor must be finite and non-negative"));
  REQUIRE_THROWS_WITH(scene::parseScene(withGlass(R"({"sheenColor":[1,2,1]})"), "t.json"),
                      ContainsSubstring("sheenColor must lie in [0, 1]"));
}

// Bounded inputs (docs/security.md, scene/input_limits.h): every refusal is
// one line naming the file and the field or the limit.
namespace {

std::string sceneText(const std::string& camera, const std::string& materials,
                      const std::string& extra) {
  return R"({"format":"penumbra-scene","version":1,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40)" +
         camera + R"(},
    "materials":{"white":{"albedo":[0.5,0.5,0.5])" +
         materials + R"(}},)" + extra + R"(
    "meshes":[{"name":"q","material":"white","quads":[[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]]}]})";
}

std::string withMeshes(const std::string& meshes) {
  return R"({"format":"penumbra-scene","version":1,
    "camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
    "materials":{"white":{"albedo":[0.5,0.5,0.5]}},"meshes":)" +
         meshes + "}";
}

// `text` refused with one line that holds every part of `mentions`.
void requireRefused(const std::string& text, const std::vector<std::string>& mentions,
                    const scene::InputLimits& limits = {}) {
  INFO(text.substr(0, 400));
  try {
    scene::parseScene(text, "t.json", "", {}, limits);
    FAIL("no error");
  } catch (const Error& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find('\n') == std::string::npos);
    CHECK_THAT(message, ContainsSubstring("t.json"));
    for (const auto& m : mentions) CHECK_THAT(message, ContainsSubstring(m));
  }
}

}  // namespace

TEST_CASE("JSON nesting is measured on the raw text, strings and escapes skipped", "[scene]") {
  using penumbra::json_nesting::firstTooDeep;
  CHECK_FALSE(firstTooDeep(R"({"a":[1,{"b":[]}]})", 4));
  CHECK(firstTooDeep(R"({"a":[1,{"b":[]}]})", 3) == 13u);  // the innermost '['
  // Brackets in strings, after an escaped quote and an escaped backslash, do not count.
  CHECK_FALSE(firstTooDeep(R"(["[[[\"[[[", "\\", "{{{"])", 1));
  CHECK(firstTooDeep(R"(["\\"[)", 1) == 5u);
  // Closers never take the depth below zero, so they cannot buy depth later.
  CHECK(firstTooDeep("]]]][[", 1) == 5u);
}

TEST_CASE("scene files nested past the JSON depth limit are refused before parsing", "[scene]") {
  // A million levels in "meshes": the loader's copy of the tree recursed once
  // per level and overflowed the stack.
  const size_t deep = 1'000'000;
  const std::string bomb = R"({"format":"penumbra-scene","version":1,"meshes":)" +
                           std::string(deep, '[') + std::string(deep, ']') + "}";
  requireRefused(bomb, {"JSON nests", "the limit 256", "InputLimits::maxJsonDepth"});
  // The document is level 1: 255 more levels in an ignored key still load.
  const std::string nested = std::string(255, '[') + std::string(255, ']');
  REQUIRE_NOTHROW(scene::parseScene(sceneText("", "", "\"notes\":" + nested + ","), "t.json"));
  requireRefused(sceneText("", "", "\"notes\":[" + nested + "],"), {"InputLimits::maxJsonDepth"});
}

TEST_CASE("scene files: a wrong type or an out-of-range number names the file and the field",
          "[scene]") {
  struct Case {
    std::string text;
    std::vector<std::string> mentions;
  };
  const Case cases[] = {
      {"[1]", {"not a penumbra scene"}},
      {R"({"format":"penumbra-scene","version":"1"})", {"unsupported version"}},
      {sceneText("", R"(,"model":5)", ""),
       {"material 'white'", "\"model\" is not a string (got a number)"}},
      {sceneText("", R"(,"roughness":"x")", ""),
       {"material 'white'", "\"roughness\" is not a number (got a string)"}},
      {sceneText("", R"(,"thin":1)", ""), {"\"thin\" is not true or false"}},
      {sceneText("", "", R"("materials":[1],)"), {"\"materials\" must be an object"}},
      // Past a double: nlohmann's out_of_range, once an "internal error".
      {sceneText("", R"(,"roughness":1e400)", ""), {"invalid JSON", "1e400"}},
      // Past a float: infinity, which the renderer would have summed.
      {sceneText("", R"(,"emission":[1e39,0,0])", ""),
       {"material 'white' emission", "does not fit a float"}},
      {sceneText("", R"(,"metallic":-1e39)", ""), {"\"metallic\"", "does not fit a float"}},
      // A zero forward normalised to NaN, and NaN passed every comparison.
      {R"({"format":"penumbra-scene","version":1,
          "camera":{"position":[0,0,0],"forward":[0,0,0],"up":[0,1,0],"verticalFovDegrees":40},
          "materials":{},"meshes":[]})",
       {"camera.forward", "non-zero direction"}},
      {sceneText(R"(,"apertureBlades":1e300)", "", ""),
       {"camera", "\"apertureBlades\"", "not a whole number in 0..32"}},
      {sceneText(R"(,"verticalFovDegrees":"wide")", "", ""),
       {"camera", "\"verticalFovDegrees\" is not a number"}},
      {sceneText("", "", R"("unitScale":"mm",)"), {"\"unitScale\" is not a number"}},
      {sceneText("", "", R"("unitScale":0,)"), {"\"unitScale\" 0 must be > 0"}},
      {sceneText("", "", R"("lights":[{"type":5}],)"), {"light[0]", "\"type\" is not a string"}},
      {sceneText("", "", R"("lights":[[1]],)"), {"light[0]", "must be an object (got an array)"}},
      {sceneText("", "",
                 R"("lights":[{"type":"point","position":[0,1,0],"intensity":[1e39,1,1]}],)"),
       {"light[0] intensity", "does not fit a float"}},
      {sceneText("", "", R"("environment":{"color":[1,1,1],"rotation":"left"},)"),
       {"environment", "\"rotation\" is not a number"}},
      {sceneText("", "", R"("gltf":[{"file":7}],)"), {"gltf[0]", "\"file\" is not a string"}},
      {withMeshes(
           R"([{"name":"p","material":"white","quads":[[[0,0,0],[1,0,0],["a",1,0],[0,1,0]]]}])"),
       {"mesh 'p' quad 0 vertex 2", "element 0 is not a number (got a string)"}},
      {withMeshes(R"([{"name":3,"material":"white","quads":[]}])"),
       {"meshes[0]", "\"name\" is not a string"}},
      {withMeshes(R"({"name":"p"})"), {"\"meshes\" must be an array"}},
  };
  for (const auto& c : cases) requireRefused(c.text, c.mentions);
}

TEST_CASE("scene files: the material-test row's subdivisions and count are bounded", "[scene]") {
  auto row = [](const std::string& fields) {
    return R"({"format":"penumbra-scene","version":1,
      "camera":{"position":[0,0,-5],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
      "materials":{"base":{"roughness":0.5}},
      "materialTest":{"material":"base","first":[-1,0,0],"last":[1,0,0])" +
           fields + "}}";
  };
  // -1 became 4294967295 subdivisions; 10 and 12 asked for 21 and 335 million
  // triangles a sphere.
  requireRefused(row(R"(,"subdivisions":-1)"),
                 {"materialTest", "\"subdivisions\" -1 is not a whole number in 0..4294967295"});
  for (const char* n : {"10", "12"})
    requireRefused(row(std::string(R"(,"subdivisions":)") + n),
                   {"materialTest \"subdivisions\" " + std::string(n), "the limit 9",
                    "InputLimits::maxSphereSubdivisions"});
  // 64 spheres of 5.2 million triangles: each sphere passes, the row does not.
  requireRefused(row(R"(,"subdivisions":9,"count":64)"),
                 {"materialTest", "triangle count", "InputLimits::maxTriangles"});
  requireRefused(row(R"(,"count":"seven")"), {"materialTest", "\"count\" is not a whole number"});
  requireRefused(row(R"(,"count":65)"),
                 {"materialTest", "\"count\" 65 is not a whole number in 1..64"});
  requireRefused(row(R"(,"vary":1)"), {"materialTest", "\"vary\" is not a string"});

  // Just under the limits: the limit itself loads.
  scene::InputLimits limits;
  limits.maxSphereSubdivisions = 2;
  limits.maxTriangles = 3 * 320;
  const auto s = scene::parseScene(row(R"(,"subdivisions":2,"count":3)"), "t.json", "", {}, limits);
  CHECK(s.triangleCount() == 3u * 320u);
  requireRefused(row(R"(,"subdivisions":3,"count":3)"), {"InputLimits::maxSphereSubdivisions"},
                 limits);
  requireRefused(row(R"(,"subdivisions":2,"count":4)"), {"InputLimits::maxTriangles"}, limits);
}

TEST_CASE("scene files: quads, implicit objects and the file size are bounded", "[scene]") {
  scene::InputLimits limits;
  limits.maxTriangles = 2;  // the one quad
  REQUIRE(scene::parseScene(sceneText("", "", ""), "t.json", "", {}, limits).triangleCount() == 2u);
  limits.maxTriangles = 1;
  requireRefused(sceneText("", "", ""),
                 {"mesh 'q'", "triangle count 2", "InputLimits::maxTriangles"}, limits);
  limits = {};
  const std::string text = sceneText("", "", "");
  limits.maxJsonBytes = text.size();
  REQUIRE_NOTHROW(scene::parseScene(text, "t.json", "", {}, limits));
  limits.maxJsonBytes = text.size() - 1;
  requireRefused(text, {"JSON text size in bytes", "InputLimits::maxJsonBytes"}, limits);
  limits = {};
  limits.maxImplicitObjects = 1;
  const std::string sphere = R"({"kind":"sphere","material":"white","radius":1})";
  REQUIRE(scene::parseScene(sceneText("", "", "\"implicits\":[" + sphere + "],"), "t.json", "", {},
                            limits)
              .implicits.size() == 1u);
  requireRefused(sceneText("", "", "\"implicits\":[" + sphere + "," + sphere + "],"),
                 {"implicit object count 2", "InputLimits::maxImplicitObjects"}, limits);
}

TEST_CASE("environment maps whose header claims more than 16384x8192 are refused undecoded",
          "[scene]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("penumbra-env-{}", ::getpid());
  fs::create_directories(dir);
  // A Radiance header of 16384 x 8193 texels and no texels: stb_image
  // allocated 1.6 GB of floats to fill from nothing.
  std::ofstream(dir / "huge.hdr", std::ios::binary)
      << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8193 +X 16384\n"
      << std::string(64, '\x01');
  // An EXR as the renderer writes them, its data window then widened to
  // 20000 x 2 in the header.
  image::saveExr((dir / "huge.exr").string(), image::Image(3, 2));
  std::string exr;
  {
    std::ifstream in(dir / "huge.exr", std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    exr = bytes.str();
  }
  const std::string attribute("dataWindow\0box2i\0", 17);
  const size_t at = exr.find(attribute);
  REQUIRE(at != std::string::npos);
  const int32_t maxX = 19999;  // the box's third int: max x (little-endian, as the targets)
  std::memcpy(&exr[at + attribute.size() + 4 + 8], &maxX, 4);
  std::ofstream(dir / "huge.exr", std::ios::binary) << exr;
  for (const char* file : {"huge.hdr", "huge.exr"}) {
    INFO(file);
    REQUIRE_THROWS_WITH(
        scene::parseScene(
            sceneText("", "", std::string(R"("environment":{"file":")") + file + "\"},"), "t.json",
            dir.string()),
        ContainsSubstring(file) && ContainsSubstring("its header declares") &&
            ContainsSubstring("more than 16384x8192"));
  }
  fs::remove_all(dir);
}

TEST_CASE("scene files choose a glTF file's animation and time; the caller's choice wins",
          "[gltf]") {
  test::TempFolder folder("scene-animation");
  // A triangle at node 0, moved LINEAR from x = 0 at 0 s to x = 4 at 2 s: at
  // 1 s its corner (1,0,0) is at (3,0,0); at 0.5 s at (2,0,0).
  test::GltfWriter w;
  const int position =
      w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3, R"(,"min":[0,0,0],"max":[1,1,0])");
  const int times = w.floats({0, 2}, "SCALAR", 1);
  const int moves = w.floats({0, 0, 0, 4, 0, 0}, "VEC3", 3);
  w.write(folder, "moving",
          fmt::format(R"(
    "meshes":[{{"primitives":[{{"attributes":{{"POSITION":{}}}}}]}}],
    "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],
    "animations":[{{"name":"Slide","samplers":[{{"input":{},"output":{}}}],
      "channels":[{{"sampler":0,"target":{{"node":0,"path":"translation"}}}}]}}])",
                      position, times, moves));
  auto cornerX = [](const scene::Scene& s) {
    double most = -1e9;
    for (const glm::vec3& p : s.meshes.at(0).positions)
      most = std::max(most, (s.instances.at(0).transform * glm::dvec4(glm::dvec3(p), 1.0)).x);
    return most;
  };
  const std::string text = R"({"format":"penumbra-scene","version":1,
    "gltf":[{"file":"moving.gltf","animation":"Slide","time":1}]})";
  CHECK(cornerX(scene::parseScene(text, "s.json", folder.path(""))) == Catch::Approx(3.0));
  // The caller's choice (the command line's) over the entry's.
  CHECK(cornerX(scene::parseScene(text, "s.json", folder.path(""), {}, {}, {"0", 0.5})) ==
        Catch::Approx(2.0));
  CHECK_THROWS_WITH(scene::parseScene(R"({"format":"penumbra-scene","version":1,
    "gltf":[{"file":"moving.gltf","time":"soon"}]})",
                                      "s.json", folder.path("")),
                    ContainsSubstring("gltf[0]: \"time\" must be a number (seconds)"));
  // A scene with no glTF file has nothing to animate.
  CHECK_THROWS_WITH(scene::loadScene("cornell-box", {}, {}, {"", 1.0}),
                    ContainsSubstring("has no glTF files, so no animations to draw at a time"));
}
