#pragma once
// The API-neutral scene: meshes with materials, instances, a camera. Units are
// metres once loaded (scene files may state a unitScale).
#include <array>
#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/environment.h"
#include "penumbra/scene/implicit_object.h"

namespace penumbra::scene {

// A decoded image, 8 bits per channel RGBA, rows top to bottom (glTF's uv
// (0, 0) is the first texel).
struct Texture {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;  // width * height * 4 bytes
  // The channels hold sRGB-encoded colour (base colour, emission): the GPU
  // decodes them to linear when sampling. Data textures (metallic-roughness,
  // normal, occlusion) are linear. An image used both ways becomes two.
  bool srgb = false;
};

// How a texture is filtered and wrapped (glTF samplers). Within a level,
// nearest or linear; between the mip levels a ray's footprint picks, none
// (level 0 only), the nearest level or a blend of the two (glTF's minFilter:
// NEAREST and LINEAR have none, *_MIPMAP_NEAREST nearest, *_MIPMAP_LINEAR and
// no filter at all a blend).
enum class TextureFilter { Nearest, Linear };
enum class MipFilter { None, Nearest, Linear };
enum class TextureWrap { Repeat, MirroredRepeat, ClampToEdge };
struct TextureSampler {
  TextureFilter magFilter = TextureFilter::Linear;
  TextureFilter minFilter = TextureFilter::Linear;
  MipFilter mipFilter = MipFilter::Linear;
  TextureWrap wrapU = TextureWrap::Repeat;
  TextureWrap wrapV = TextureWrap::Repeat;
  bool operator==(const TextureSampler&) const = default;
};

// One use of a texture by a material: which image, how it is sampled, and
// the texture coordinates it reads (KHR_texture_transform applied to the
// chosen set: uv' = transform * (u, v, 1)).
struct TextureRef {
  uint32_t texture = 0;  // index into Scene::textures
  TextureSampler sampler;
  uint32_t texCoord = 0;  // TEXCOORD_0 or TEXCOORD_1
  // Columns of the 3x2 affine transform: uv' = c0 * u + c1 * v + c2.
  glm::vec2 transform0{1.0f, 0.0f};
  glm::vec2 transform1{0.0f, 1.0f};
  glm::vec2 transform2{0.0f, 0.0f};
};

// glTF alpha modes: how the base colour's alpha cuts the surface.
enum class AlphaMode { Opaque, Mask, Blend };

// Which shading model a material uses (docs/materials.md).
enum class MaterialModel {
  Disney,   // the principled BSDF with Burley diffuse
  Lambert,  // Disney parameters, but Lambertian diffuse (glTF, the Cornell box)
  Phong,    // Whitted's Phong model; the path tracer maps it onto Disney
  Unlit,    // glTF KHR_materials_unlit: baseColor is the radiance seen; it reflects no light
};

struct Material {
  std::string name;
  MaterialModel model = MaterialModel::Disney;
  glm::vec3 baseColor{0.8f};
  glm::vec3 emission{0.0f};  // radiance from the counter-clockwise face
  // Disney (Burley 2012/2015).
  float metallic = 0.0f;
  float roughness = 0.5f;
  float anisotropic = 0.0f;
  float specular = 0.5f;
  float specularTint = 0.0f;
  // Multiplies the dielectric F0 per channel before it is clamped to 1:
  // F0 = specular * min(0.08 * lerp(1, tint, specularTint) * specularColor, 1).
  // glTF's KHR_materials_specular colour lands here (times F0(ior) / 0.08).
  glm::vec3 specularColor{1.0f};
  // The dielectric layer's grazing reflectance is at most this (glTF's
  // KHR_materials_specular: F90 = specularFactor); 1 keeps Schlick's F90 = 1.
  float specularF90 = 1.0f;
  float sheen = 0.0f;
  float sheenTint = 0.5f;
  // Multiplies the sheen per channel, in [0, 1] (glTF's sheen colour is
  // sheen = its largest channel, sheenColor = colour / sheen).
  glm::vec3 sheenColor{1.0f};
  // The Lambert model's sheen is glTF's (KHR_materials_sheen: Charlie fibres
  // of this roughness, in [0, 1]); Disney's sheen has no roughness.
  float sheenRoughness = 0.0f;
  float clearcoat = 0.0f;
  float clearcoatGloss = 1.0f;
  float specTrans = 0.0f;
  // KHR_materials_diffuse_transmission: this share of the diffuse lobe
  // passes to the other side as Lambertian transmission of this colour
  // (leaves, paper, lamp shades); the rest reflects with baseColor.
  float diffuseTransmission = 0.0f;
  glm::vec3 diffuseTransmissionColor{1.0f};
  float ior = 1.5f;
  float subsurface = 0.0f;
  // KHR_materials_iridescence: a thin film of index iridescenceIor over the
  // specular layer turns its reflectance into the film's interference
  // colours (soap bubbles, oil, anodised metal), by this share. Its
  // thickness in nanometres is the maximum, or with iridescenceThicknessTexture
  // lerp(minimum, maximum, the texture's green); 0 is no film.
  float iridescence = 0.0f;
  float iridescenceIor = 1.3f;
  float iridescenceThicknessMinimum = 100.0f;
  float iridescenceThicknessMaximum = 400.0f;
  // KHR_materials_dispersion: 20 / Abbe number. A refracting volume (specTrans
  // > 0, not thin) bends each wavelength by its own index, Cauchy's law
  // through `ior` at 587.6 nm; 0 is none, 1 (Abbe 20) about the strongest of
  // common materials, crown glass 0.33, diamond 0.36.
  float dispersion = 0.0f;
  // KHR_materials_anisotropy: along the direction `anisotropyRotation`
  // radians from the tangent towards the bitangent, the GGX alpha grows from
  // roughness^2 to lerp(roughness^2, 1, anisotropyStrength^2); across it
  // stays. (Disney's `anisotropic` stretches both ways; the two compose.)
  float anisotropyStrength = 0.0f;
  float anisotropyRotation = 0.0f;
  bool thin = false;
  // The medium inside a transmissive solid (KHR_materials_volume): light
  // that travels attenuationDistance through it keeps attenuationColor of
  // itself (Beer-Lambert); an infinite distance is a clear medium.
  glm::vec3 attenuationColor{1.0f};
  float attenuationDistance = std::numeric_limits<float>::infinity();
  // Phong (Whitted): kd = baseColor.
  float ks = 0.0f;
  float exponent = 32.0f;
  float reflectivity = 0.0f;
  float transparency = 0.0f;

