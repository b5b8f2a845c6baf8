// The "implicits" array of scene files (engine/penumbra/scene/implicit_json.cpp) and
// validation of implicit objects (engine/penumbra/scene/implicit_object.cpp).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>

#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using Catch::Approx;
using Catch::Matchers::ContainsSubstring;
namespace shapes = scene::implicit;

namespace {

// A scene file with one material "m" and the given implicits array.
std::string withImplicits(const std::string& implicits, const std::string& extra = "") {
  return R"({"format":"penumbra-scene","version":1,)" + extra +
         R"("camera":{"position":[0,0,0],"forward":[0,0,1],"up":[0,1,0],"verticalFovDegrees":40},
    "materials":{"m":{"albedo":[0.5,0.5,0.5]}, "glow":{"emission":[2,2,2]}},
    "implicits":)" +
         implicits + "}";
}

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}

void requireNear(glm::vec3 a, glm::vec3 b) {
  INFO("(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z
           << ")");
  // Degrees to radians and back through sin/cos in float: 1e-6 relative.
  REQUIRE(glm::length(a - b) <= 1e-5f * std::max(1.0f, glm::length(b)));
}

}  // namespace

TEST_CASE("scene files: implicit objects of every kind, with transforms", "[scene][implicit]") {
  const auto s = scene::parseScene(withImplicits(R"([
    {"name":"ball","kind":"sphere","material":"m","radius":0.5,
     "transform":{"translate":[1,2,3],"rotate":{"axis":[0,0,2],"degrees":90},"scale":2}},
    {"kind":"plane","material":"m"},
    {"name":"panel","kind":"plane","material":"glow","halfExtents":[1,2]},
    {"name":"crate","kind":"box","material":"m","halfExtents":[1,2,3],
     "transform":{"scale":[1,2,3]}},
    {"name":"ring","kind":"torus","material":"m","majorRadius":1,"minorRadius":0.25,
     "maxSteps":64,"tolerance":1e-3},
    {"name":"pillar","kind":"roundedBox","material":"m","halfExtents":[0.5,1,0.5],
     "cornerRadius":0.1},
    {"name":"drop","kind":"blend","material":"m","blendRadius":0.2,"primitives":[
      {"kind":"sphere","radius":0.3,"offset":[-0.2,0,0]},
      {"kind":"torus","majorRadius":0.3,"minorRadius":0.1},
      {"kind":"box","halfExtents":[0.1,0.1,0.1],"offset":[0,1,0]}]},
    {"name":"bulb","kind":"mandelbulb","material":"m"}])",
                                                 R"("unitScale":0.5,)"),
                                   "t.json");
  REQUIRE(s.meshes.empty());
  REQUIRE(s.implicits.size() == 8);
  using K = scene::ImplicitKind;
  const K kinds[] = {K::Sphere, K::Plane,      K::Plane, K::Box,
                     K::Torus,  K::RoundedBox, K::Blend, K::Mandelbulb};
  for (size_t i = 0; i < 8; ++i) REQUIRE(s.implicits[i].kind() == kinds[i]);

  const auto& ball = s.implicits[0];
  REQUIRE(ball.name == "ball");
  REQUIRE(std::get<shapes::Sphere>(ball.shape).radius == 0.5f);
  // unitScale * translate * rotate * scale: object (1, 0, 0) -> scale 2 ->
  // rotate 90 degrees about z -> (0, 2, 0) -> + (1, 2, 3) -> times 0.5.
  requireNear(apply(ball.transform, {1, 0, 0}), {0.5f, 2.0f, 1.5f});
  requireNear(apply(ball.transform, {0, 0, 0}), {0.5f, 1.0f, 1.5f});

  REQUIRE(s.implicits[1].name == "plane1");  // unnamed: kind and index
  REQUIRE_FALSE(std::get<shapes::Plane>(s.implicits[1].shape).halfExtents.has_value());
  REQUIRE(*std::get<shapes::Plane>(s.implicits[2].shape).halfExtents == glm::vec2(1, 2));
  REQUIRE(s.materials[s.implicits[2].material].name == "glow");
  // Non-uniform scale is allowed on analytic kinds.
  requireNear(apply(s.implicits[3].transform, {1, 1, 1}), {0.5f, 1.0f, 1.5f});

  const auto& ring = s.implicits[4];
  REQUIRE(ring.sphereTracing.maxSteps == 64u);
  REQUIRE(ring.sphereTracing.tolerance == Approx(1e-3f));
  REQUIRE(std::get<shapes::Torus>(ring.shape).minorRadius == 0.25f);
  const scene::SphereTracing defaults;
  REQUIRE(s.implicits[5].sphereTracing.maxSteps == defaults.maxSteps);
  REQUIRE(std::get<shapes::RoundedBox>(s.implicits[5].shape).cornerRadius == Approx(0.1f));

  const auto& drop = std::get<shapes::Blend>(s.implicits[6].shape);
  REQUIRE(drop.blendRadius == Approx(0.2f));
  REQUIRE(drop.primitives.size() == 3);
  REQUIRE(std::holds_alternative<shapes::Sphere>(drop.primitives[0].shape));
  REQUIRE(drop.primitives[0].offset == glm::vec3(-0.2f, 0, 0));
  REQUIRE(std::holds_alternative<shapes::Torus>(drop.primitives[1].shape));
  REQUIRE(drop.primitives[1].offset == glm::vec3(0));
  REQUIRE(std::get<shapes::Box>(drop.primitives[2].shape).halfExtents == glm::vec3(0.1f));

  const auto& bulb = std::get<shapes::Mandelbulb>(s.implicits[7].shape);
  REQUIRE(bulb.power == 8.0f);
  REQUIRE(bulb.iterations == shapes::Mandelbulb{}.iterations);
}

