// Whitted ray tracing (--integrator whitted) on small mirror and glass scenes
// built in code: the host follows each pixel's ray by reflection about the
// normal, Snell refraction and total internal reflection (ray_geometry.h) to
// the coloured surface it must end on, and the rendered pixel must read that
// surface's colour and not another's. A ray-level check, not a picture.
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <sstream>
#include <string>

#include "penumbra/scene/mesh_builders.h"
#include "ray_geometry.h"
#include "render_test_utils.h"

using namespace penumbra;

namespace {
constexpr uint32_t kSize = 48;
// Far deeper than any main path below (the longest, in the cube, enters,
// is totally reflected twice, leaves and hits a wall: 5 hits); Whitted
// shades the hit at depth <= maxDepth.
constexpr uint32_t kMaxDepth = 12;
// Pixels whose main path keeps less than this share of the weight (near the
// critical angle, Fresnel sends most of it elsewhere) say little; skip them.
constexpr float kMinMainWeight = 0.5f;

const glm::vec3 kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1);

scene::Material phong(const char* name, glm::vec3 kd) {
  scene::Material m;
  m.name = name;
  m.model = scene::MaterialModel::Phong;
  m.baseColor = kd;
  m.ks = 0.0f;
  return m;
}
scene::Material mirror() {
  auto m = phong("mirror", glm::vec3(0.0f));
  m.reflectivity = 1.0f;
  return m;
}
scene::Material glass(float ior) {
  auto m = phong("glass", glm::vec3(1.0f));  // kd tints refraction: untinted
  m.transparency = 1.0f;
  m.ior = ior;
  return m;
}

uint32_t addMaterial(scene::Scene& s, const scene::Material& m) {
  s.materials.push_back(m);
  return uint32_t(s.materials.size() - 1);
}
void addMesh(scene::Scene& s, scene::Mesh mesh, const glm::mat4& transform = glm::mat4(1.0f)) {
  s.instances.push_back({uint32_t(s.meshes.size()), transform});
  s.meshes.push_back(std::move(mesh));
}
// A wall in the plane through `origin` spanned by u, v, facing cross(u, v).
void addWall(scene::Scene& s, glm::vec3 origin, glm::vec3 u, glm::vec3 v, uint32_t material) {
  addMesh(s, scene::makeQuad(origin, u, v, material));
}

scene::Scene emptyScene(const char* name, float fovDegrees) {
  scene::Scene s;
  s.name = name;
  s.camera.position = glm::vec3(0.0f);
  s.camera.forward = glm::vec3(0, 0, 1);
  s.camera.up = glm::vec3(0, 1, 0);  // image right is world -x
  s.camera.verticalFovDegrees = fovDegrees;
  return s;
}

test::SurfaceKind kindOf(const scene::Scene& s, uint32_t material) {
  const auto& m = s.materials[material];
  if (m.transparency > 0.0f) return test::SurfaceKind::Glass;
  if (m.reflectivity > 0.0f) return test::SurfaceKind::Mirror;
  return test::SurfaceKind::Opaque;
}

test::MainPath mainPath(const scene::Scene& s, const std::vector<test::WorldTriangle>& tris,
                        glm::vec2 film) {
  const glm::vec3 d = test::cameraRayDirection(s.camera, kSize, kSize, film);
  return test::traceMainPath(
      tris, s.camera.position, d, [&](uint32_t m) { return kindOf(s, m); },
      [&](uint32_t m) { return s.materials[m].ior; }, kMaxDepth + 1);
}

