// The effect-specialized pipeline (engine/penumbra/render/effect_set.h): the effect set
// a scene calls for, and images identical to the full pipeline's.
#include <fmt/format.h>

#include <bit>
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <string>

#include "effects.h"
#include "penumbra/image/image_compare.h"
#include "penumbra/render/effect_set.h"
#include "penumbra/render/gpu_scene.h"
#include "penumbra/scene/mesh_builders.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra_shaders.h"
#include "render_test_utils.h"

using namespace penumbra;

namespace {

// The Cornell box (metres) with one extra sphere of `material`, and optionally a point
// light: each effect can be switched on alone.
scene::Scene cornellWithSphere(const scene::Material& material, bool pointLight = false) {
  scene::Scene s = scene::loadScene("cornell-box");
  s.materials.push_back(material);
  auto sphere = scene::makeIcosphere(2, 0.09f, false, uint32_t(s.materials.size() - 1));
  s.meshes.push_back(sphere);
  scene::Instance instance;
  instance.mesh = uint32_t(s.meshes.size() - 1);
  instance.transform[3] = glm::vec4(0.278f, 0.15f, 0.25f, 1.0f);
  s.instances.push_back(instance);
  if (pointLight) {
    scene::PointLight light;
    light.position = {0.278f, 0.45f, 0.15f};
    light.intensity = glm::vec3(0.2f);
    s.pointLights.push_back(light);
  }
  return s;
}

scene::Material disney() {
  scene::Material m;
  m.model = scene::MaterialModel::Disney;
  m.baseColor = {0.7f, 0.5f, 0.3f};
  m.specular = 0.0f;  // no specular layer unless a case asks for one
  m.roughness = 0.4f;
  return m;
}

}  // namespace

