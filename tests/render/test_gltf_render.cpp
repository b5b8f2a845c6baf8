// glTF scenes through the renderer: emissive primitives as area lights,
// interpolated vertex normals, and the guards that keep shading normals from
// leaking light.
#include <algorithm>
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "penumbra/scene/environment.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/scene_loader.h"
#include "render_test_utils.h"
#include "test_data.h"

using namespace penumbra;

namespace {

std::string gltf(const std::string& name) {
  return test::dataPath("gltf/" + name);
}

// Mean of the green channel over the square of side 2r + 1 at the image centre.
double centreMean(const image::Image& img, uint32_t r) {
  double sum = 0;
  uint32_t n = 0;
  for (uint32_t y = img.height / 2 - r; y <= img.height / 2 + r; ++y)
    for (uint32_t x = img.width / 2 - r; x <= img.width / 2 + r; ++x, ++n)
      sum += img.pixel(x, y)[1];
  return sum / n;
}

// Mean squared second difference along rows, L(x-1) - 2 L(x) + L(x+1), in
// the well-lit part of the image (a quarter of the peak or more: away from
// the background, the silhouette and the shadow terminator, where the faceted
// geometry's own shadows show whatever the normals). Flat facets put their
// whole step into one such difference at each edge; smooth shading changes
// its gradient gradually, so its second differences stay small.
double facetEdges(const image::Image& img) {
  float peak = 0.0f;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) peak = std::max(peak, img.pixel(x, y)[1]);
  double sum = 0;
  uint32_t n = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 1; x + 1 < img.width; ++x) {
      const float a = img.pixel(x - 1, y)[1], b = img.pixel(x, y)[1], c = img.pixel(x + 1, y)[1];
      if (std::min({a, b, c}) < 0.25f * peak) continue;
      const double d = double(a) - 2.0 * double(b) + double(c);
      sum += d * d;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

}  // namespace