  // Textures (glTF), each an index into Scene::textureRefs or none. Each
  // multiplies its factor above: base colour (rgb; alpha for alphaMode),
  // metallic (blue) and roughness (green), emission (rgb).
  static constexpr uint32_t kNoTexture = 0xffffffffu;
  uint32_t baseColorTexture = kNoTexture;
  uint32_t metallicRoughnessTexture = kNoTexture;
  uint32_t normalTexture = kNoTexture;  // tangent space, scaled xy by normalScale
  uint32_t emissiveTexture = kNoTexture;
  uint32_t occlusionTexture = kNoTexture;  // red channel; only Whitted's ambient term uses it
  // The KHR_materials_* textures (docs/materials.md), each multiplying the
  // parameter its factor became: clearcoat by red, the coat's roughness by
  // green (clearcoatGloss follows), specTrans by the transmission's red,
  // sheenColor by the sheen colour texture (rgb), sheenRoughness by the sheen
  // roughness texture's alpha, specular and specularF90 by the specular texture's alpha,
  // specularColor by the specular colour texture (rgb).
  uint32_t clearcoatTexture = kNoTexture;
  uint32_t clearcoatRoughnessTexture = kNoTexture;
  uint32_t transmissionTexture = kNoTexture;
  uint32_t sheenColorTexture = kNoTexture;  // sRGB
  uint32_t sheenRoughnessTexture = kNoTexture;
  uint32_t specularTexture = kNoTexture;
  uint32_t specularColorTexture = kNoTexture;  // sRGB
  // Red and green: the anisotropy direction in tangent space ([0, 1] for
  // [-1, 1]), turned further by anisotropyRotation; blue scales the strength.
  uint32_t anisotropyTexture = kNoTexture;
  // KHR_materials_clearcoat's own normal map (tangent space, xy scaled by
  // clearcoatNormalScale). Without it the glTF coat follows the vertex
  // normal, not the base's normal map (the extension says so).
  uint32_t clearcoatNormalTexture = kNoTexture;
  float clearcoatNormalScale = 1.0f;
  // Alpha scales diffuseTransmission; rgb (sRGB) diffuseTransmissionColor.
  uint32_t diffuseTransmissionTexture = kNoTexture;
  uint32_t diffuseTransmissionColorTexture = kNoTexture;
  // Red scales iridescence; green picks the film's thickness (above).
  uint32_t iridescenceTexture = kNoTexture;
  uint32_t iridescenceThicknessTexture = kNoTexture;
  float normalScale = 1.0f;
  float occlusionStrength = 1.0f;
  float alpha = 1.0f;  // base colour alpha factor
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  // Whether this material's emission is part of the scene's lighting
  // (Scene::hasOwnLighting). A glTF file's emissive material is a label, a
  // screen or a lamp's glow: drawn and sampled like any emitter, but it does
  // not keep the default environment away (every glTF viewer lights such a
  // file), whether the glTF file is loaded alone or merged into a scene file
  // ("gltf"). Materials a scene file declares itself, and built-in scenes'
  // emitters, are the scene's lights.
  bool emissionIsLighting = true;