TEST_CASE("effect set: derived from what the scene's materials, lights and camera use",
          "[render]") {
  const auto cornell = scene::loadScene("cornell-box");
  // Lambertian walls (no specular layer) and an emissive ceiling light.
  REQUIRE(render::deriveEffects(cornell) == PT_EFFECT_AREA_LIGHTS);
  // The camera's projection: the scene's own, or the one it is seen from.
  scene::Camera parallel = cornell.camera;
  parallel.orthographicHeight = 1.0f;
  REQUIRE(render::deriveEffects(cornell, parallel) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_ORTHOGRAPHIC));
  auto orthographicCornell = cornell;
  orthographicCornell.camera = parallel;
  REQUIRE(render::deriveEffects(orthographicCornell) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_ORTHOGRAPHIC));
  REQUIRE(render::deriveEffects(orthographicCornell, cornell.camera) == PT_EFFECT_AREA_LIGHTS);

  auto m = disney();
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  REQUIRE(render::deriveEffects(cornellWithSphere(m, true)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_DELTA_LIGHTS));
  m.specular = 0.5f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR));
  m = disney();
  m.metallic = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR));
  // A coloured dielectric F0 (glTF's specular colour, its texture, Disney's
  // specularTint) or a grey one above 0.08, also on a metal (a metallic
  // texture can leave parts of it dielectric); not without a specular layer.
  const uint32_t colouredF0 = PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR | PT_EFFECT_SPECULAR_COLOR;
  m = disney();
  m.specular = 1.0f;
  m.specularColor = {2.0f, 1.0f, 1.0f};
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == colouredF0);
  m.specularColor = glm::vec3(1.5f);
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == colouredF0);
  m.metallic = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == colouredF0);
  m = disney();
  m.specular = 0.5f;
  m.specularTint = 0.3f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == colouredF0);
  m.specular = 0.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  // glTF's F90 = specularFactor below 1, or a specular texture (whose alpha
  // scales it), is part of the same code.
  m = disney();
  m.specular = 0.25f;
  m.specularF90 = 0.5f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == colouredF0);
  m.specularF90 = 1.0f;
  m.specularTexture = 0;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == (colouredF0 | PT_EFFECT_TEXTURES));
  m = disney();
  m.specTrans = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TRANSMISSION));
  m = disney();
  m.clearcoat = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_CLEARCOAT));
  m = disney();
  m.sheen = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SHEEN));
  // The lambert model's (glTF's) coat and sheen are the extensions', with
  // code of their own.
  m = disney();
  m.model = scene::MaterialModel::Lambert;
  m.clearcoat = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_CLEARCOAT | PT_EFFECT_GLTF_COAT));
  m.clearcoat = 0.0f;
  m.sheen = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SHEEN | PT_EFFECT_GLTF_SHEEN));
  m.sheen = 0.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  // Diffuse transmission, for either model; a Phong material has none.
  m.diffuseTransmission = 0.4f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_DIFFUSE_TRANSMISSION));
  m.model = scene::MaterialModel::Disney;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_DIFFUSE_TRANSMISSION));
  m.model = scene::MaterialModel::Phong;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  // A thin film colours a specular layer: none without one (or for Phong).
  m = disney();
  m.iridescence = 0.5f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  m.metallic = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR | PT_EFFECT_IRIDESCENCE));
  m.model = scene::MaterialModel::Phong;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  // Dispersion bends a volume's refraction: none on thin glass or without glass.
  m = disney();
  m.dispersion = 0.5f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) == PT_EFFECT_AREA_LIGHTS);
  m.specTrans = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TRANSMISSION | PT_EFFECT_DISPERSION));
  m.thin = true;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TRANSMISSION));
  // glTF anisotropy turns the tangent where the hit is built: surface detail.
  m = disney();
  m.metallic = 1.0f;
  m.anisotropyStrength = 0.5f;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR | PT_EFFECT_TEXTURES));

  // Phong: mirrors and highlights need the specular code, transparency refraction.
  scene::Material phong;
  phong.model = scene::MaterialModel::Phong;
  phong.specular = 0.5f;  // a Disney field: ignored by both integrators for Phong
  REQUIRE(render::deriveEffects(cornellWithSphere(phong)) == PT_EFFECT_AREA_LIGHTS);
  phong.reflectivity = 0.8f;
  REQUIRE(render::deriveEffects(cornellWithSphere(phong)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR));
  phong.reflectivity = 0.0f;
  phong.transparency = 0.9f;
  REQUIRE(render::deriveEffects(cornellWithSphere(phong)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TRANSMISSION));
  // glTF anisotropy is a Disney-lobe parameter: a Phong material keeps no
  // bit for it, and the GPU never sees it (so no variant can differ).
  phong.anisotropyStrength = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(phong)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TRANSMISSION));
  REQUIRE(render::packMaterial(phong).anisotropyStrength == 0.0f);
  scene::Material brushed = disney();
  REQUIRE(render::packMaterial(brushed).anisotropyStrength == 0.0f);
  brushed.anisotropyStrength = 0.25f;
  REQUIRE(render::packMaterial(brushed).anisotropyStrength == 0.25f);

  // Unlit: only the surface-detail code, whose variants hold the unlit
  // branch; its Disney fields are ignored.
  scene::Material unlit = disney();
  unlit.model = scene::MaterialModel::Unlit;
  unlit.metallic = 1.0f;
  unlit.specTrans = 1.0f;
  REQUIRE(render::deriveEffects(cornellWithSphere(unlit)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TEXTURES));

  // A material no instance uses calls for nothing.
  auto unused = scene::loadScene("cornell-box");
  scene::Material glass = disney();
  glass.specTrans = 1.0f;
  unused.materials.push_back(glass);
  REQUIRE(render::deriveEffects(unused) == PT_EFFECT_AREA_LIGHTS);

  // Textures, and alpha masking when a MASK material has a base-colour
  // texture (MASK without one is decided when the scene is loaded).
  m = disney();
  m.normalTexture = 0;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TEXTURES));
  m.alphaMode = scene::AlphaMode::Mask;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TEXTURES));
  m.baseColorTexture = 0;
  REQUIRE(render::deriveEffects(cornellWithSphere(m)) ==
          (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TEXTURES | PT_EFFECT_ALPHA_MASK));

  // Vertex colours (COLOR_0) share the textures' bit whatever the material:
  // a mesh with them turns it on, and only a drawn one does.
  scene::Scene coloured = cornellWithSphere(disney());
  coloured.meshes.back().colors.assign(coloured.meshes.back().positions.size(),
                                       glm::vec4(1.0f, 0.5f, 0.25f, 1.0f));
  REQUIRE(render::deriveEffects(coloured) == (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_TEXTURES));
  coloured.instances.pop_back();
  REQUIRE(render::deriveEffects(coloured) == PT_EFFECT_AREA_LIGHTS);

  REQUIRE(render::effectNames(PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SHEEN) ==
          std::vector<std::string>{"area-lights", "sheen"});
  REQUIRE(render::effectNames(PT_EFFECT_CLEARCOAT | PT_EFFECT_GLTF_COAT | PT_EFFECT_GLTF_SHEEN |
                              PT_EFFECT_DIFFUSE_TRANSMISSION | PT_EFFECT_IRIDESCENCE |
                              PT_EFFECT_DISPERSION) ==
          std::vector<std::string>{"clearcoat", "gltf-coat", "gltf-sheen", "diffuse-transmission",
                                   "iridescence", "dispersion"});
}

