#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>

#include "scene/mesh_builders.h"
#include "scene/scene_loader.h"
#include "test_data.h"
#include "util/error.h"

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
}