  bool isEmissive() const { return emission.x > 0 || emission.y > 0 || emission.z > 0; }
  // Every texture slot above, for code that treats them alike (validation,
  // merging scenes, hashing, the textures' effect bit).
  std::array<uint32_t, 18> textures() const {
    return {baseColorTexture,
            metallicRoughnessTexture,
            normalTexture,
            emissiveTexture,
            occlusionTexture,
            clearcoatTexture,
            clearcoatRoughnessTexture,
            transmissionTexture,
            sheenColorTexture,
            sheenRoughnessTexture,
            specularTexture,
            specularColorTexture,
            anisotropyTexture,
            clearcoatNormalTexture,
            diffuseTransmissionTexture,
            diffuseTransmissionColorTexture,
            iridescenceTexture,
            iridescenceThicknessTexture};
  }
  std::array<uint32_t*, 18> textureSlots() {
    return {&baseColorTexture,
            &metallicRoughnessTexture,
            &normalTexture,
            &emissiveTexture,
            &occlusionTexture,
            &clearcoatTexture,
            &clearcoatRoughnessTexture,
            &transmissionTexture,
            &sheenColorTexture,
            &sheenRoughnessTexture,
            &specularTexture,
            &specularColorTexture,
            &anisotropyTexture,
            &clearcoatNormalTexture,
            &diffuseTransmissionTexture,
            &diffuseTransmissionColorTexture,
            &iridescenceTexture,
            &iridescenceThicknessTexture};
  }
  // A Lambertian surface of the given reflectance (no specular layer).
  static Material lambert(std::string name, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f));
};

enum class LightType { Point, Spot, Directional };

// A delta light for NEE and Whitted: a point, spot or directional light
// (scene files' "lights", glTF's KHR_lights_punctual).
struct PointLight {
  LightType type = LightType::Point;
  glm::dvec3 position{0.0};   // double, as every world placement (Instance); not directional
  glm::vec3 intensity{1.0f};  // radiant intensity, W/sr per channel; directional: irradiance, W/m^2
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way a spot faces, a directional light travels
  float innerConeDegrees = 180.0f;         // spot: full intensity within, falling off to outer
  float outerConeDegrees = 180.0f;
  float range = 0.0f;  // point and spot: no light beyond this distance (0: unlimited)
  // Directional: the sun's angular radius (0: a delta light; more: a soft
  // sun, a disk of that radius whose irradiance is `intensity`).
  float angularRadiusDegrees = 0.0f;
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise = front
  uint32_t material = 0;
  // Optional per-vertex attributes: each is empty or has one entry per
  // position. Without normals the renderer shades with the geometric normal.
  std::vector<glm::vec3> normals;   // unit, object space
  std::vector<glm::vec4> tangents;  // xyz unit, w = +-1: bitangent = cross(normal, xyz) * w
  std::vector<glm::vec2> uv0;       // glTF convention: (0, 0) is the image's top-left corner
  std::vector<glm::vec2> uv1;       // TEXCOORD_1, as uv0
  std::vector<glm::vec4>
      colors;  // COLOR_0, linear RGBA in [0, 1]: multiplies the base colour and alpha
  uint32_t triangleCount() const { return uint32_t(indices.size() / 3); }
};

// World placements (instance and implicit-object transforms, camera and light
// positions) are double: a scene may sit far from the origin (georeferenced
// data, large levels), and the renderer moves the world to the camera in
// double before anything becomes float (docs/ARCHITECTURE.md, "Precision").
struct Instance {
  uint32_t mesh = 0;
  glm::dmat4 transform{1.0};  // object to world
};