TEST_CASE("effect set: a variant leaves out the code of absent effects", "[render]") {
  REQUIRE(render::effectVariant("path_trace.rgen", PT_EFFECTS_ALL | PT_OUTPUT_GUIDES) ==
          "path_trace.rgen");
  REQUIRE(render::effectVariant("path_trace.rgen", PT_EFFECTS_ALL) == "path_trace.e130687.rgen");
  REQUIRE(render::effectVariant("path_trace.rgen", PT_EFFECT_AREA_LIGHTS) == "path_trace.e1.rgen");
  REQUIRE(render::effectVariant("path_trace.rgen", PT_EFFECT_AREA_LIGHTS | PT_OUTPUT_GUIDES) ==
          "path_trace.e257.rgen");
  // Whitted has variants for specular and transmission only.
  REQUIRE(render::effectVariant("whitted.rgen", PT_EFFECT_AREA_LIGHTS) == "whitted.e0.rgen");
  REQUIRE(render::effectVariant("whitted.rgen", PT_EFFECTS_ALL) == "whitted.rgen");
  // Each effect (or the guides) removed makes the shader smaller.
  const uint32_t all = PT_EFFECTS_ALL | PT_OUTPUT_GUIDES;
  const size_t full = shaders::shaderDesc("path_trace.rgen").spirv.size();
  for (uint32_t bit = 1; bit <= PT_EFFECT_DISPERSION; bit <<= 1) {
    if ((PT_PATH_TRACE_EFFECT_BITS & bit) == 0) continue;  // alpha masking: no variant
    const auto without = shaders::shaderDesc(render::effectVariant("path_trace.rgen", all & ~bit));
    INFO("without effect bit " << bit << ": " << without.spirv.size() << " words, full " << full);
    REQUIRE(without.spirv.size() < full);
  }
  // Every set resolves to a built variant holding all its effects.
  for (uint32_t mask = 0; mask <= all; ++mask) {
    const std::string name = render::effectVariant("path_trace.rgen", mask);
    REQUIRE_NOTHROW(shaders::shaderDesc(name));
    const uint32_t bits = PT_PATH_TRACE_EFFECT_BITS;  // alpha masking (128) is no variant bit
    const uint32_t built = name == "path_trace.rgen" ? bits : uint32_t(std::stoul(name.substr(12)));
    INFO("effects " << mask << " -> " << name);
    REQUIRE((built & mask & bits) == (mask & bits));
  }
  // A set that is not built takes the smallest built superset: sheen alone
  // (32) is in no built variant smaller than 63 (every effect up to sheen).
  REQUIRE(render::effectVariant("path_trace.rgen", PT_EFFECT_SHEEN) == "path_trace.e63.rgen");
  // Of the supersets with the fewest extra bits, the one with the least code:
  // glTF's layered materials without textures (tests/data/gltf/materials.gltf),
  // which several variants of "every bit but one" hold.
  const uint32_t layered = PT_EFFECT_AREA_LIGHTS | PT_EFFECT_SPECULAR | PT_EFFECT_TRANSMISSION |
                           PT_EFFECT_CLEARCOAT | PT_EFFECT_SHEEN | PT_EFFECT_ENVIRONMENT |
                           PT_EFFECT_SPECULAR_COLOR | PT_EFFECT_GLTF_COAT | PT_EFFECT_GLTF_SHEEN;
  const std::string chosen = render::effectVariant("path_trace.rgen", layered);
  const uint32_t chosenBits = uint32_t(std::stoul(chosen.substr(12)));
  const size_t chosenWords = shaders::find(chosen).size();
  int equals = 0;
  for (uint32_t mask = 0; mask <= all; ++mask) {
    if ((mask & layered) != layered || (mask & ~all) != 0) continue;
    const auto spirv = shaders::find(fmt::format("path_trace.e{}.rgen", mask));
    if (spirv.empty()) continue;
    INFO("chosen " << chosen << " (" << chosenWords << " words); built superset " << mask << " ("
                   << spirv.size() << " words)");
    REQUIRE(std::popcount(mask) >= std::popcount(chosenBits));
    if (std::popcount(mask) == std::popcount(chosenBits)) {
      REQUIRE(spirv.size() >= chosenWords);
      ++equals;
    }
  }
  REQUIRE(equals > 1);  // a real choice
  // The triangles' closest hit only stores a HitRecord: it has no variants.
  REQUIRE_THROWS(render::effectVariant("triangle.rchit", PT_EFFECT_AREA_LIGHTS));
}

