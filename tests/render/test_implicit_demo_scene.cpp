// The built-in implicit-surfaces scene (every implicit kind, glass, metal,
// an area light) renders with both integrators.
#include <catch2/catch_test_macros.hpp>

#include "penumbra/scene/scene_loader.h"
#include "render_test_utils.h"

using namespace penumbra;

TEST_CASE("the implicit-surfaces scene renders finite, non-negative images with both integrators",
          "[render][gpu][implicit]") {
  auto device = test::makeTestDevice();
  const auto s = scene::loadScene("implicit-surfaces");
  render::PathTracer tracer(*device, s, 48, 32);
  for (auto integrator : {render::Integrator::Path, render::Integrator::Whitted}) {
    INFO((integrator == render::Integrator::Path ? "path" : "Whitted"));
    render::PathTracerSettings settings;
    settings.integrator = integrator;
    tracer.resetAccumulation();
    tracer.renderFrame(settings, 4);
    const image::Image img = tracer.readback();
    REQUIRE(image::countNonFinite(img) == 0);
    float darkest = 0.0f;
    for (float v : img.rgba) darkest = std::min(darkest, v);
    REQUIRE(darkest >= 0.0f);
    // The room is lit (measured means 0.05-0.2 per channel): a black image
    // would mean nothing was hit or lit.
    const auto mean = image::meanRgb(img);
    INFO("mean " << mean.r << " " << mean.g << " " << mean.b);
    REQUIRE(mean.r > 0.01);
    REQUIRE(mean.g > 0.01);
    REQUIRE(mean.b > 0.01);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
