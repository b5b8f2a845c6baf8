// The material-test row (engine/penumbra/scene/material_row.h).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "penumbra/scene/material_row.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using Catch::Approx;
using Catch::Matchers::ContainsSubstring;

namespace {
const scene::Material& sphereMaterial(const scene::Scene& s, size_t i) {
  return s.materials[s.materialRow->materials[i]];
}
}  // namespace

TEST_CASE("material-test: seven spheres differ in one parameter from 0 to 1", "[scene]") {
  const auto s = scene::loadScene("material-test");
  REQUIRE(s.materialRow.has_value());
  REQUIRE(s.materialRow->vary == "roughness");
  REQUIRE(s.materialRow->materials.size() == 7u);
  for (size_t i = 0; i < 7; ++i) {
    const auto& m = sphereMaterial(s, i);
    REQUIRE(m.roughness == Approx(float(i) / 6.0f));
    // Everything else is the base material's.
    REQUIRE(m.baseColor == s.materialRow->base.baseColor);
    REQUIRE(m.metallic == s.materialRow->base.metallic);
    REQUIRE(m.specular == s.materialRow->base.specular);
  }
  // Each sphere is its own instance, ordered along the row: left to right on screen.
  std::vector<float> screenX;
  const auto& cam = s.camera;
  const glm::vec3 right = glm::normalize(glm::cross(cam.forward, cam.up));
  for (const auto& inst : s.instances) {
    const auto& mesh = s.meshes[inst.mesh];
    if (mesh.name.rfind("material row sphere", 0) == 0)
      screenX.push_back(glm::dot(glm::vec3(inst.transform[3]) - glm::vec3(cam.position), right));
  }
  REQUIRE(screenX.size() == 7u);
  for (size_t i = 1; i < screenX.size(); ++i) REQUIRE(screenX[i] > screenX[i - 1]);
}

TEST_CASE("material-test: --vary and --set change the row", "[scene]") {
  auto s = scene::loadScene("material-test");
  scene::changeMaterialRow(s, "metallic", "roughness=0.25,baseColor=0.9,0.6,0.2,clearcoat=1");
  for (size_t i = 0; i < 7; ++i) {
    const auto& m = sphereMaterial(s, i);
    REQUIRE(m.metallic == Approx(float(i) / 6.0f));
    REQUIRE(m.roughness == 0.25f);
    REQUIRE(m.clearcoat == 1.0f);
    REQUIRE(m.baseColor == glm::vec3(0.9f, 0.6f, 0.2f));
  }
  // --set alone keeps the varied parameter.
  scene::changeMaterialRow(s, "", "specTrans=1");
  REQUIRE(s.materialRow->vary == "metallic");
  REQUIRE(sphereMaterial(s, 6).metallic == 1.0f);
  REQUIRE(sphereMaterial(s, 3).specTrans == 1.0f);
  // glTF's anisotropy, not a 0..1 row parameter for the rotation, is set too.
  scene::changeMaterialRow(s, "", "anisotropyStrength=0.7,anisotropyRotation=1.25");
  REQUIRE(sphereMaterial(s, 2).anisotropyStrength == 0.7f);
  REQUIRE(sphereMaterial(s, 2).anisotropyRotation == 1.25f);
  // The dielectric F0's colour, unbounded above (F0 clamps at 1).
  scene::changeMaterialRow(s, "", "specularColor=12.5,3,0.2");
  REQUIRE(sphereMaterial(s, 4).specularColor == glm::vec3(12.5f, 3.0f, 0.2f));
}

TEST_CASE("material-test: bad --vary and --set are clear errors", "[scene]") {
  auto s = scene::loadScene("material-test");
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "colour", ""),
                      ContainsSubstring("--vary 'colour'"));
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "", "gloss=1"),
                      ContainsSubstring("unknown material parameter 'gloss'"));
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "", "metallic=abc"), ContainsSubstring("'abc'"));
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "", "baseColor=1,2"),
                      ContainsSubstring("needs 3 numbers"));
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "", "specularColor=1,2"),
                      ContainsSubstring("--set specularColor: needs 3 numbers"));
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "", "metallic=1,2"),
                      ContainsSubstring("needs 1 number"));
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(s, "", "0.5"),
                      ContainsSubstring("expected name=value"));
  auto cornell = scene::loadScene("cornell-box");
  REQUIRE_THROWS_WITH(scene::changeMaterialRow(cornell, "roughness", ""),
                      ContainsSubstring("has no material-test row"));
}