// The specialized pipeline must render what the full one renders. The same
// seed gives the same paths, and an absent effect's code adds exactly zero in
// the full pipeline, so the images are expected bit-identical; the tolerance
// (1e-5 relative, 1e-6 absolute) only admits a compiler contracting a * b + c
// differently in the two variants. Measured on lavapipe: max difference 0.
TEST_CASE("effect set: specialized and full pipelines render the same image", "[render][gpu]") {
  auto device = test::makeTestDevice();
  struct Case {
    const char* name;
    scene::Scene scene;
    render::Integrator integrator;
  };
  auto glass = disney();
  glass.specTrans = 1.0f;
  glass.roughness = 0.2f;
  scene::Material mirror;
  mirror.model = scene::MaterialModel::Phong;
  mirror.reflectivity = 0.8f;
  mirror.ks = 0.5f;
  scene::Material phongGlass;
  phongGlass.model = scene::MaterialModel::Phong;
  phongGlass.transparency = 0.9f;
  auto everything = disney();
  everything.specular = 0.5f;
  everything.specTrans = 0.5f;
  everything.clearcoat = 0.5f;
  everything.sheen = 0.5f;
  auto tinted = disney();
  tinted.baseColor = {0.8f, 0.3f, 0.1f};
  tinted.specular = 1.0f;
  tinted.specularColor = {12.5f, 3.0f, 0.2f};
  tinted.roughness = 0.3f;
  // glTF's coat and sheen over a partly metallic, partly transmitting base:
  // the derivation must ask for their bits, or the variant renders Disney's.
  auto gltfLayers = disney();
  gltfLayers.model = scene::MaterialModel::Lambert;
  gltfLayers.metallic = 0.3f;
  gltfLayers.specular = 0.5f;
  gltfLayers.specTrans = 0.3f;
  gltfLayers.clearcoat = 0.8f;
  gltfLayers.clearcoatGloss = 0.7f;
  gltfLayers.sheen = 1.0f;
  gltfLayers.sheenColor = {0.9f, 0.6f, 0.3f};
  gltfLayers.sheenRoughness = 0.4f;
  // A closed sphere that sends part of its diffuse light inside and through:
  // the transmitted share's lobe and its sampling.
  auto leaf = disney();
  leaf.model = scene::MaterialModel::Lambert;
  leaf.baseColor = {0.2f, 0.6f, 0.1f};
  leaf.specular = 0.5f;
  leaf.diffuseTransmission = 0.7f;
  leaf.diffuseTransmissionColor = {0.9f, 0.8f, 0.2f};
  // A film over a plastic and a metal: both layers' Fresnel coloured.
  auto soapy = disney();
  soapy.model = scene::MaterialModel::Lambert;
  soapy.metallic = 0.4f;
  soapy.specular = 0.5f;
  soapy.iridescence = 1.0f;
  soapy.iridescenceThicknessMaximum = 320.0f;
  auto brushed = disney();
  brushed.metallic = 1.0f;
  brushed.roughness = 0.2f;
  brushed.anisotropyStrength = 0.8f;
  brushed.anisotropyRotation = 0.4f;
  // Smooth normals and tangents along the sphere's parallels, so the
  // direction is the mesh's.
  scene::Scene brushedScene = cornellWithSphere(brushed);
  auto& ball = brushedScene.meshes.back();
  for (const glm::vec3& p : ball.positions) {
    const glm::vec3 n = glm::normalize(p);
    ball.normals.push_back(n);
    const glm::vec3 t = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), n);
    ball.tangents.push_back(
        glm::vec4(glm::dot(t, t) > 1e-8f ? glm::normalize(t) : glm::vec3(1.0f, 0.0f, 0.0f), 1.0f));
  }

  // Each distinct pipeline costs lavapipe seconds to compile, so the cases are
  // chosen to cover: the area-light-only Lambert scene, an effect alone with
  // the specular layer compiled out (glass), every effect at once (a bit the
  // derivation forgot would drop its lobe and change the image), and both
  // Whitted branches.
  // The branch features (soft sun, spot, thin lens with blades, absorbing
  // glass) all in one scene: they are no variants, so both pipelines hold
  // them, but the specialized one must still match. The environment and the
  // orthographic camera are variant bits: seen through them.
  auto absorbing = glass;
  absorbing.roughness = 0.0f;
  absorbing.attenuationColor = {0.9f, 0.5f, 0.2f};
  absorbing.attenuationDistance = 0.05f;
  absorbing.dispersion = 0.5f;
  scene::Scene branches = cornellWithSphere(absorbing, true);
  branches.environment = scene::defaultEnvironment();
  scene::PointLight sun;
  sun.type = scene::LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.2f, -0.5f, -1.0f));
  sun.intensity = glm::vec3(2.0f);
  sun.angularRadiusDegrees = 3.0f;
  scene::PointLight spot;
  spot.type = scene::LightType::Spot;
  spot.position = {0.2, 0.5, 0.3};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.innerConeDegrees = 20.0f;
  spot.outerConeDegrees = 35.0f;
  spot.intensity = glm::vec3(0.3f);
  branches.pointLights.push_back(sun);
  branches.pointLights.push_back(spot);
  branches.camera.apertureRadius = 0.01f;
  branches.camera.focusDistance = 0.8f;
  branches.camera.apertureBlades = 6;
  branches.camera.orthographicHeight = 0.5f;
  REQUIRE(render::featureNames(render::deriveFeatures(branches, std::nullopt)) ==
          std::vector<std::string>{"directional-lights", "soft-sun", "spot-lights", "thin-lens",
                                   "lens-blades", "absorption"});
  REQUIRE((render::deriveEffects(branches) & PT_EFFECT_ENVIRONMENT) != 0u);
  REQUIRE((render::deriveEffects(branches) & PT_EFFECT_ORTHOGRAPHIC) != 0u);
  REQUIRE(render::deriveFeatures(scene::loadScene("cornell-box"), std::nullopt) == 0u);

  std::vector<Case> cases = {
      {"cornell box (area light, Lambert)", scene::loadScene("cornell-box"),
       render::Integrator::Path},
      {"rough glass sphere", cornellWithSphere(glass), render::Integrator::Path},
      {"every lobe, point light", cornellWithSphere(everything, true), render::Integrator::Path},
      {"coloured dielectric F0 up to 1", cornellWithSphere(tinted), render::Integrator::Path},
      {"glTF coat and sheen", cornellWithSphere(gltfLayers), render::Integrator::Path},
      {"diffuse transmission", cornellWithSphere(leaf, true), render::Integrator::Path},
      {"iridescence", cornellWithSphere(soapy, true), render::Integrator::Path},
      {"glTF anisotropy (surface detail)", brushedScene, render::Integrator::Path},
      {"Whitted mirror", cornellWithSphere(mirror, true), render::Integrator::Whitted},
      {"Whitted glass", cornellWithSphere(phongGlass, true), render::Integrator::Whitted},
      {"environment, soft sun, spot, bladed lens, absorbing dispersive glass, orthographic",
       branches, render::Integrator::Path},
      {"Whitted under the environment", branches, render::Integrator::Whitted},
  };
  render::PipelineOptions full;
  full.allEffects = true;
  for (const auto& c : cases) {
    INFO(c.name);
    render::PathTracerSettings settings;
    settings.integrator = c.integrator;
    settings.seed = 3;
    render::PathTracer specialized(*device, c.scene, 24, 24);
    REQUIRE(specialized.pipelineEffects() == render::deriveEffects(c.scene));
    specialized.renderFrame(settings, 4);
    render::PathTracer reference(*device, c.scene, 24, 24, full);
    REQUIRE(reference.pipelineEffects() == uint32_t(PT_EFFECTS_ALL));
    reference.renderFrame(settings, 4);
    const auto a = specialized.readback();
    const auto b = reference.readback();
    REQUIRE(image::countNonFinite(a) == 0);
    double maxAbs = 0;
    size_t beyond = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
      const double d = std::abs(double(a.rgba[i]) - double(b.rgba[i]));
      maxAbs = std::max(maxAbs, d);
      if (d > 1e-6 + 1e-5 * std::abs(double(b.rgba[i]))) ++beyond;
    }
    INFO("max |difference| " << maxAbs);
    REQUIRE(beyond == 0);
    // The image is not trivially black: the comparison means something.
    REQUIRE(image::meanRgb(b).g > 0.0);
  }
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}

