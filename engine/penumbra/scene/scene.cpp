#include "penumbra/scene/scene.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "penumbra/util/error.h"

namespace penumbra::scene {

Material Material::lambert(std::string name, glm::vec3 albedo, glm::vec3 emission) {
  Material m;
  m.name = std::move(name);
  m.model = MaterialModel::Lambert;
  m.baseColor = albedo;
  m.emission = emission;
  m.specular = 0.0f;
  m.roughness = 1.0f;
  return m;
}

namespace {

template <class Fail>
void validateTextures(const Scene& scene, const Fail& fail) {
  for (size_t i = 0; i < scene.textures.size(); ++i) {
    const auto& t = scene.textures[i];
    const uint64_t bytes = uint64_t(t.width) * t.height * 4;
    if (t.width == 0 || t.height == 0 || t.rgba8.size() != bytes)
      fail(fmt::format("texture {} '{}' is {} x {} but has {} bytes of RGBA8 (expected {})", i,
                       t.name, t.width, t.height, t.rgba8.size(), bytes));
  }
  for (size_t i = 0; i < scene.textureRefs.size(); ++i) {
    const auto& r = scene.textureRefs[i];
    if (r.texture >= scene.textures.size())
      fail(fmt::format("texture reference {} uses texture {} of {}", i, r.texture,
                       scene.textures.size()));
    if (r.texCoord > 1)
      fail(fmt::format("texture reference {} reads texture coordinate set {} (0 or 1)", i,
                       r.texCoord));
    for (glm::vec2 c : {r.transform0, r.transform1, r.transform2})
      if (!std::isfinite(c.x) || !std::isfinite(c.y))
        fail(fmt::format("texture reference {} has a non-finite texture transform", i));
  }
}

}  // namespace

uint64_t Scene::triangleCount() const {
  uint64_t n = 0;
  for (const auto& inst : instances) n += meshes.at(inst.mesh).triangleCount();
  return n;
}

uint64_t Scene::meshBytes() const {
  uint64_t bytes = 0;
  for (const auto& m : meshes)
    bytes += m.positions.size() * sizeof(glm::vec3) + m.indices.size() * sizeof(uint32_t) +
             m.normals.size() * sizeof(glm::vec3) + m.tangents.size() * sizeof(glm::vec4) +
             (m.uv0.size() + m.uv1.size()) * sizeof(glm::vec2) +
             m.colors.size() * sizeof(glm::vec4);
  return bytes;
}

// Here rather than in environment.cpp, which reads image files: the glTF
// loader's sanitizer build links scene.cpp without the image readers.
void validateEnvironment(const Environment& env) {
  if (!env.present()) return;
  // 2^27 texels at most, the largest equirectangular map being 16384x8192:
  // 16 bytes each is a 2 GiB buffer, and 2^27 elements is D3D12's largest
  // buffer view (D3D12_REQ_BUFFER_RESOURCE_TEXEL_COUNT_2_TO_EXP).
  if (env.width > kMaxEnvironmentWidth || env.height > kMaxEnvironmentWidth ||
      uint64_t(env.width) * env.height > kMaxEnvironmentTexels)
    throw Error(fmt::format("environment '{}': {}x{} texels is more than 16384x8192 ({} texels)",
                            env.source, env.width, env.height, kMaxEnvironmentTexels));
  if (env.radiance.size() != size_t(env.width) * env.height)
    throw Error(fmt::format("environment '{}': {} texels for a {}x{} map", env.source,
                            env.radiance.size(), env.width, env.height));
  if (!std::isfinite(env.rotationDegrees))
    throw Error(fmt::format("environment '{}': the rotation is not finite", env.source));
  if (!(env.intensity >= 0.0f) || !std::isfinite(env.intensity))
    throw Error(fmt::format("environment '{}': intensity {} is not a finite number >= 0",
                            env.source, env.intensity));
  for (size_t i = 0; i < env.radiance.size(); ++i) {
    const glm::vec3 r = env.radiance[i];
    for (int k = 0; k < 3; ++k)
      if (!(r[k] >= 0.0f) || !std::isfinite(r[k]))
        throw Error(
            fmt::format("environment '{}': texel ({}, {}) holds {}, not a finite radiance >= 0",
                        env.source, i % env.width, i / env.width, r[k]));
  }
}

namespace {
// Whether a drawn material (on an instance or an implicit object) passes.
template <class Pred>
bool anyDrawnMaterial(const Scene& scene, Pred pred) {
  for (const auto& inst : scene.instances)
    if (pred(scene.materials.at(scene.meshes.at(inst.mesh).material))) return true;
  for (const auto& object : scene.implicits)
    if (pred(scene.materials.at(object.material))) return true;
  return false;
}
}  // namespace

bool Scene::hasOwnLighting() const {
  return !pointLights.empty() || anyDrawnMaterial(*this, [](const Material& m) {
    return m.emissionIsLighting && m.isEmissive();
  });
}

bool Scene::hasEmitters() const {
  return anyDrawnMaterial(*this, [](const Material& m) { return m.isEmissive(); });
}

float apertureRadiusForFNumber(float fNumber, float verticalFovDegrees) {
  const double focalLength = 0.012 / std::tan(glm::radians(double(verticalFovDegrees)) * 0.5);
  return float(focalLength / (2.0 * fNumber));
}

bool sameFilm(const Camera& a, const Camera& b) {
  return a.orthographicHeight == b.orthographicHeight && a.aspectRatio == b.aspectRatio &&
         (a.orthographic() || a.verticalFovDegrees == b.verticalFovDegrees);
}

void validateCamera(const Camera& camera) {
  // Bounded so that the film's corners stay far from float's overflow.
  if (!(camera.orthographicHeight >= 0.0f && camera.orthographicHeight <= 1e9f))
    throw Error(fmt::format(
        "camera: orthographic height {} must be finite, >= 0 and at most 1e9 (0: perspective)",
        camera.orthographicHeight));
  if (!(camera.aspectRatio >= 0.0f) || !std::isfinite(camera.aspectRatio))
    throw Error(fmt::format("camera: aspect ratio {} must be finite and >= 0 (0: none)",
                            camera.aspectRatio));
  if (!(camera.apertureRadius >= 0.0f) || !std::isfinite(camera.apertureRadius))
    throw Error(fmt::format("camera: aperture radius {} must be finite and >= 0 (0: pinhole)",
                            camera.apertureRadius));
  if (camera.apertureBlades != 0 && (camera.apertureBlades < 3 || camera.apertureBlades > 32))
    throw Error(fmt::format("camera: {} aperture blades; 0 (round) or 3..32 expected",
                            camera.apertureBlades));
  if (camera.apertureRadius > 0.0f &&
      (!(camera.focusDistance > 0.0f) || !std::isfinite(camera.focusDistance)))
    throw Error(
        fmt::format("camera: focus distance {} must be finite and > 0", camera.focusDistance));
}

namespace {

// A mesh's indices, material and vertex attributes (counts and finiteness).
template <class Fail>
void validateMesh(const Mesh& mesh, const Scene& scene, const Fail& fail) {
  if (mesh.material >= scene.materials.size())
    fail(fmt::format("mesh '{}' uses material {} of {}", mesh.name, mesh.material,
                     scene.materials.size()));
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
    fail(fmt::format("mesh '{}' has {} indices, not a positive multiple of 3", mesh.name,
                     mesh.indices.size()));
  for (uint32_t i : mesh.indices)
    if (i >= mesh.positions.size())
      fail(fmt::format("mesh '{}' has index {} but {} vertices", mesh.name, i,
                       mesh.positions.size()));
  for (const auto& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(fmt::format("mesh '{}' has a non-finite vertex position", mesh.name));
  auto checkAttribute = [&](size_t count, bool finite, const char* what) {
    if (count != 0 && count != mesh.positions.size())
      fail(fmt::format("mesh '{}' has {} {} for {} vertices", mesh.name, count, what,
                       mesh.positions.size()));
    if (!finite) fail(fmt::format("mesh '{}' has non-finite {}", mesh.name, what));
  };
  auto finite = [](const auto& values) {
    for (const auto& v : values)
      for (int i = 0; i < v.length(); ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
  };
  checkAttribute(mesh.normals.size(), finite(mesh.normals), "normals");
  checkAttribute(mesh.tangents.size(), finite(mesh.tangents), "tangents");
  checkAttribute(mesh.uv0.size(), finite(mesh.uv0), "texture coordinates");
  checkAttribute(mesh.uv1.size(), finite(mesh.uv1), "second texture coordinates");
  checkAttribute(mesh.colors.size(), finite(mesh.colors), "vertex colours");
  for (const auto& c : mesh.colors)
    for (int i = 0; i < 4; ++i)
      if (!(c[i] >= 0.0f && c[i] <= 1.0f))
        fail(fmt::format("mesh '{}' has a vertex colour component {} outside [0, 1]", mesh.name,
                         c[i]));
}

// A material's parameters in their ranges, its texture references in the scene.
template <class Fail>
void validateMaterial(const Material& m, const Scene& scene, const Fail& fail) {
  auto unit = [](float v) { return v >= 0.0f && v <= 1.0f; };
  for (int i = 0; i < 3; ++i)
    if (!unit(m.baseColor[i]) || !(m.emission[i] >= 0.0f) || !std::isfinite(m.emission[i]))
      fail(fmt::format(
          "material '{}': baseColor must lie in [0, 1] and emission be finite and non-negative",
          m.name));
  for (float v : {m.metallic, m.roughness, m.anisotropic, m.specular, m.specularTint, m.sheen,
                  m.sheenTint, m.clearcoat, m.clearcoatGloss, m.specTrans, m.subsurface,
                  m.reflectivity, m.transparency, m.anisotropyStrength, m.sheenRoughness,
                  m.diffuseTransmission, m.specularF90, m.iridescence})
    if (!unit(v)) fail(fmt::format("material '{}': a parameter is outside [0, 1]", m.name));
  for (int i = 0; i < 3; ++i)
    if (!unit(m.sheenColor[i]))
      fail(fmt::format("material '{}': sheenColor must lie in [0, 1]", m.name));
  for (int i = 0; i < 3; ++i)
    if (!unit(m.diffuseTransmissionColor[i]))
      fail(fmt::format("material '{}': diffuseTransmissionColor must lie in [0, 1]", m.name));
  for (int i = 0; i < 3; ++i)
    if (!(m.specularColor[i] >= 0.0f) || !std::isfinite(m.specularColor[i]))
      fail(fmt::format("material '{}': specularColor must be finite and non-negative", m.name));
  if (!(m.iridescenceIor >= 1.0f && m.iridescenceIor <= 4.0f))
    fail(fmt::format("material '{}': iridescenceIor must lie in [1, 4]", m.name));
  if (!(m.iridescenceThicknessMinimum >= 0.0f && m.iridescenceThicknessMaximum >= 0.0f &&
        m.iridescenceThicknessMaximum <= 1e5f && m.iridescenceThicknessMinimum <= 1e5f))
    fail(fmt::format("material '{}': iridescence thicknesses must lie in [0, 1e5] nm", m.name));
  // Abbe number 2: ten times the strongest common glass's spread of indices.
  if (!(m.dispersion >= 0.0f && m.dispersion <= 10.0f))
    fail(fmt::format("material '{}': dispersion must lie in [0, 10]", m.name));
  if (!std::isfinite(m.anisotropyRotation))
    fail(fmt::format("material '{}': anisotropyRotation is not finite", m.name));
  if (!(m.ior >= 1.0f && m.ior <= 4.0f))
    fail(fmt::format("material '{}': ior {} is outside [1, 4]", m.name, m.ior));
  if (!(m.exponent >= 0.0f)) fail(fmt::format("material '{}': negative Phong exponent", m.name));
  for (int i = 0; i < 3; ++i)
    if (!unit(m.attenuationColor[i]))
      fail(fmt::format("material '{}': attenuationColor must lie in [0, 1]", m.name));
  if (!(m.attenuationDistance > 0.0f))
    fail(fmt::format("material '{}': attenuationDistance {} must be > 0", m.name,
                     m.attenuationDistance));
  for (uint32_t ref : m.textures())
    if (ref != Material::kNoTexture && ref >= scene.textureRefs.size())
      fail(fmt::format("material '{}' uses texture reference {} of {}", m.name, ref,
                       scene.textureRefs.size()));
  if (!std::isfinite(m.normalScale) || !std::isfinite(m.clearcoatNormalScale) ||
      !unit(m.occlusionStrength) || !unit(m.alpha) ||
      !(m.alphaCutoff >= 0.0f && std::isfinite(m.alphaCutoff)))
    fail(
        fmt::format("material '{}': normalScale and clearcoatNormalScale must be finite, "
                    "occlusionStrength and alpha lie in [0, 1] and alphaCutoff be finite and "
                    "non-negative",
                    m.name));
}

}  // namespace

void validate(const Scene& scene) {
  auto fail = [&](const std::string& what) {
    throw Error(fmt::format("scene '{}': {}", scene.name, what));
  };
  validateCamera(scene.camera);
  if (scene.meshes.empty() && scene.implicits.empty())
    fail("has no geometry (neither meshes nor implicit objects)");
  for (const auto& mesh : scene.meshes) validateMesh(mesh, scene, fail);
  validateTextures(scene, fail);
  try {
    validateEnvironment(scene.environment);
  } catch (const Error& e) {
    fail(e.what());
  }
  for (const auto& light : scene.pointLights) {
    if (!(light.angularRadiusDegrees >= 0.0f && light.angularRadiusDegrees < 90.0f))
      fail(fmt::format("a directional light's angular radius {} is outside [0, 90) degrees",
                       light.angularRadiusDegrees));
    // A value past float's range became infinity on the way in.
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(light.intensity[i]) || !std::isfinite(light.position[i]))
        fail("a light's intensity or position is not finite");
  }
  for (const auto& m : scene.materials) validateMaterial(m, scene, fail);
  for (const auto& object : scene.implicits) {
    try {
      validateImplicit(object, scene.materials.size());
    } catch (const Error& e) {
      fail(e.what());
    }
  }
  for (const auto& inst : scene.instances)
    if (inst.mesh >= scene.meshes.size())
      fail(fmt::format("an instance refers to mesh {} of {}", inst.mesh, scene.meshes.size()));
  for (const auto& variant : scene.materialVariants)
    for (const auto& [mesh, material] : variant.meshMaterials)
      if (mesh >= scene.meshes.size() || material >= scene.materials.size())
        fail(fmt::format("material variant '{}' gives mesh {} of {} material {} of {}",
                         variant.name, mesh, scene.meshes.size(), material,
                         scene.materials.size()));
  const auto& c = scene.camera;
  if (!(c.verticalFovDegrees > 0.0f && c.verticalFovDegrees < 180.0f))
    fail(fmt::format("camera vertical field of view {} is not in (0, 180)", c.verticalFovDegrees));
  // Written so that NaN fails too (a normalised zero vector is NaN).
  if (!(glm::length(c.forward) > 0.0f) || !(glm::length(glm::cross(c.forward, c.up)) > 0.0f) ||
      !std::isfinite(glm::length(c.forward)) || !std::isfinite(glm::length(c.up)))
    fail("camera forward and up must be non-zero, finite and not parallel");
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c.position[i])) fail("camera position is not finite");
}