TEST_CASE("scene files: bad implicit objects give one clear error naming them",
          "[scene][implicit]") {
  struct Case {
    const char* implicit;
    std::vector<const char*> mentions;
  };
  const Case cases[] = {
      {R"({"name":"a","kind":"cone","material":"m"})", {"implicit 'a'", "unknown kind 'cone'"}},
      {R"({"name":"a","kind":"sphere","material":"m","radious":1})",
       {"implicit 'a'", "unknown key \"radious\"", "radius"}},
      {R"({"name":"a","kind":"sphere","material":"m"})", {"implicit 'a'", "missing \"radius\""}},
      {R"({"name":"a","kind":"sphere","material":"m","radius":-1})",
       {"implicit 'a' (sphere)", "radius must be positive", "-1"}},
      {R"({"name":"a","kind":"sphere","material":"m","radius":1e39})",
       {"implicit 'a' (sphere)", "radius must be positive", "inf"}},
      {R"({"name":"a","kind":"sphere","material":"m","radius":"big"})",
       {"implicit 'a'", "\"radius\" is not a number"}},
      {R"({"name":"a","kind":"sphere","material":"blue","radius":1})",
       {"implicit 'a'", "unknown material 'blue'"}},
      {R"({"name":"a","kind":"plane","material":"m","halfExtents":[0,1]})",
       {"implicit 'a' (plane)", "halfExtents must be positive"}},
      {R"({"name":"a","kind":"box","material":"m","halfExtents":[1,1]})",
       {"implicit 'a'", "halfExtents", "3 numbers"}},
      {R"({"name":"a","kind":"torus","material":"m","majorRadius":1,"minorRadius":0})",
       {"implicit 'a' (torus)", "minorRadius must be positive"}},
      {R"({"name":"a","kind":"torus","material":"m","majorRadius":1,"minorRadius":0.2,
           "transform":{"scale":[1,2,1]}})",
       {"implicit 'a' (torus)", "non-uniform scale"}},
      {R"({"name":"a","kind":"torus","material":"m","majorRadius":1,"minorRadius":0.2,
           "maxSteps":0})",
       {"implicit 'a'", "maxSteps", "1..1000000"}},
      {R"({"name":"a","kind":"torus","material":"m","majorRadius":1,"minorRadius":0.2,
           "tolerance":-1e-4})",
       {"implicit 'a' (torus)", "tolerance must be positive"}},
      {R"({"name":"a","kind":"sphere","material":"m","radius":1,"maxSteps":10})",
       {"implicit 'a'", "unknown key \"maxSteps\""}},
      {R"({"name":"a","kind":"roundedBox","material":"m","halfExtents":[1,0.2,1],
           "cornerRadius":0.3})",
       {"implicit 'a' (roundedBox)", "cornerRadius must lie in [0, 0.2]"}},
      {R"({"name":"a","kind":"blend","material":"m","blendRadius":0.1,
           "primitives":[{"kind":"sphere","radius":1}]})",
       {"implicit 'a' (blend)", "2 to 4 primitives, got 1"}},
      {R"({"name":"a","kind":"blend","material":"m","blendRadius":0.1,
           "primitives":[{"kind":"sphere","radius":1},{"kind":"plane"}]})",
       {"implicit 'a' primitive 1", "'plane' cannot be blended"}},
      {R"({"name":"a","kind":"blend","material":"m","blendRadius":0.1,
           "primitives":[{"kind":"sphere","radius":1},{"kind":"sphere","radius":-2}]})",
       {"implicit 'a' (blend) primitive 1", "radius must be positive"}},
      {R"({"name":"a","kind":"mandelbulb","material":"m","power":1})",
       {"implicit 'a' (mandelbulb)", "power must lie in [2, 32]"}},
      {R"({"name":"a","kind":"sphere","material":"m","radius":1,
           "transform":{"rotate":{"axis":[0,0,0],"degrees":10}}})",
       {"implicit 'a' transform rotate", "axis must be non-zero"}},
      {R"({"name":"a","kind":"sphere","material":"m","radius":1,"transform":{"scale":0}})",
       {"implicit 'a' (sphere)", "not invertible"}},
  };
  for (const auto& c : cases) {
    INFO(c.implicit);
    try {
      scene::parseScene(withImplicits(std::string("[") + c.implicit + "]"), "t.json");
      FAIL("no error");
    } catch (const Error& e) {
      const std::string message = e.what();
      INFO(message);
      CHECK(message.find('\n') == std::string::npos);
      for (const char* m : c.mentions) CHECK_THAT(message, ContainsSubstring(m));
    }
  }
  REQUIRE_THROWS_WITH(scene::parseScene(withImplicits(R"({"kind":"sphere"})"), "t.json"),
                      ContainsSubstring("\"implicits\" must be an array"));
  REQUIRE_THROWS_WITH(scene::parseScene(withImplicits("[]"), "t.json"),
                      ContainsSubstring("has no geometry"));
}

