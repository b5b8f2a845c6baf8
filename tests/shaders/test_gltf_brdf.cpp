// The Lambert-diffuse Disney model that glTF materials use, against glTF 2.0's
// BRDF (specification Appendix B) written out here independently: which
// parts agree exactly and by how much the rest differs (docs/materials.md,
// "How close the Lambert variant is to glTF's Appendix B").
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <complex>
#include <iterator>
#include <numbers>
#include <utility>
#include <vector>

#include "bsdf_harness.h"
#include "penumbra/scene/gltf_materials.h"
#include "penumbra/scene/tinygltf.h"
#include "test_device.h"

using namespace penumbra;

namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 direction(double thetaDegrees, double phiDegrees) {
  const double t = thetaDegrees * kPi / 180.0, p = phiDegrees * kPi / 180.0;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

double lambda(double cosTheta, double alpha) {
  const double tan2 = (1.0 - cosTheta * cosTheta) / (cosTheta * cosTheta);
  return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

// Appendix B: f = (1-m)[(1 - F) c/pi + F D V] + m F_metal D V with Schlick's
// F at VdotH, GGX D, and the separable Smith G of the specification
// (`heightCorrelated` swaps in G2 = 1 / (1 + L(v) + L(l)), as its
// implementation notes allow).
glm::dvec3 appendixB(glm::dvec3 c, double metallic, double roughness, glm::dvec3 v, glm::dvec3 l,
                     bool heightCorrelated) {
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  const glm::dvec3 h = glm::normalize(v + l);
  const double vh = glm::dot(v, h), nh = h.z, nv = v.z, nl = l.z;
  const double d = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  const double g = heightCorrelated ? 1.0 / (1.0 + lambda(nv, alpha) + lambda(nl, alpha))
                                    : 1.0 / ((1.0 + lambda(nv, alpha)) * (1.0 + lambda(nl, alpha)));
  const double spec = d * g / (4.0 * nv * nl);
  const double w = std::pow(1.0 - vh, 5.0);
  const double f = 0.04 + 0.96 * w;
  const glm::dvec3 fMetal = c + (glm::dvec3(1.0) - c) * w;
  return (1.0 - metallic) * ((1.0 - f) * c / kPi + glm::dvec3(f * spec)) + metallic * fMetal * spec;
}

scene::Material gltfMaterial(glm::vec3 baseColor, float metallic, float roughness) {
  scene::Material m = scene::gltf::defaultMaterial();  // Lambert, specular 0.5 (F0 0.04)
  m.baseColor = baseColor;
  m.metallic = metallic;
  m.roughness = roughness;
  return m;
}

// A black dielectric (no diffuse) with KHR_materials_ior and
// KHR_materials_specular, through the loader's own conversion.
scene::Material specularExtensionMaterial(double ior, glm::dvec3 color, double factor,
                                          double roughness) {
  using tinygltf::Value;
  tinygltf::Material src;
  src.pbrMetallicRoughness.baseColorFactor = {0.0, 0.0, 0.0, 1.0};
  src.pbrMetallicRoughness.metallicFactor = 0.0;
  src.pbrMetallicRoughness.roughnessFactor = roughness;
  src.extensions["KHR_materials_ior"] = Value(Value::Object{{"ior", Value(ior)}});
  src.extensions["KHR_materials_specular"] =
      Value(Value::Object{{"specularFactor", Value(factor)},
                          {"specularColorFactor",
                           Value(Value::Array{Value(color.x), Value(color.y), Value(color.z)})}});
  std::vector<std::string> warnings;
  return scene::gltf::convertMaterial(src, "test", warnings).material;
}

// KHR_materials_specular's dielectric layer over a black base: F D G2 /
// (4 NdotL NdotV) with F = F0 + (F90 - F0)(1 - VdotH)^5 per channel,
// F0 = min(((ior - 1)/(ior + 1))^2 color, 1) factor and F90 = factor.
glm::dvec3 specularExtension(double ior, glm::dvec3 color, double factor, double roughness,
                             glm::dvec3 v, glm::dvec3 l) {
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  const glm::dvec3 h = glm::normalize(v + l);
  const double d = a2 / (kPi * std::pow(h.z * h.z * (a2 - 1.0) + 1.0, 2.0));
  const double g = 1.0 / (1.0 + lambda(v.z, alpha) + lambda(l.z, alpha));
  const double r = (ior - 1.0) / (ior + 1.0);
  const glm::dvec3 f0 = glm::min(r * r * color, glm::dvec3(1.0)) * factor;
  const glm::dvec3 f = f0 + (glm::dvec3(factor) - f0) * std::pow(1.0 - glm::dot(v, h), 5.0);
  return f * (d * g / (4.0 * v.z * l.z));
}

struct Pair {
  glm::dvec3 v, l;
};

const Pair kPairs[] = {
    {direction(0, 0), direction(30, 0)},    {direction(30, 10), direction(45, 200)},
    {direction(60, 0), direction(60, 180)}, {direction(75, 30), direction(20, 100)},
    {direction(10, 0), direction(80, 90)},
};

}  // namespace

TEST_CASE("glTF BRDF: the specular layer is Appendix B's with height-correlated masking",
          "[shaders][bsdf][gpu][gltf][spirv-only]") {
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  // Metals, and dielectrics with a black base (no diffuse): specular only.
  const scene::Material materials[] = {
      gltfMaterial({0.9f, 0.6f, 0.3f}, 1.0f, 0.5f), gltfMaterial({0.9f, 0.6f, 0.3f}, 1.0f, 0.9f),
      gltfMaterial({0.0f, 0.0f, 0.0f}, 0.0f, 0.4f), gltfMaterial({0.0f, 0.0f, 0.0f}, 0.0f, 1.0f)};
  for (const auto& m : materials)
    for (const auto& p : kPairs) {
      const auto e = harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      const glm::dvec3 ref =
          appendixB(glm::dvec3(m.baseColor), m.metallic, m.roughness, p.v, p.l, true);
      INFO("metallic " << m.metallic << " roughness " << m.roughness << " v.z " << p.v.z << " l.z "
                       << p.l.z << ": f " << e.f.x << " " << e.f.y << " " << e.f.z
                       << ", Appendix B " << ref.x << " " << ref.y << " " << ref.z);
      for (int c = 0; c < 3; ++c)
        REQUIRE(e.f[c] == Catch::Approx(ref[c]).epsilon(2e-4).margin(1e-7));
    }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("glTF BRDF: the specification's separable masking differs only off normal incidence",
          "[shaders][bsdf][gpu][gltf][spirv-only]") {
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const auto metal = gltfMaterial({0.9f, 0.9f, 0.9f}, 1.0f, 1.0f);
  // Viewed head-on, Lambda(v) = 0 and both forms agree.
  {
    const glm::dvec3 v = direction(0, 0), l = direction(60, 0);
    const auto e = harness.eval(metal, glm::vec3(v), {glm::vec3(l)})[0];
    REQUIRE(e.f.x == Catch::Approx(appendixB({0.9, 0.9, 0.9}, 1, 1, v, l, false).x).epsilon(2e-4));
  }
  // Roughness 1 (alpha 1), both at 80 degrees: Lambda = (sqrt(1 + tan^2 80) - 1) / 2
  // = (1 / cos 80 - 1) / 2 = 2.3794; separable 1 / (1 + L)^2 = 0.08756, correlated
  // 1 / (1 + 2 L) = 0.17365: the engine reflects 1.983 times what Appendix B's formula says.
  const glm::dvec3 v = direction(80, 0), l = direction(80, 180);
  const auto e = harness.eval(metal, glm::vec3(v), {glm::vec3(l)})[0];
  const double ratio = e.f.x / appendixB({0.9, 0.9, 0.9}, 1, 1, v, l, false).x;
  REQUIRE(ratio == Catch::Approx(0.17365 / 0.08756).epsilon(2e-3));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE("glTF BRDF: the diffuse carries two Fresnel factors where Appendix B has one",
          "[shaders][bsdf][gpu][gltf][spirv-only]") {
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const glm::vec3 white(1.0f);
  const auto m = gltfMaterial(white, 0.0f, 1.0f);
  const glm::dvec3 n = direction(0, 0);
  // Both directions along the normal: the specular terms agree (Lambda = 0),
  // and the diffuse is (1 - 0.04)^2 / pi here against (1 - 0.04) / pi there.
  const auto e = harness.eval(m, glm::vec3(n), {glm::vec3(n)})[0];
  const glm::dvec3 ref = appendixB(glm::dvec3(white), 0, 1, n, n, false);
  REQUIRE(ref.x - e.f.x == Catch::Approx((0.96 - 0.96 * 0.96) / kPi).epsilon(1e-3));
  // A grazing light (89 degrees) seen from straight above: the engine's
  // diffuse weight (1 - F(cos 89))(1 - F(1)) collapses, Appendix B's stays
  // near 1 - F(VdotH) = 1 - F(cos 44.5) ~ 0.958.
  const glm::dvec3 l = direction(89, 0);
  const auto g = harness.eval(m, glm::vec3(n), {glm::vec3(l)})[0];
  const double fl = 0.04 + 0.96 * std::pow(1.0 - l.z, 5.0);
  const double expectedDiffuse = (1.0 - fl) * 0.96 / kPi;
  const double vh = glm::dot(n, glm::normalize(n + l));
  const double specular = appendixB({0, 0, 0}, 0, 1, n, l, true).x;  // black base: specular only
  REQUIRE(g.f.x == Catch::Approx(expectedDiffuse + specular).epsilon(1e-3));
  // Against the specification itself: the engine's BRDF falls short of
  // Appendix B's by exactly the two diffuse weights' difference, and its
  // diffuse part is well under half of Appendix B's there.
  const double fvh = 0.04 + 0.96 * std::pow(1.0 - vh, 5.0);
  const double specGrazing = appendixB(glm::dvec3(white), 0, 1, n, l, true).x;
  REQUIRE(specGrazing - g.f.x == Catch::Approx(((1.0 - fvh) - (1.0 - fl) * 0.96) / kPi).epsilon(1e-3));
  REQUIRE(g.f.x - specular < 0.5 * (specGrazing - specular));
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE(
    "glTF BRDF: KHR_materials_specular's coloured F0, up to 1, is the specular layer's Fresnel",
    "[shaders][bsdf][gpu][gltf][spirv-only]") {
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  // ior 2 (F0 1/9) times (10, 1, 0.2): red's 10/9 clamps to 1, green stays
  // 1/9 (above the 0.08 a Disney `specular` reaches), blue 0.022.
  const glm::dvec3 color(10.0, 1.0, 0.2);
  for (double roughness : {0.4, 0.8})
    for (const auto& p : kPairs) {
      const auto m = specularExtensionMaterial(2.0, color, 1.0, roughness);
      const auto e = harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      const glm::dvec3 ref = specularExtension(2.0, color, 1.0, roughness, p.v, p.l);
      INFO("roughness " << roughness << " v.z " << p.v.z << " l.z " << p.l.z << ": f " << e.f.x
                        << " " << e.f.y << " " << e.f.z << ", extension " << ref.x << " " << ref.y
                        << " " << ref.z);
      for (int c = 0; c < 3; ++c)
        REQUIRE(e.f[c] == Catch::Approx(ref[c]).epsilon(2e-4).margin(1e-7));
    }
  // specularFactor 0.5 scales F0 and is F90: at every pair, grazing half
  // angles included, where F90 dominates (the engine's Fresnel once kept
  // F90 = 1 there and reflected up to twice as much). A grey F0 of 0.02
  // (ior 1.5, colour 1), which the loader writes as `specular` alone, too.
  for (const auto& [ior, tint] : {std::pair{2.0, color}, std::pair{1.5, glm::dvec3(1.0)}}) {
    const auto half = specularExtensionMaterial(ior, tint, 0.5, 0.5);
    std::vector<Pair> pairs(std::begin(kPairs), std::end(kPairs));
    pairs.push_back({direction(80, 0), direction(80, 180)});
    pairs.push_back({direction(85, 10), direction(70, 200)});
    for (const auto& p : pairs) {
      const auto e = harness.eval(half, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      const glm::dvec3 ref = specularExtension(ior, tint, 0.5, 0.5, p.v, p.l);
      INFO("ior " << ior << " v.z " << p.v.z << " l.z " << p.l.z << ": f " << e.f.y
                  << ", extension " << ref.y);
      for (int c = 0; c < 3; ++c)
        REQUIRE(e.f[c] == Catch::Approx(ref[c]).epsilon(2e-4).margin(1e-7));
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {

// A dielectric glTF material of base colour `base` and ior 1 (F0 0: no
// specular layer), for the extension under test to add to.
tinygltf::Material iorOneMaterial(glm::dvec3 base) {
  tinygltf::Material src;
  src.pbrMetallicRoughness.baseColorFactor = {base.x, base.y, base.z, 1.0};
  src.pbrMetallicRoughness.metallicFactor = 0.0;
  src.extensions["KHR_materials_ior"] =
      tinygltf::Value(tinygltf::Value::Object{{"ior", tinygltf::Value(1.0)}});
  return src;
}

// A black base with ior 1 (F0 0: no specular layer) under
// KHR_materials_clearcoat, through the loader's own conversion: the coat alone.
scene::Material clearcoatExtensionMaterial(double factor, double roughness) {
  using tinygltf::Value;
  tinygltf::Material src = iorOneMaterial(glm::dvec3(0.0));
  src.extensions["KHR_materials_clearcoat"] = Value(Value::Object{
      {"clearcoatFactor", Value(factor)}, {"clearcoatRoughnessFactor", Value(roughness)}});
  std::vector<std::string> warnings;
  return scene::gltf::convertMaterial(src, "test", warnings).material;
}

// The extension's coat over a black base: mix(base, coat_brdf, factor Fr)
// with Fr = 0.04 + 0.96 (1 - NdotV)^5 and coat_brdf = D V of alpha =
// roughness^2 (V height-correlated, as for the base layer above).
double clearcoatExtension(double factor, double roughness, glm::dvec3 v, glm::dvec3 l) {
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  const glm::dvec3 h = glm::normalize(v + l);
  const double d = a2 / (kPi * std::pow(h.z * h.z * (a2 - 1.0) + 1.0, 2.0));
  const double g = 1.0 / (1.0 + lambda(v.z, alpha) + lambda(l.z, alpha));
  const double fr = 0.04 + 0.96 * std::pow(1.0 - v.z, 5.0);
  return factor * fr * d * g / (4.0 * v.z * l.z);
}

}  // namespace

TEST_CASE(
    "glTF BRDF: KHR_materials_clearcoat's coat reflects at full strength, as the extension says",
    "[shaders][bsdf][gpu][gltf][spirv-only]") {
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  for (double roughness : {0.3, 0.7}) {
    const auto m = clearcoatExtensionMaterial(0.7, roughness);
    // In the mirror configuration the half vector is the normal, VdotH =
    // NdotV, and the engine's microfacet Fresnel F(VdotH) is the extension's
    // F(NdotV): the same value.
    for (double theta : {0.0, 30.0, 60.0, 75.0}) {
      const glm::dvec3 v = direction(theta, 20), l = direction(theta, 200);
      const auto e = harness.eval(m, glm::vec3(v), {glm::vec3(l)})[0];
      const double ref = clearcoatExtension(0.7, roughness, v, l);
      INFO("roughness " << roughness << " theta " << theta << ": f " << e.f.x << ", extension "
                        << ref);
      for (int c = 0; c < 3; ++c) REQUIRE(e.f[c] == Catch::Approx(ref).epsilon(2e-4));
    }
    // Elsewhere the engine's coat is a microfacet reflection, Fresnel at the
    // half vector; the extension weights its mix by F(NdotV): the two differ
    // by exactly that ratio.
    for (const auto& p : kPairs) {
      const auto e = harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      const double vh = glm::dot(p.v, glm::normalize(p.v + p.l));
      const double ratio =
          (0.04 + 0.96 * std::pow(1.0 - vh, 5.0)) / (0.04 + 0.96 * std::pow(1.0 - p.v.z, 5.0));
      const double ref = clearcoatExtension(0.7, roughness, p.v, p.l) * ratio;
      INFO("roughness " << roughness << " v.z " << p.v.z << " l.z " << p.l.z << ": f " << e.f.x
                        << " vs " << ref);
      REQUIRE(e.f.x == Catch::Approx(ref).epsilon(2e-4).margin(1e-7));
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE(
    "glTF BRDF: a coat with its own normal is the extension's coat about that normal, times its "
    "cosine over the base's",
    "[shaders][bsdf][gpu][gltf][spirv-only]") {
  // clearcoatNormalTexture tilts the coat's normal n away from the base's
  // (z). The extension's coat term is then D V F in n's frame, integrated
  // against n.l; the engine's integrator multiplies by the base's cosine
  // l.z, so f l.z must equal the coat's BRDF in n's frame times n.l. The
  // frame here is a rotation about z x n (Rodrigues), not the shader's.
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const glm::dvec3 n = glm::normalize(glm::dvec3(-0.35, 0.25, 1.0));
  const glm::dvec3 axis = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), n));
  const double angle = std::acos(n.z);
  // Rotates by -angle about axis: n to z (into n's frame).
  auto toCoat = [&](glm::dvec3 v) {
    const double c = std::cos(-angle), s = std::sin(-angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
  };
  for (double roughness : {0.3, 0.7}) {
    const auto m = clearcoatExtensionMaterial(0.7, roughness);
    for (const auto& p : kPairs) {
      const glm::dvec3 vc = toCoat(p.v), lc = toCoat(p.l);
      const auto e = harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)}, glm::vec3(n))[0];
      double ref = 0.0;
      if (vc.z > 0.0 && lc.z > 0.0) {
        // The microfacet Fresnel F(VdotH), as the untilted case above says.
        const double vh = glm::dot(p.v, glm::normalize(p.v + p.l));
        const double ratio =
            (0.04 + 0.96 * std::pow(1.0 - vh, 5.0)) / (0.04 + 0.96 * std::pow(1.0 - vc.z, 5.0));
        ref = clearcoatExtension(0.7, roughness, vc, lc) * lc.z * ratio;
      }
      INFO("roughness " << roughness << " v.z " << p.v.z << " l.z " << p.l.z << " (coat frame "
                        << vc.z << ", " << lc.z << "): f l.z " << e.f.x * p.l.z << " vs " << ref);
      REQUIRE(e.f.x * p.l.z == Catch::Approx(ref).epsilon(2e-4).margin(1e-7));
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE(
    "glTF BRDF: KHR_materials_diffuse_transmission sends its share of the diffuse lobe through, "
    "Lambertian, in its colour",
    "[shaders][bsdf][gpu][gltf][spirv-only]") {
  // A base with ior 1 (F0 0: no specular layer above the diffuse one), so
  // the extension's mix(diffuse_brdf(baseColor), diffuse_btdf(colour), t)
  // is all there is: (1 - t) baseColor / pi towards wo's side, t colour / pi
  // towards the other, whatever the directions.
  using tinygltf::Value;
  tinygltf::Material src = iorOneMaterial(glm::dvec3(0.6, 0.4, 0.2));
  src.extensions["KHR_materials_diffuse_transmission"] = Value(Value::Object{
      {"diffuseTransmissionFactor", Value(0.3)},
      {"diffuseTransmissionColorFactor", Value(Value::Array{Value(0.9), Value(0.5), Value(0.1)})}});
  std::vector<std::string> warnings;
  const auto m = scene::gltf::convertMaterial(src, "test", warnings).material;
  CHECK(warnings.empty());
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const glm::dvec3 base(0.6, 0.4, 0.2), color(0.9, 0.5, 0.1);
  for (bool inside : {false, true})
    for (const auto& p : kPairs) {
      const double side = inside ? -1.0 : 1.0;
      const glm::dvec3 v(p.v.x, p.v.y, p.v.z * side);
      const glm::dvec3 reflected(p.l.x, p.l.y, p.l.z * side);
      const glm::dvec3 through(p.l.x, p.l.y, -p.l.z * side);
      const auto e = harness.eval(m, glm::vec3(v), {glm::vec3(reflected), glm::vec3(through)});
      INFO("inside " << inside << " v.z " << p.v.z << " l.z " << p.l.z);
      for (int c = 0; c < 3; ++c) {
        REQUIRE(e[0].f[c] == Catch::Approx(0.7 * base[c] / kPi).epsilon(1e-5));
        REQUIRE(e[1].f[c] == Catch::Approx(0.3 * color[c] / kPi).epsilon(1e-5));
      }
    }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {

// A base of colour `base` with ior 1 (F0 0: no specular layer) under
// KHR_materials_sheen, through the loader's own conversion.
scene::Material sheenExtensionMaterial(glm::dvec3 color, double roughness, double base) {
  using tinygltf::Value;
  tinygltf::Material src = iorOneMaterial(glm::dvec3(base));
  src.extensions["KHR_materials_sheen"] = Value(Value::Object{
      {"sheenColorFactor", Value(Value::Array{Value(color.x), Value(color.y), Value(color.z)})},
      {"sheenRoughnessFactor", Value(roughness)}});
  std::vector<std::string> warnings;
  return scene::gltf::convertMaterial(src, "test", warnings).material;
}

// The extension's sheen BRDF for colour 1 (its implementation notes): the
// Charlie distribution of alpha = roughness^2 and the visibility built on
// its fitted shadowing term.
double sheenFit(double x, double alpha) {
  const double t = (1.0 - alpha) * (1.0 - alpha);
  const double a = 21.5473 + (25.3245 - 21.5473) * t, b = 3.82987 + (3.32435 - 3.82987) * t;
  const double c = 0.19823 + (0.16801 - 0.19823) * t, d = -1.97760 + (-1.27393 + 1.97760) * t;
  const double e = -4.32054 + (-4.85967 + 4.32054) * t;
  return a / (1.0 + b * std::pow(x, c)) + d * x + e;
}

double sheenLambda(double cosTheta, double alpha) {
  return cosTheta < 0.5 ? std::exp(sheenFit(cosTheta, alpha))
                        : std::exp(2.0 * sheenFit(0.5, alpha) - sheenFit(1.0 - cosTheta, alpha));
}

double sheenBrdf(double roughness, glm::dvec3 v, glm::dvec3 l) {
  const double alpha = roughness * roughness;
  const double nh = glm::normalize(v + l).z;
  const double d = (2.0 + 1.0 / alpha) * std::pow(1.0 - nh * nh, 0.5 / alpha) / (2.0 * kPi);
  return d / ((1.0 + sheenLambda(v.z, alpha) + sheenLambda(l.z, alpha)) * 4.0 * v.z * l.z);
}

// The sheen's directional albedo E(mu, roughness), integrated over the
// hemisphere here (midpoint rule).
double sheenAlbedo(double mu, double roughness) {
  const glm::dvec3 v(std::sqrt(1.0 - mu * mu), 0.0, mu);
  const int nTheta = 600, nPhi = 300;
  double sum = 0.0;
  for (int i = 0; i < nTheta; ++i) {
    const double theta = (i + 0.5) * 0.5 * kPi / nTheta;
    for (int j = 0; j < nPhi; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / nPhi;
      const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta));
      sum += sheenBrdf(roughness, v, l) * l.z * std::sin(theta);
    }
  }
  return sum * (0.5 * kPi / nTheta) * (2.0 * kPi / nPhi);
}

}  // namespace

TEST_CASE("glTF BRDF: KHR_materials_sheen's sheen is colour x the Charlie fibres' D x V",
          "[shaders][bsdf][gpu][gltf][spirv-only]") {
  // Over a black base the sheen is all there is. Every direction here has
  // E <= 1, where the engine leaves the extension's lobe as it is.
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const glm::dvec3 color(0.9, 0.5, 0.2);
  for (double roughness : {0.1, 0.3, 0.7, 1.0}) {
    const auto m = sheenExtensionMaterial(color, roughness, 0.0);
    REQUIRE(m.sheenRoughness == Catch::Approx(roughness));
    for (const auto& p : kPairs) {
      const auto e = harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      const double ref = sheenBrdf(roughness, p.v, p.l);
      INFO("roughness " << roughness << " v.z " << p.v.z << " l.z " << p.l.z << ": f " << e.f.x
                        << ", extension " << color.x * ref);
      for (int c = 0; c < 3; ++c)
        REQUIRE(e.f[c] == Catch::Approx(color[c] * ref).epsilon(1e-3).margin(1e-7));
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE(
    "glTF BRDF: the base below KHR_materials_sheen keeps 1 - max(colour) x E, E the sheen's albedo",
    "[shaders][bsdf][gpu][gltf][spirv-only]") {
  // A white Lambertian base under a sheen of largest channel 0.5:
  // f = (1 - 0.5 max(E(v), E(l))) / pi + colour x sheen. The engine looks E
  // up in a table (tools/sheen_albedo); here it is integrated again, so the
  // test catches a wrong table, a wrong lookup or a wrong layering. At the
  // table's nodes only the integrations' error is left (2e-3 of E lets
  // through no misplaced row or column); between them, bilinear
  // interpolation's too (0.04 of E, the worst found over a fine grid, at
  // grazing angles: 2 % of the light reaching the base).
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const glm::dvec3 color(0.5, 0.25, 0.1);
  struct Point {
    double roughness, cosV, cosL, tolerance;
  };
  // The table's nodes: roughness 0.07 + 0.93 i / 15, cosine (j / 15)^4.
  auto row = [](int i) { return 0.07 + 0.93 * i / 15.0; };
  auto node = [](int j) { return std::pow(j / 15.0, 4.0); };
  const Point points[] = {{row(5), node(9), node(15), 2e-3},
                          {row(5), node(12), node(14), 2e-3},
                          {row(10), node(6), node(14), 2e-3},
                          {row(10), node(10), node(15), 2e-3},
                          {0.5, 0.3, 0.9, 0.04},
                          {0.85, 0.15, 0.6, 0.04}};
  for (const auto& p : points) {
    const auto m = sheenExtensionMaterial(color, p.roughness, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - p.cosV * p.cosV), 0.0, p.cosV);
    const glm::dvec3 l(-0.6 * std::sqrt(1.0 - p.cosL * p.cosL),
                       0.8 * std::sqrt(1.0 - p.cosL * p.cosL), p.cosL);
    const auto e = harness.eval(m, glm::vec3(v), {glm::vec3(l)})[0];
    const double sheen = color.x * sheenBrdf(p.roughness, v, l);
    const double engineE = (1.0 - (double(e.f.x) - sheen) * kPi) / 0.5;
    const double expectedE =
        std::max(sheenAlbedo(p.cosV, p.roughness), sheenAlbedo(p.cosL, p.roughness));
    INFO("roughness " << p.roughness << " cos v " << p.cosV << " cos l " << p.cosL << ": E "
                      << engineE << ", integrated " << expectedE);
    REQUIRE(std::abs(engineE - expectedE) <= p.tolerance);
    // Every channel of the base is dimmed alike (by the colour's largest).
    const double baseY = double(e.f.y) - color.y * sheenBrdf(p.roughness, v, l);
    REQUIRE(baseY == Catch::Approx(double(e.f.x) - sheen).epsilon(1e-4));
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

namespace {

// The exact reflectance of a film of index n2 and thickness d (nm) on a
// substrate of index n3, in air, at normal incidence and one wavelength
// (Airy: the amplitudes of all the waves bouncing in the film summed).
double airyReflectance(double n2, double n3, double d, double wavelength) {
  const double r12 = (1.0 - n2) / (1.0 + n2), r23 = (n2 - n3) / (n2 + n3);
  const std::complex<double> phase = std::polar(1.0, 4.0 * kPi * n2 * d / wavelength);
  return std::norm((r12 + r23 * phase) / (1.0 + r12 * r23 * phase));
}

double schlick(double f0, double cosTheta) {
  return f0 + (1.0 - f0) * std::pow(1.0 - cosTheta, 5.0);
}

}  // namespace

TEST_CASE(
    "glTF BRDF: KHR_materials_iridescence's film has the interference colours of its "
    "thickness",
    "[shaders][bsdf][gpu][gltf][spirv-only]") {
  auto device = test::makeTestDevice();
  test::BsdfHarness harness(*device);
  const glm::vec3 up(0.0f, 0.0f, 1.0f);

  SECTION("a soap-like film on glass, seen head on, against the exact Airy reflectance") {
    // A black dielectric of F0 0.04 (index 1.5) under a film of index 1.33.
    // The engine's colour is the Airy reflectance integrated against the
    // eye's curves; at 650, 550 and 450 nm the exact one tells the hue. The
    // film's reflectance is f / f without it x 0.04 (D and G cancel). The
    // thicknesses are where the three wavelengths differ most (the first
    // orders' colours); 0.01 lets through no dropped interference term
    // (which would leave the incoherent 0.0235 everywhere, off by 0.016 or
    // more at 250 nm) and no misplaced order.
    auto m = gltfMaterial(glm::vec3(0.0f), 0.0f, 0.5f);
    const double plain = double(harness.eval(m, up, {up})[0].f.y);
    m.iridescence = 1.0f;
    m.iridescenceIor = 1.33f;
    for (double d : {150.0, 200.0, 250.0, 300.0, 400.0}) {
      m.iridescenceThicknessMaximum = float(d);
      const glm::dvec3 film = glm::dvec3(harness.eval(m, up, {up})[0].f) / plain * 0.04;
      const glm::dvec3 exact(airyReflectance(1.33, 1.5, d, 650.0),
                             airyReflectance(1.33, 1.5, d, 550.0),
                             airyReflectance(1.33, 1.5, d, 450.0));
      INFO(d << " nm: film " << film.x << " " << film.y << " " << film.z
             << ", Airy at 650/550/450 nm " << exact.x << " " << exact.y << " " << exact.z);
      for (int c = 0; c < 3; ++c) REQUIRE(std::abs(film[c] - exact[c]) < 0.01);
      // The brightest and darkest channels are the exact spectrum's.
      auto argmax = [](glm::dvec3 v) {
        return v.x >= v.y && v.x >= v.z ? 0 : (v.y >= v.z ? 1 : 2);
      };
      auto argmin = [&](glm::dvec3 v) { return argmax(-v); };
      REQUIRE(argmax(film) == argmax(exact));
      REQUIRE(argmin(film) == argmin(exact));
    }
  }

  SECTION("a film far thicker than the light's coherence adds its two interfaces' reflectances") {
    // 20 um: the interference averages out over the visible spectrum, and
    // the extension's reflectance becomes the incoherent sum R12 + T^2 R23 /
    // (1 - R12 R23), with Schlick's reflectance at the air-film boundary
    // (F0 of index 1.3) and at the film-metal one (the metal's F0 0.5 read
    // as an index n3, its F0 against the film, at the refracted cosine).
    // The ratio to the film-less metal (Schlick of 0.5) leaves D and G out.
    auto m = gltfMaterial(glm::vec3(0.5f), 1.0f, 0.5f);
    auto filmed = m;
    filmed.iridescence = 1.0f;
    filmed.iridescenceIor = 1.3f;
    filmed.iridescenceThicknessMaximum = 20000.0f;
    auto half = filmed;
    half.iridescence = 0.5f;
    const double n2 = 1.3, n3 = (1.0 + std::sqrt(0.5)) / (1.0 - std::sqrt(0.5));
    for (const auto& p : kPairs) {
      const double cosD = glm::dot(p.v, glm::normalize(p.v + p.l));
      const double cosT = std::sqrt(1.0 - (1.0 - cosD * cosD) / (n2 * n2));
      const double r12 = schlick(std::pow((n2 - 1.0) / (n2 + 1.0), 2.0), cosD);
      const double r23 = schlick(std::pow((n3 - n2) / (n3 + n2), 2.0), cosT);
      const double incoherent = r12 + (1.0 - r12) * (1.0 - r12) * r23 / (1.0 - r12 * r23);
      const double bare = schlick(0.5, cosD);
      const double f = double(harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)})[0].f.x);
      const auto e = harness.eval(filmed, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      const auto eHalf = harness.eval(half, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      INFO("cos theta_d " << cosD << ": film / bare " << e.f.x / f << ", incoherent sum "
                          << incoherent / bare);
      for (int c = 0; c < 3; ++c) {
        REQUIRE(e.f[c] / f == Catch::Approx(incoherent / bare).epsilon(1e-3));
        // iridescenceFactor mixes the two reflectances.
        REQUIRE(eHalf.f[c] / f == Catch::Approx(0.5 * (incoherent + bare) / bare).epsilon(1e-3));
      }
    }
  }

  SECTION("no film: thickness 0, or factor 0") {
    auto m = gltfMaterial(glm::vec3(0.9f, 0.6f, 0.3f), 0.5f, 0.4f);
    auto none = m;
    none.iridescence = 1.0f;
    none.iridescenceThicknessMaximum = 0.0f;
    auto off = m;
    off.iridescenceThicknessMaximum = 300.0f;
    for (const auto& p : kPairs) {
      const auto e = harness.eval(m, glm::vec3(p.v), {glm::vec3(p.l)})[0];
      for (const auto& other : {none, off}) {
        const auto o = harness.eval(other, glm::vec3(p.v), {glm::vec3(p.l)})[0];
        for (int c = 0; c < 3; ++c) REQUIRE(o.f[c] == e.f[c]);
        REQUIRE(o.pdf == e.pdf);
      }
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
