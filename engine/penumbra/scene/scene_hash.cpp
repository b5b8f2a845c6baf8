#include "penumbra/scene/scene_hash.h"

#include <variant>

#include "penumbra/util/content_hash.h"
#include "penumbra/util/field_count.h"

namespace penumbra::scene {
namespace {

// Each struct's fields are hashed one by one (padding bytes are not
// content). The field counts catch a field added without being hashed here,
// padding or not, on every compiler: when one fails, hash the new field,
// then update the count.
// Material::emissionIsLighting only decides whether the default environment
// is added, and the environment is hashed: not hashed.
static_assert(fieldCount<Material>() == 61, "a Material field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<Mesh>() == 9, "a Mesh field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<Camera>() == 9, "a Camera field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<PointLight>() == 8, "a PointLight field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<TextureRef>() == 6, "a TextureRef field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<TextureSampler>() == 5, "a sampler field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<Texture>() == 5, "a Texture field is not hashed (scene_hash.cpp)");
static_assert(fieldCount<ImplicitObject>() == 5, "an ImplicitObject field is not hashed");
static_assert(fieldCount<SphereTracing>() == 2, "a SphereTracing field is not hashed");
static_assert(fieldCount<Instance>() == 2, "an Instance field is not hashed (scene_hash.cpp)");
// Environment::source only names where the map came from: not hashed.
static_assert(fieldCount<Environment>() == 7,
              "an Environment field is not hashed (scene_hash.cpp)");

void hashMaterial(ContentHash& h, const Material& m) {
  h.text(m.name);
  h.value(m.model);
  h.value(m.baseColor);
  h.value(m.emission);
  for (float v : {m.metallic, m.roughness, m.anisotropic, m.specular, m.specularTint, m.sheen,
                  m.sheenTint, m.clearcoat, m.clearcoatGloss, m.specTrans, m.ior, m.subsurface})
    h.value(v);
  h.value(m.specularColor);
  h.value(m.sheenColor);
  h.value(m.sheenRoughness);
  h.value(m.diffuseTransmission);
  h.value(m.specularF90);
  h.value(m.diffuseTransmissionColor);
  for (float v : {m.iridescence, m.iridescenceIor, m.iridescenceThicknessMinimum,
                  m.iridescenceThicknessMaximum, m.dispersion})
    h.value(v);
  h.value(m.anisotropyStrength);
  h.value(m.anisotropyRotation);
  h.value(m.thin);
  h.value(m.attenuationColor);
  h.value(m.attenuationDistance);
  for (float v : {m.ks, m.exponent, m.reflectivity, m.transparency}) h.value(v);
  for (uint32_t t : m.textures()) h.value(t);
  for (float v : {m.normalScale, m.occlusionStrength, m.alpha, m.clearcoatNormalScale}) h.value(v);
  h.value(m.alphaMode);
  h.value(m.alphaCutoff);
}

void hashCamera(ContentHash& h, const Camera& c) {
  h.value(c.position);
  h.value(c.forward);
  h.value(c.up);
  for (float v : {c.verticalFovDegrees, c.orthographicHeight, c.aspectRatio, c.apertureRadius,
                  c.focusDistance})
    h.value(v);
  h.value(c.apertureBlades);
}

void hashShape(ContentHash& h, const ImplicitShape& shape) {
  h.value(uint32_t(shape.index()));
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, implicit::Sphere>) {
          h.value(s.radius);
        } else if constexpr (std::is_same_v<T, implicit::Plane>) {
          h.value(s.halfExtents.has_value());
          if (s.halfExtents) h.value(*s.halfExtents);
        } else if constexpr (std::is_same_v<T, implicit::Box>) {
          h.value(s.halfExtents);
        } else if constexpr (std::is_same_v<T, implicit::Torus>) {
          h.value(s.majorRadius);
          h.value(s.minorRadius);
        } else if constexpr (std::is_same_v<T, implicit::RoundedBox>) {
          h.value(s.halfExtents);
          h.value(s.cornerRadius);
        } else if constexpr (std::is_same_v<T, implicit::Blend>) {
          h.value(uint64_t(s.primitives.size()));
          for (const auto& p : s.primitives) {
            // A blend's primitives are the simple shapes: hashed as shapes.
            std::visit([&](const auto& inner) { hashShape(h, ImplicitShape(inner)); }, p.shape);
            h.value(p.offset);
          }
          h.value(s.blendRadius);
        } else {
          static_assert(std::is_same_v<T, implicit::Mandelbulb>, "an implicit shape is not hashed");
          h.value(s.power);
          h.value(s.iterations);
        }
      },
      shape);
}

}  // namespace

std::string contentHash(const Scene& scene) {
  ContentHash h;
  h.value(uint64_t(scene.materials.size()));
  for (const auto& m : scene.materials) hashMaterial(h, m);
  h.value(uint64_t(scene.textures.size()));
  for (const auto& t : scene.textures) {
    h.text(t.name);
    h.value(t.width);
    h.value(t.height);
    h.array(t.rgba8);
    h.value(t.srgb);
  }
  h.value(uint64_t(scene.textureRefs.size()));
  for (const auto& r : scene.textureRefs) {
    h.value(r.texture);
    h.value(r.sampler.magFilter);
    h.value(r.sampler.minFilter);
    h.value(r.sampler.mipFilter);
    h.value(r.sampler.wrapU);
    h.value(r.sampler.wrapV);
    h.value(r.texCoord);
    h.value(r.transform0);
    h.value(r.transform1);
    h.value(r.transform2);
  }
  h.value(uint64_t(scene.meshes.size()));
  for (const auto& m : scene.meshes) {
    h.text(m.name);
    h.array(m.positions);
    h.array(m.indices);
    h.value(m.material);
    h.array(m.normals);
    h.array(m.tangents);
    h.array(m.uv0);
    h.array(m.uv1);
    h.array(m.colors);
  }
  h.value(uint64_t(scene.instances.size()));
  for (const auto& i : scene.instances) {
    h.value(i.mesh);
    h.value(i.transform);
  }
  h.value(uint64_t(scene.implicits.size()));
  for (const auto& o : scene.implicits) {
    h.text(o.name);
    hashShape(h, o.shape);
    h.value(o.transform);
    h.value(o.material);
    h.value(o.sphereTracing.maxSteps);
    h.value(o.sphereTracing.tolerance);
  }
  h.value(uint64_t(scene.pointLights.size()));
  for (const auto& l : scene.pointLights) {
    h.value(l.type);
    h.value(l.position);
    h.value(l.intensity);
    h.value(l.direction);
    for (float v : {l.innerConeDegrees, l.outerConeDegrees, l.range, l.angularRadiusDegrees})
      h.value(v);
  }
  const Environment& e = scene.environment;
  h.value(e.width);
  h.value(e.height);
  h.array(e.radiance);
  h.value(e.rotationDegrees);
  h.value(e.intensity);
  h.value(e.visibleBackground);
  h.value(scene.ambient);
  hashCamera(h, scene.camera);
  return h.hex();
}

}  // namespace penumbra::scene