// Radiance Whitted's Phong model gives the opaque surface a main path ends
// on: kd (ambient + sum of n.l I / d^2 over unshadowed point lights), ks = 0;
// `lit` counts the lights it sees, so pixels straddling a shadow edge can be
// told apart.
struct Leaf {
  glm::vec3 radiance{0.0f};
  uint32_t lit = 0;
};
Leaf leafRadiance(const scene::Scene& s, const std::vector<test::WorldTriangle>& tris,
                  const test::MainPath& p) {
  Leaf leaf;
  if (p.material == test::MainPath::kNothing) return leaf;
  const glm::vec3 kd = s.materials[p.material].baseColor;
  // Shaded on the side the ray arrives from.
  const glm::vec3 n = glm::dot(p.normal, p.direction) < 0.0f ? p.normal : -p.normal;
  glm::vec3 light = s.ambient;
  for (const auto& l : s.pointLights) {
    const glm::vec3 toLight = glm::vec3(l.position) - p.position;
    const float distance = glm::length(toLight);
    const float cosine = glm::dot(n, toLight / distance);
    if (cosine <= 0.0f) continue;
    const auto blocker = test::intersect(tris, p.position, toLight / distance);
    if (blocker && blocker->t < distance) continue;
    leaf.lit += 1;
    light += l.intensity * (cosine / (distance * distance));
  }
  leaf.radiance = kd * light;
  return leaf;
}

// What one test learns from the pixels it could predict.
struct PixelCheck {
  uint32_t checked = 0;
  std::map<std::string, uint32_t> counts;  // checked pixels by label
  std::vector<std::string> failures;
  uint32_t count(const std::string& label) const {
    auto it = counts.find(label);
    return it == counts.end() ? 0 : it->second;
  }
};

// For every pixel whose whole footprint follows one main path (same route,
// same surface, same events) keeping at least kMinMainWeight of the weight:
// the pixel's channel c must lie in [wMin L_lo, wMax L_hi + (1 - wMin) maxLeaf],
// where L is the end surface's radiance over the footprint and the second
// term bounds what the Fresnel branches left by the main path can add (their
// weights sum to at most 1 - w and no surface is brighter than maxLeaf). So a
// red end surface must read red, and green and blue stay below 1 - w.
template <class Label>
PixelCheck checkPixels(const image::Image& img, const scene::Scene& s, float maxLeaf, Label label) {
  const auto tris = test::worldTriangles(s);
  PixelCheck check;
  for (uint32_t y = 0; y < kSize; ++y) {
    for (uint32_t x = 0; x < kSize; ++x) {
      bool consistent = true;
      float wMin = 1.0f, wMax = 0.0f;
      glm::vec3 lo(1e30f), hi(-1e30f);
      const auto footprint = test::pixelFootprint(x, y);
      test::MainPath first;
      Leaf firstLeaf;
      for (size_t i = 0; i < footprint.size(); ++i) {
        const auto p = mainPath(s, tris, footprint[i]);
        const auto leaf = leafRadiance(s, tris, p);
        if (i == 0) {
          first = p;
          firstLeaf = leaf;
        } else if (p.route != first.route || p.material != first.material ||
                   p.internalReflections != first.internalReflections ||
                   leaf.lit != firstLeaf.lit) {
          consistent = false;
        }
        wMin = std::min(wMin, p.weight);
        wMax = std::max(wMax, p.weight);
        lo = glm::min(lo, leaf.radiance);
        hi = glm::max(hi, leaf.radiance);
      }
      if (!consistent || wMin < kMinMainWeight) continue;
      check.checked += 1;
      check.counts[label(first, x, y)] += 1;
      const float* px = img.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        // 1e-4 absolute and 1e-3 relative: float rounding of a few bounces,
        // and the 3 x 3 footprint grid missing the exact extremes of a
        // smooth 1/d^2 falloff across one pixel.
        const float low = wMin * lo[c] * (1.0f - 1e-3f) - 1e-4f;
        const float high = wMax * hi[c] * (1.0f + 1e-3f) + (1.0f - wMin) * maxLeaf + 1e-4f;
        if (px[c] < low || px[c] > high) {
          std::ostringstream os;
          os << "pixel (" << x << ", " << y << ") channel " << c << " = " << px[c]
             << ", expected in [" << low << ", " << high << "] (" << label(first, x, y)
             << ", main-path weight " << wMin << ")";
          check.failures.push_back(os.str());
        }
      }
    }
  }
  return check;
}

void requireNoFailures(const PixelCheck& check) {
  std::ostringstream counts;
  for (const auto& [label, n] : check.counts) counts << label << ": " << n << "; ";
  INFO(check.checked << " pixels checked: " << counts.str());
  std::string first = check.failures.empty() ? "" : check.failures.front();
  INFO(check.failures.size() << " failing channels; first: " << first);
  REQUIRE(check.failures.empty());
}