TEST_CASE("scene validation: SDF kinds take rotation, translation and uniform scale only",
          "[scene][implicit]") {
  // Scenes built in code skip the loader; validate() holds them to the same rules.
  scene::Scene s;
  s.name = "code";
  s.materials.push_back(scene::Material::lambert("m", glm::vec3(0.5f)));
  scene::ImplicitObject torus;
  torus.name = "ring";
  torus.shape = shapes::Torus{1.0f, 0.25f};
  torus.transform =
      glm::scale(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(1, 2, 3)), glm::vec3(3.0f));
  s.implicits = {torus};
  REQUIRE_NOTHROW(scene::validate(s));
  s.implicits[0].transform[1][0] = 0.5f;  // shear
  REQUIRE_THROWS_WITH(scene::validate(s), ContainsSubstring("scene 'code': implicit 'ring'") &&
                                              ContainsSubstring("non-uniform scale"));
  s.implicits[0].transform = glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, 2));
  REQUIRE_THROWS_WITH(scene::validate(s), ContainsSubstring("non-uniform scale"));
  s.implicits[0].shape = shapes::Sphere{1.0f};  // analytic: an ellipsoid is fine
  REQUIRE_NOTHROW(scene::validate(s));
  s.implicits[0].material = 3;
  REQUIRE_THROWS_WITH(scene::validate(s), ContainsSubstring("uses material 3 of 1"));
}

TEST_CASE("the implicit-surfaces scene has every implicit kind and an area light",
          "[scene][implicit]") {
  const auto s = scene::loadScene("implicit-surfaces");
  std::set<scene::ImplicitKind> kinds;
  for (const auto& o : s.implicits) kinds.insert(o.kind());
  REQUIRE(kinds.size() == 7);
  bool areaLight = false;
  for (const auto& m : s.meshes) areaLight = areaLight || s.materials[m.material].isEmissive();
  REQUIRE(areaLight);
}