TEST_CASE("glTF: an emissive quad lights a diffuse floor as the form factor says",
          "[render][gpu][gltf]") {
  auto device = test::makeTestDevice();
  const auto scene = scene::loadGltf(gltf("emissive_quad.gltf"));
  render::PathTracerSettings settings;
  settings.seed = 3;
  const auto img = test::renderScene(*device, scene, 16, 16, 4096, settings);
  REQUIRE(image::countNonFinite(img) == 0);
  // The camera sees the floor (albedo 0.5, Lambertian: specularFactor 0)
  // right under the centre of a 1 m square emitter of radiance 2.5 x 4 = 10,
  // 1 m up. Point-to-parallel-rectangle form factor, four 0.5 m x 0.5 m
  // quadrants at distance 1 (X = Y = 0.5):
  //   F = 4 / (2 pi) [2 X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2))] = 0.2394548,
  // so the floor's radiance is albedo x L_e x F = 0.5 x 10 x 0.2394548 = 1.1973.
  // The emitter is black, so there is no other light.
  const double expected = 0.5 * 10.0 * 0.2394548;
  const double measured = centreMean(img, 2);
  INFO("floor radiance " << measured << ", expected " << expected);
  // 4096 spp over the 5 x 5 centre pixels leave about 0.1 % of noise
  // (measured at 16384 spp: 0.03 % off, the mirrored file 0.08 %; the
  // patch is small enough that the form factor's falloff across it is
  // below that): 0.5 % lets through no light-sampling bias larger than that.
  REQUIRE(measured == Catch::Approx(expected).epsilon(0.005));

  // Mirrored in x by a scene file's transform (the setup is symmetric): the
  // light must still emit downwards, for next-event estimation too.
  const auto mirrored = scene::loadScene(gltf("emissive_mirrored.json"));
  const auto img2 = test::renderScene(*device, mirrored, 16, 16, 4096, settings);
  const double measured2 = centreMean(img2, 2);
  INFO("mirrored: floor radiance " << measured2);
  REQUIRE(measured2 == Catch::Approx(expected).epsilon(0.005));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("glTF: smooth vertex normals shade without facets", "[render][gpu][gltf]") {
  auto device = test::makeTestDevice();
  // The same 12 x 8 UV sphere lit by a point light, with its NORMAL attribute
  // and without (flat normals). Both integrators shade with the vertex normals.
  for (auto integrator : {render::Integrator::Path, render::Integrator::Whitted}) {
    render::PathTracerSettings settings;
    settings.integrator = integrator;
    settings.maxDepth = 1;
    const auto smooth = test::renderScene(*device, scene::loadScene(gltf("sphere_smooth.json")), 64,
                                          64, 4, settings);
    const auto flat =
        test::renderScene(*device, scene::loadScene(gltf("sphere_flat.json")), 64, 64, 4, settings);
    REQUIRE(image::countNonFinite(smooth) == 0);
    const double rs = facetEdges(smooth), rf = facetEdges(flat);
    INFO("integrator " << int(integrator) << ": mean squared second difference smooth " << rs
                       << ", flat " << rf);
    REQUIRE(rf > 0.0);
    REQUIRE(rs < 0.25 * rf);
    // The same light reaches both. Not an analytic check: interpolated
    // normals move light across the sphere, so the means are of two
    // different images and differ by 2.1 % (path) and 1.7 % (Whitted),
    // measured; 5 % catches a light lost or counted twice on either path,
    // while the form-factor test above holds the light's own value to 0.5 %.
    const auto ms = image::meanRgb(smooth), mf = image::meanRgb(flat);
    INFO("mean green: smooth " << ms.g << ", flat " << mf.g);
    REQUIRE(ms.g == Catch::Approx(mf.g).epsilon(0.05));
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("glTF: leaning shading normals leak no light and stay finite", "[render][gpu][gltf]") {
  auto device = test::makeTestDevice();
  // A floor whose vertex normals lean 53 degrees off (one strip above the
  // horizon, one below). A light under the floor must leave its top black;
  // a light above must light it with finite, non-negative radiance.
  for (auto integrator : {render::Integrator::Path, render::Integrator::Whitted}) {
    render::PathTracerSettings settings;
    settings.integrator = integrator;
    const auto below =
        test::renderScene(*device, scene::loadScene(gltf("leak_below.json")), 32, 32, 16, settings);
    const auto above =
        test::renderScene(*device, scene::loadScene(gltf("leak_above.json")), 32, 32, 16, settings);
    REQUIRE(image::countNonFinite(below) == 0);
    REQUIRE(image::countNonFinite(above) == 0);
    for (size_t i = 0; i < below.rgba.size(); i += 4)
      for (int c = 0; c < 3; ++c) {
        REQUIRE(below.rgba[i + size_t(c)] == 0.0f);
        REQUIRE(above.rgba[i + size_t(c)] >= 0.0f);
      }
    REQUIRE(image::meanRgb(above).g > 0.05);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("glTF KHR_materials_unlit: the base colour is what is seen, under any light",
          "[render][gpu][gltf]") {
  auto device = test::makeTestDevice();
  // unlit.gltf: base colour 0.5 times COLOR_0 (0.2, 0.4, 0.8), emission
  // (1, 1, 1) to be ignored, framed by the loader. Under a white
  // environment of radiance 2 a lit surface of that colour would show at
  // least its albedo times 2 plus its reflection; an unlit one shows
  // (0.1, 0.2, 0.4) exactly, and every sample agrees (no noise).
  scene::Scene scene = scene::loadGltf(gltf("unlit.gltf"));
  REQUIRE(scene.materials.at(0).model == scene::MaterialModel::Unlit);
  scene.environment = scene::constantEnvironment(glm::vec3(2.0f));
  const float expected[3] = {0.1f, 0.2f, 0.4f};
  for (const auto integrator : {render::Integrator::Path, render::Integrator::Whitted}) {
    render::PathTracerSettings settings;
    settings.integrator = integrator;
    settings.seed = 5;
    const auto img = test::renderScene(*device, scene, 16, 16, 4, settings);
    REQUIRE(image::countNonFinite(img) == 0);
    const float* centre = img.pixel(8, 8);
    for (int k = 0; k < 3; ++k) {
      INFO("integrator " << int(integrator) << " channel " << k << ": " << centre[k]);
      // float32 products of the colour factors: 1e-6 is rounding, not light.
      CHECK(std::abs(centre[k] - expected[k]) <= 1e-6f);
    }
  }
  // A black unlit surface stays black where a black Lambert one reflects
  // the environment through its specular layer.
  scene.materials.at(0).baseColor = glm::vec3(0.0f);
  render::PathTracerSettings settings;
  settings.seed = 6;
  const auto black = test::renderScene(*device, scene, 16, 16, 4, settings);
  CHECK(black.pixel(8, 8)[0] == 0.0f);
  CHECK(black.pixel(8, 8)[1] == 0.0f);
  CHECK(black.pixel(8, 8)[2] == 0.0f);
}

TEST_CASE("scene files merge glTF files with their transforms and cameras", "[scene][gltf]") {
  const auto s = scene::loadScene(gltf("merged.json"));
  // The floor quad, cameras.gltf's triangle and transforms.gltf's 5 instances.
  REQUIRE(s.instances.size() == 1u + 1u + 5u);
  // No scene camera: the view is cameras.gltf's 'side' (its "camera"),
  // at (5, 0, 0) scaled by 2 and moved by (0, 0, -3): (10, 0, -3).
  REQUIRE(s.camera.position.x == Catch::Approx(10.0f));
  REQUIRE(s.camera.position.z == Catch::Approx(-3.0f));
  REQUIRE(s.camera.forward.x == Catch::Approx(-1.0f));
  REQUIRE(s.cameras.size() == 3u);
  // The orthographic 'ortho' (2 m tall, 2 m up) grows with the file's scale.
  const scene::Camera& ortho = s.cameras[2].camera;
  REQUIRE(ortho.orthographicHeight == Catch::Approx(4.0f));
  REQUIRE(ortho.position.y == Catch::Approx(4.0));
  REQUIRE(ortho.forward.y == Catch::Approx(-1.0f));
  // transforms.gltf moved up by 100 (column-major matrix): its 'child'
  // instance's vertex (1,0,0) lands at (10, 2, 2) + (0, 100, 0).
  const auto& child = s.instances[2];
  const glm::vec3 p =
      glm::vec3(child.transform * glm::vec4(s.meshes[child.mesh].positions[1], 1.0f));
  REQUIRE(p.x == Catch::Approx(10.0f));
  REQUIRE(p.y == Catch::Approx(102.0f));
  REQUIRE(p.z == Catch::Approx(2.0f));
  // Materials keep their own indices after the merge.
  REQUIRE(s.materials[s.meshes[0].material].name == "white");
}