struct Camera {
  glm::dvec3 position{0.0};
  glm::vec3 forward{0.0f, 0.0f, 1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float verticalFovDegrees = 45.0f;  // perspective
  // > 0: an orthographic camera, its view this tall (world units) and as wide
  // as the image's shape makes it: rays leave the film plane through
  // `position` in parallel along forward, and verticalFovDegrees is not used.
  // 0: perspective, rays fan out from `position`.
  float orthographicHeight = 0.0f;
  // The width / height of the frame the field of view was chosen for (as
  // glTF's aspectRatio). 0: none, the vertical field of view holds at every
  // image aspect. Otherwise an image narrower than this keeps the frame's
  // horizontal field of view instead (and shows more above and below), so a
  // scene's content stays in view at any window shape; a wider one keeps
  // the vertical field of view (and shows more at the sides).
  float aspectRatio = 0.0f;
  // A thin lens: rays leave a disk of this radius (world units) about the
  // position and meet again on the plane `focusDistance` ahead along
  // forward, which is in focus. 0: a pinhole, everything sharp.
  float apertureRadius = 0.0f;
  float focusDistance = 1.0f;
  // The aperture's blades: 0 a round aperture, 3..32 a regular polygon of
  // that many straight sides inscribed in the radius (bokeh takes its shape).
  uint32_t apertureBlades = 0;

  bool orthographic() const { return orthographicHeight > 0.0f; }
};

// Whether two cameras have the same film: projection, field of view or
// orthographic height, and frame shape (they may stand and look anywhere).
bool sameFilm(const Camera& a, const Camera& b);

// The material-test row (scene/material_row.h): which materials belong to
// its spheres, the base they share and the Disney parameter they vary.
struct MaterialRow {
  Material base;
  std::string vary;
  std::vector<uint32_t> materials;  // one per sphere, first to last
};

// A camera a scene file names (glTF cameras), selectable by name.
struct NamedCamera {
  std::string name;      // the camera's own name
  std::string nodeName;  // the name of the node that places it (glTF), may be empty
  Camera camera;
};

// A named choice of materials (glTF KHR_materials_variants): under it each
// listed mesh is drawn with the listed material instead of its own.
struct MaterialVariant {
  std::string name;
  std::vector<std::pair<uint32_t, uint32_t>> meshMaterials;  // (mesh, material)
};

struct Scene {
  std::string name;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<TextureRef> textureRefs;
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<ImplicitObject> implicits;
  std::vector<PointLight> pointLights;
  Environment environment;           // none unless the scene file or the command line gives one
  glm::vec3 ambient{0.0f};           // Whitted's ambient term
  Camera camera;                     // the view rendered
  std::vector<NamedCamera> cameras;  // alternatives for selectCamera
  std::vector<MaterialVariant> materialVariants;  // alternatives for selectMaterialVariant
  std::optional<MaterialRow> materialRow;
  uint64_t triangleCount() const;
  // The bytes of the meshes' vertex, attribute and index arrays as loaded.
  uint64_t meshBytes() const;
  // Whether the scene brings its own lighting: a delta light, or a drawn
  // emissive material whose emission is lighting (Material::
  // emissionIsLighting). A scene without it gets the default environment.
  bool hasOwnLighting() const;
  // Whether any drawn material emits, lighting or not.
  bool hasEmitters() const;
};

// Makes the camera named `name` (its own name or its node's) the scene's view,
// or, when no camera has that name, the one at that index of `cameras` (node
// order) when `name` is a number; throws penumbra::Error listing the cameras
// by index and name.
void selectCamera(Scene& scene, const std::string& name);

// Gives each mesh the variant's material (by name, or by index when `name` is
// a number that names no variant); meshes the variant does not list keep
// theirs. Throws penumbra::Error listing the variants by index and name.
void selectMaterialVariant(Scene& scene, const std::string& name);

// Checks indices, materials, texture references and instances refer to
// things that exist, that positions, texture coordinates and texture
// transforms are finite, that textures hold width x height RGBA8 texels and
// implicit objects are well-formed (validateImplicit); throws penumbra::Error
// naming the scene and the part.
void validate(const Scene& scene);
// A usable camera: an orthographic height in [0, 1e9], aperture radius >= 0,
// 0 or 3..32 blades and, with a lens, a focus distance > 0. Throws penumbra::Error saying which.
void validateCamera(const Camera& camera);
// The aperture radius (metres) of a lens at f-number N on a 35 mm camera
// (a 24 mm tall frame) with this vertical field of view: focal length / 2N.
float apertureRadiusForFNumber(float fNumber, float verticalFovDegrees);

}  // namespace penumbra::scene