TEST_CASE(
    "effect set: every built-in scene has its own variant, with guides, an environment or an "
    "orthographic camera",
    "[render]") {
  const uint32_t guides = PT_OUTPUT_GUIDES, environment = PT_EFFECT_ENVIRONMENT,
                 orthographic = PT_EFFECT_ORTHOGRAPHIC;
  for (const std::string& name : scene::builtInSceneNames()) {
    const uint32_t effects = render::deriveEffects(scene::loadScene(name));
    for (uint32_t extra :
         {0u, guides, environment, guides | environment, orthographic, guides | orthographic}) {
      const uint32_t pathTrace = (effects | extra) & PT_PATH_TRACE_EFFECT_BITS;
      INFO(name << ": effects " << (effects | extra));
      // Not a superset: the exact set (shaders/effect_variants.cmake).
      CHECK(render::effectVariant("path_trace.rgen", pathTrace) ==
            (pathTrace == PT_PATH_TRACE_EFFECT_BITS
                 ? std::string("path_trace.rgen")
                 : "path_trace.e" + std::to_string(pathTrace) + ".rgen"));
      // Whitted, no real-time view, has its own sets for the scene as it is
      // and under an environment.
      if (extra & orthographic) continue;
      const uint32_t whitted = (effects | extra) & PT_WHITTED_EFFECT_BITS;
      CHECK(render::effectVariant("whitted.rgen", whitted) ==
            (whitted == PT_WHITTED_EFFECT_BITS ? std::string("whitted.rgen")
                                               : "whitted.e" + std::to_string(whitted) + ".rgen"));
    }
  }
}
