// Every built-in scene renders with both integrators at a small size: finite,
// non-negative, not black, no validation messages.
#include <catch2/catch_test_macros.hpp>

#include "penumbra/scene/scene_loader.h"
#include "render_test_utils.h"

using namespace penumbra;

TEST_CASE("showcase scenes: each built-in scene renders without NaN/Inf", "[render][gpu]") {
  auto device = test::makeTestDevice();
  const auto names = scene::builtInSceneNames();
  REQUIRE(names.size() >= 2u);
  for (const auto& name : names) {
    const auto scene = scene::loadScene(name);
    for (auto integrator : {render::Integrator::Path, render::Integrator::Whitted}) {
      INFO(name << (integrator == render::Integrator::Path ? " path" : " whitted"));
      render::PathTracerSettings settings;
      settings.integrator = integrator;
      const auto img = test::renderScene(*device, scene, 40, 24, 4, settings);
      REQUIRE(image::countNonFinite(img) == 0);
      for (float v : img.rgba) REQUIRE(v >= 0.0f);
      const auto mean = image::meanRgb(img);
      REQUIRE(mean.r + mean.g + mean.b > 0.0);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
