#pragma once
// The effect set of a scene (shaders/shared/effects.h): the code paths its
// pipeline must hold. The path tracer builds its pipeline from the shader
// variants compiled for exactly this set, unless asked for every effect.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/scene/scene.h"

namespace penumbra::render {

// PT_EFFECT_* bits the scene calls for, seen from `camera` (the scene's own if
// absent). A bit is set if any material, light or the camera could use the
// code behind it, so a variant without it renders the scene exactly as the
// full pipeline does.
uint32_t deriveEffects(const scene::Scene& scene,
                       const std::optional<scene::Camera>& camera = std::nullopt);

// The bits a camera calls for: PT_EFFECT_ORTHOGRAPHIC for an orthographic one.
uint32_t cameraEffects(const scene::Camera& camera);

// The PT_EFFECT_* bits one material calls for when drawn (not area lights:
// those follow from emission, which deriveEffects adds).
uint32_t deriveMaterialEffects(const scene::Material& material);

// The bits one mesh calls for whatever its material: vertex colours (COLOR_0)
// vary the surface per point, as textures do, and share their bit, so scenes
// without either keep that code out of their pipelines.
uint32_t meshEffects(const scene::Mesh& mesh);

// Whether a material's surface is cut by its base colour's alpha: alphaMode
// MASK with a base-colour texture (per texel) or vertex alpha, or BLEND with
// alpha below 1 anywhere (stochastic coverage). Its meshes are non-opaque geometry and the
// triangles' hit group gets the alpha any-hit shader. MASK without a texture
// is all or nothing, decided when the scene is loaded. A mesh whose vertex
// colours (COLOR_0) carry alpha below 1 (`vertexAlpha`) varies it per point
// too, under MASK or BLEND.
bool alphaMasked(const scene::Material& material, bool vertexAlpha = false);
// Whether a mesh's vertex colours carry alpha below 1 anywhere.
bool hasVertexAlpha(const scene::Mesh& mesh);

// Names of the bits in `effects`, in bit order ("area-lights", "sheen", ...).
std::vector<std::string> effectNames(uint32_t effects);

// Features of a scene that the shaders reach by a uniform branch on a value
// of the frame, the camera or a light or material record rather than by a
// variant bit: each bit doubles the compiled variants, and these cost a
// scene without them nothing measurable (docs/results.md). The
// environment, which did cost (11 % of the Cornell box's frame on the
// H200), is the variant bit PT_EFFECT_ENVIRONMENT, and so is the
// orthographic camera, whose branch moved the driver's code for the whole
// megakernel by up to 2 % per sample. Listed by --print-effects.
enum SceneFeature : uint32_t {
  kFeatureDirectionalLights = 1,  // directional lights (delta or soft suns)
  kFeatureSoftSun = 2,            // a directional light with an angular radius
  kFeatureSpotLights = 4,
  kFeatureThinLens = 8,     // an aperture radius > 0
  kFeatureLensBlades = 16,  // a polygonal aperture
  kFeatureAbsorption = 32,  // a transmissive material with a finite attenuation distance
};
// The features of the scene rendered from `camera` (the scene's own if absent).
uint32_t deriveFeatures(const scene::Scene& scene, const std::optional<scene::Camera>& camera);
// Their names ("soft-sun", "thin-lens", ...), in bit order.
std::vector<std::string> featureNames(uint32_t features);

// The embedded variant of an entry point ("path_trace.rgen", "whitted.rgen",
// "triangle.rchit") compiled for `effects`, restricted to the bits the entry
// point has variants for: "path_trace.e5.rgen", or the plain name when every
// one of its bits is set.
std::string effectVariant(std::string_view shader, uint32_t effects);

}  // namespace penumbra::render