void selectMaterialVariant(Scene& scene, const std::string& name) {
  const MaterialVariant* chosen = nullptr;
  for (const auto& v : scene.materialVariants)
    if (v.name == name) chosen = &v;
  size_t index = 0;
  const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), index);
  if (!chosen && ec == std::errc() && end == name.data() + name.size() && !name.empty() &&
      index < scene.materialVariants.size())
    chosen = &scene.materialVariants[index];
  if (!chosen) {
    std::string names;
    for (size_t i = 0; i < scene.materialVariants.size(); ++i)
      names +=
          fmt::format("{}{} '{}'", names.empty() ? "" : ", ", i, scene.materialVariants[i].name);
    throw Error(fmt::format("scene '{}': no material variant '{}' ({})", scene.name, name,
                            names.empty() ? "the scene has no material variants"
                                          : "variants by index and name: " + names));
  }
  for (const auto& [mesh, material] : chosen->meshMaterials)
    scene.meshes.at(mesh).material = material;
}

void selectCamera(Scene& scene, const std::string& name) {
  for (const auto& c : scene.cameras)
    if (c.name == name || (!c.nodeName.empty() && c.nodeName == name)) {
      scene.camera = c.camera;
      return;
    }
  // A number that names no camera is an index: unnamed cameras have no
  // other handle.
  size_t index = 0;
  const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), index);
  if (ec == std::errc() && end == name.data() + name.size() && !name.empty() &&
      index < scene.cameras.size()) {
    scene.camera = scene.cameras[index].camera;
    return;
  }
  std::string names;
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    const NamedCamera& c = scene.cameras[i];
    std::string shown = c.name.empty() ? "" : fmt::format("'{}'", c.name);
    if (!c.nodeName.empty())
      shown += c.name.empty() ? fmt::format("node '{}'", c.nodeName)
                              : fmt::format(" (node '{}')", c.nodeName);
    if (shown.empty()) shown = "(unnamed)";
    names += fmt::format("{}{} {}", names.empty() ? "" : ", ", i, shown);
  }
  throw Error(fmt::format(
      "scene '{}': no camera named '{}' ({})", scene.name, name,
      names.empty() ? "the scene names no cameras" : "cameras by index and name: " + names));
}

}  // namespace penumbra::scene