std::string colourName(const scene::Scene& s, uint32_t material) {
  return material == test::MainPath::kNothing ? "nothing" : s.materials[material].name;
}

render::PathTracerSettings whittedSettings() {
  render::PathTracerSettings settings;
  settings.integrator = render::Integrator::Whitted;
  settings.maxDepth = kMaxDepth;
  return settings;
}
}  // namespace

TEST_CASE("whitted: a mirror shows the wall it faces, lit as the Phong model says",
          "[render][gpu][whitted]") {
  // A square mirror at z = 3 turned 45 degrees to face the camera and +x, a
  // side wall at x = 1.6 (red for z < 3, green beyond) that the camera sees
  // in the mirror (and, for its far green end, directly at the image's left
  // edge), a blue back wall beside and behind the mirror. The
  // ray through the mirror's centre reflects to +x and meets the wall on the
  // red/green seam, so the mirror's image splits where reflection about the
  // normal puts it. A point light makes the wall's value depend on where the
  // reflected ray lands (n.l / d^2), not just on which wall it is.
  auto s = emptyScene("whitted mirror", 40.0f);
  s.ambient = glm::vec3(0.1f);
  s.pointLights.push_back({scene::LightType::Point, glm::vec3(0.2f, 1.2f, 1.5f), glm::vec3(3.0f)});
  const uint32_t mirrorMaterial = addMaterial(s, mirror());
  const uint32_t red = addMaterial(s, phong("red", kRed));
  const uint32_t green = addMaterial(s, phong("green", kGreen));
  const uint32_t blue = addMaterial(s, phong("blue", kBlue));
  const glm::vec3 centre(0, 0, 3), along = glm::normalize(glm::vec3(1, 0, 1)), up(0, 1, 0);
  addMesh(s, scene::makeQuad(centre - 0.8f * along - 0.8f * up, 1.6f * up, 1.6f * along,
                             mirrorMaterial));
  addWall(s, {1.6f, -3, 0}, {0, 0, 3}, {0, 6, 0}, red);
  addWall(s, {1.6f, -3, 3}, {0, 0, 3}, {0, 6, 0}, green);
  addWall(s, {-3, -3, 6}, {0, 6, 0}, {4.6f, 0, 0}, blue);
  scene::validate(s);

  auto device = test::makeTestDevice();
  const auto img = test::renderScene(*device, s, kSize, kSize, 1, whittedSettings());
  REQUIRE(image::countNonFinite(img) == 0);
  // With reflectivity 1 the main path is the whole of the ray's weight, so
  // there is no residual: the pixel equals the lit wall (maxLeaf 0).
  const auto check = checkPixels(img, s, 0.0f, [&](const test::MainPath& p, uint32_t, uint32_t) {
    return colourName(s, p.material) + (p.reflections ? " in the mirror" : " directly");
  });
  requireNoFailures(check);
  // The check means something only if the mirror's image covers both walls
  // (counts when written, of 2304 pixels: 568 red and 278 green in the
  // mirror, 931 blue and 288 green seen directly).
  REQUIRE(check.count("red in the mirror") >= 300);
  REQUIRE(check.count("green in the mirror") >= 150);
  REQUIRE(check.count("blue directly") >= 500);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("whitted: a tilted glass slab shifts the wall behind it by Snell's law",
          "[render][gpu][whitted]") {
  // A 0.8 thick glass slab turned 60 degrees about y in front of a wall that
  // is red for x > 0 and green for x < 0. Refraction displaces the seen
  // seam sideways by t sin(i - r) / cos r = 0.41 (i = 60, r = 35.3 degrees),
  // about 8 pixels here, so a band of pixels whose straight line meets one
  // colour must read the other. Without point lights every surface reads
  // ambient x kd <= 1, the bound on what Fresnel's reflections can add.
  auto s = emptyScene("whitted slab", 30.0f);
  s.ambient = glm::vec3(1.0f);
  const uint32_t glassMaterial = addMaterial(s, glass(1.5f));
  const uint32_t red = addMaterial(s, phong("red", kRed));
  const uint32_t green = addMaterial(s, phong("green", kGreen));
  const glm::mat4 slab = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 2.5f}),
                                     glm::radians(60.0f), glm::vec3(0, 1, 0));
  addMesh(s, scene::makeBox({-2, -2, -0.4f}, {2, 2, 0.4f}, false, glassMaterial), slab);
  addWall(s, {0, -5, 4.5f}, {0, 10, 0}, {5, 0, 0}, red);
  addWall(s, {-5, -5, 4.5f}, {0, 10, 0}, {5, 0, 0}, green);
  scene::validate(s);

  auto device = test::makeTestDevice();
  const auto img = test::renderScene(*device, s, kSize, kSize, 1, whittedSettings());
  REQUIRE(image::countNonFinite(img) == 0);
  const auto check =
      checkPixels(img, s, 1.0f, [&](const test::MainPath& p, uint32_t x, uint32_t y) {
        // Where the unbent camera ray would meet the wall plane z = 4.5.
        const glm::vec3 d = test::cameraRayDirection(s.camera, kSize, kSize, {x + 0.5f, y + 0.5f});
        const bool straightRed = d.x * (4.5f / d.z) > 0.0f;
        const bool refractedRed = p.material == red;
        return colourName(s, p.material) +
               (p.refractions == 2 ? " through the slab" : " otherwise") +
               (straightRed != refractedRed ? ", shifted" : "");
      });
  requireNoFailures(check);
  // Counts when written, of 2304 pixels: 1152 red and 672 green through the
  // slab where the straight line meets the same colour, and 432 red where
  // it meets green.
  REQUIRE(check.count("red through the slab") >= 600);
  REQUIRE(check.count("green through the slab") >= 350);
  REQUIRE(check.count("red through the slab, shifted") >= 200);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("whitted: total internal reflection in a glass cube turns rays to the side walls",
          "[render][gpu][whitted]") {
  // A glass cube turned 45 degrees about y. A camera ray enters a front face
  // at ~45 degrees and refracts to ~28 degrees from its normal, so it meets
  // the adjacent back face at ~62 degrees, beyond the critical angle
  // asin(1/1.5) = 41.8 degrees: it is totally reflected and leaves through the
  // opposite face travelling sideways, onto the red (x = +2) or green (x = -2)
  // wall. Rays that reach the parallel back face leave straight on to the
  // blue back wall. The side walls are outside the field of view, so any red
  // or green the main path predicts arrives by total internal reflection.
  auto s = emptyScene("whitted TIR", 30.0f);
  s.ambient = glm::vec3(1.0f);
  const uint32_t glassMaterial = addMaterial(s, glass(1.5f));
  const uint32_t red = addMaterial(s, phong("red", kRed));
  const uint32_t green = addMaterial(s, phong("green", kGreen));
  const uint32_t blue = addMaterial(s, phong("blue", kBlue));
  const glm::mat4 cube = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 3}),
                                     glm::radians(45.0f), glm::vec3(0, 1, 0));
  addMesh(s, scene::makeBox(glm::vec3(-0.6f), glm::vec3(0.6f), false, glassMaterial), cube);
  addWall(s, {2, -3, -1}, {0, 0, 8}, {0, 6, 0}, red);     // faces -x
  addWall(s, {-2, -3, -1}, {0, 6, 0}, {0, 0, 8}, green);  // faces +x
  addWall(s, {-2, -3, 7}, {0, 6, 0}, {4, 0, 0}, blue);
  scene::validate(s);

  auto device = test::makeTestDevice();
  const auto img = test::renderScene(*device, s, kSize, kSize, 1, whittedSettings());
  REQUIRE(image::countNonFinite(img) == 0);
  const auto check = checkPixels(img, s, 1.0f, [&](const test::MainPath& p, uint32_t, uint32_t) {
    return colourName(s, p.material) + (p.internalReflections ? " after TIR" : " without TIR");
  });
  requireNoFailures(check);
  // Counts when written, of 2304 pixels: 436 red and 436 green after TIR,
  // 900 blue without and 236 blue after (twice) TIR; no red or green
  // without TIR, as the scene intends.
  REQUIRE(check.count("red after TIR") >= 250);
  REQUIRE(check.count("green after TIR") >= 250);
  REQUIRE(check.count("blue without TIR") >= 500);
  REQUIRE(check.count("red without TIR") == 0);
  REQUIRE(check.count("green without TIR") == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("whitted: glass splits light between reflection and refraction by Fresnel",
          "[render][gpu][whitted]") {
  // The slab of the refraction case in front of a white wall (ambient 1, so
  // the wall reads 1) narrow enough that the front face's reflection, and
  // the internal reflections leaving through the front face parallel to it,
  // miss it. A pixel then reads the sum of the transmitted branches: at least
  // the main path's (1 - R1)(1 - R2), at most the whole series
  // (1 - R1)(1 - R2) / (1 - R2^2), with R1, R2 the air-to-glass and
  // glass-to-air Fresnel reflectances at the pixel's angles (~50-70 degrees:
  // 0.80-0.87, a band 0.6-1.2% wide). Without the Fresnel term the pixel
  // would read 1; Schlick's approximation in place of the exact equations
  // moves it by ~4% at 60 degrees.
  auto s = emptyScene("whitted Fresnel", 30.0f);
  s.ambient = glm::vec3(1.0f);
  const uint32_t glassMaterial = addMaterial(s, glass(1.5f));
  const uint32_t white = addMaterial(s, phong("white", glm::vec3(1.0f)));
  const glm::mat4 slab = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 2.5f}),
                                     glm::radians(60.0f), glm::vec3(0, 1, 0));
  addMesh(s, scene::makeBox({-2, -2, -0.4f}, {2, 2, 0.4f}, false, glassMaterial), slab);
  addWall(s, {-1.5f, -5, 4.5f}, {0, 10, 0}, {3, 0, 0}, white);
  scene::validate(s);
  const auto tris = test::worldTriangles(s);
  const glm::vec3 slabNormal = glm::vec3(slab * glm::vec4(0, 0, 1, 0));

  auto device = test::makeTestDevice();
  const auto img = test::renderScene(*device, s, kSize, kSize, 1, whittedSettings());
  REQUIRE(image::countNonFinite(img) == 0);
  uint32_t failures = 0;
  std::string firstFailure;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      double low = 1e30, high = -1e30;
      for (const auto& film : test::pixelFootprint(x, y)) {
        const glm::vec3 d = test::cameraRayDirection(s.camera, kSize, kSize, film);
        const auto p = mainPath(s, tris, film);
        REQUIRE(p.material == white);
        REQUIRE(p.refractions == 2u);
        const auto front = test::intersect(tris, s.camera.position, d);
        const auto reflected = test::traceMainPath(
            tris, front->position, test::reflectAbout(d, front->normal),
            [&](uint32_t m) { return kindOf(s, m); },
            [&](uint32_t m) { return s.materials[m].ior; });
        REQUIRE(reflected.material == test::MainPath::kNothing);
        const float cosI = std::abs(glm::dot(d, slabNormal));
        const double r1 = test::fresnelUnpolarised(cosI, 1.0f, 1.5f);
        const float sinT = std::sqrt(1.0f - cosI * cosI) / 1.5f;
        const double r2 = test::fresnelUnpolarised(std::sqrt(1.0f - sinT * sinT), 1.5f, 1.0f);
        low = std::min(low, (1 - r1) * (1 - r2));
        high = std::max(high, (1 - r1) * (1 - r2) / (1 - r2 * r2));
      }
      for (int c = 0; c < 3; ++c) {
        const float v = img.pixel(x, y)[c];
        if (v < low - 1e-4 || v > high + 1e-4) {
          if (failures++ == 0) {
            std::ostringstream os;
            os << "pixel (" << x << ", " << y << ") = " << v << ", expected in [" << low << ", "
               << high << "]";
            firstFailure = os.str();
          }
        }
      }
    }
  INFO(failures << " failing channels; first: " << firstFailure);
  REQUIRE(failures == 0u);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
