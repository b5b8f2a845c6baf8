#pragma once
// Everything that determines a rendered image, as one JSON document: the
// viewer writes it beside each screenshot and `penumbra render --settings
// FILE` reads it back, so the screenshot can be reproduced exactly (same
// device, same samples, same seed).
//
//   { "format": "penumbra-render", "version": 1,
//     "scene": "cornell-box", "vary": "", "set": "",
//     "animation": "Walk", "time": 1.5,       // optional (scene::AnimationChoice)
//     "camera": { "position": [x,y,z], "forward": [..], "up": [..], "verticalFovDegrees": 39.3,
//                 "orthographicHeight": 0,  // > 0: orthographic, this tall
//                 "apertureRadius": 0, "focusDistance": 1, "apertureBlades": 0 },
//     "width": 512, "height": 512, "spp": 64, "sppPerFrame": 4,
//     "integrator": "path", "strategy": "mis", "misHeuristic": "power", "sampler": "sobol",
//     "maxDepth": 8, "russianRoulette": true, "rouletteStartDepth": 3,
//     "radianceClamp": 0, "seed": 0,
//     "exposure": 1, "toneMapping": "clamp", "allEffects": false,
//     "environment": { "map": "sky.hdr", "rotation": 90, "intensity": 1, "background": true },
//     "materials": [ { "index": 0, "name": "white", "model": "lambert",
//                      "baseColor": [r,g,b], "metallic": 0, "roughness": 0.5,
//                      "anisotropic": 0, "specular": 0.5, "specularTint": 0,
//                      "sheen": 0, "sheenTint": 0.5, "clearcoat": 0,
//                      "clearcoatGloss": 1, "specTrans": 0, "ior": 1.5,
//                      "subsurface": 0, "thin": false, "ks": 0, "exponent": 32,
//                      "reflectivity": 0, "transparency": 0,
//                      "anisotropyStrength": 0, "anisotropyRotation": 0,
//                      "sheenRoughness": 0 } ] }  // the last three optional
// Floats are written with enough digits to read back bit-identical.
//
// "materials" records the viewer's Material-menu edits: every material whose
// editable parameters differ from the scene as loaded with vary/set applied,
// by index into the scene's materials. It is absent when nothing was edited.
// The name is checked when the record is applied, so a record applied to
// another scene fails instead of recolouring the wrong objects. Emission is
// not editable (emitters are tabulated when the scene loads), and textures and
// alpha stay the scene's.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/batch/render_settings.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/scene/gltf_loader.h"
#include "penumbra/scene/input_limits.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// One edited material. `material` holds the edited values, but only its
// editable parameters (model, baseColor, the Disney and Phong parameters) are
// recorded and applied; its name identifies it.
struct MaterialOverride {
  uint32_t index = 0;  // into scene.materials
  scene::Material material;
  // Parameters made editable after the record was written, which it does
  // not give: the scene's values stay (anisotropyStrength, anisotropyRotation,
  // sheenRoughness, diffuseTransmission and the colours but baseColor).
  std::vector<std::string> sceneValues;
};

// The environment asked for over the scene's own (the command line's --env
// options, the viewer's Environment menu). What is not given keeps the
// scene's; a scene with no light at all gets the default environment
// unless `map` is "none".
struct EnvironmentChoice {
  std::string map;  // "" the scene's, "none", "default", or an .exr / .hdr file
  std::optional<float> rotationDegrees, intensity;
  std::optional<bool> visibleBackground;
  bool empty() const { return map.empty() && !rotationDegrees && !intensity && !visibleBackground; }
};

// Applies the choice to the scene's environment; a scene left without
// lighting (no environment, scene::Scene::hasOwnLighting false: glTF's
// emissive materials do not count) gets scene::defaultEnvironment() and one
// line on stderr saying so. Throws penumbra::Error for an unreadable map or
// a setting given with no environment to apply it to.
void applyEnvironmentChoice(scene::Scene& scene, const EnvironmentChoice& choice);
// The same, the scene's own environment given apart (the viewer keeps it
// while the scene's current one follows its menu).
scene::Environment chooseEnvironment(const scene::Environment& sceneEnvironment,
                                     const scene::Scene& scene, const EnvironmentChoice& choice);

struct RenderJob {
  std::string scene = "cornell-box";    // built-in name or scene file path
  std::string vary, set;                // material-test row (scene::changeMaterialRow)
  std::string
      variant;  // material variant by name or index (scene::selectMaterialVariant); empty: none
  scene::AnimationChoice animation;     // the moment of the glTF files' animations; empty: none
  std::optional<scene::Camera> camera;  // absent: the scene's camera
  uint32_t width = 512, height = 512;
  uint32_t spp = 64;
  RenderSettings settings;                  // the table's settings (render_settings.h)
  std::vector<MaterialOverride> materials;  // applied after vary/set
  EnvironmentChoice environment;
};

const char* materialModelName(scene::MaterialModel model);
std::optional<scene::MaterialModel> parseMaterialModel(std::string_view name);

// The parameters the viewer can edit besides baseColor, by their record (and
// scene file) names: the scalars, then the colours (specularColor,
// sheenColor, diffuseTransmissionColor).
const std::vector<std::string>& editableMaterialParameters();
// Sets an editable parameter: 3 values for a colour, 1 otherwise. Throws
// penumbra::Error naming the parameter on an unknown name or a bad count.
void setEditableParameter(scene::Material& material, std::string_view name,
                          const std::vector<float>& values);
// The overrides that turn `loaded` into `edited` (same materials, same order):
// one per material whose editable parameters differ.
std::vector<MaterialOverride> materialOverrides(const std::vector<scene::Material>& loaded,
                                                const std::vector<scene::Material>& edited);
// Copies each override's editable parameters onto the scene's material,
// keeping its emission, textures and alpha. Throws penumbra::Error naming
// `source` and the field if an index is out of range or the name differs.
void applyMaterialOverrides(scene::Scene& scene, const std::vector<MaterialOverride>& overrides,
                            const std::string& source);

std::string renderJobToJson(const RenderJob& job);
// Throws penumbra::Error naming `source` and the field on a malformed
// document: a wrong type, a number out of its range (whole numbers where
// the field is one, floats finite), a zero camera direction, or text past
// limits.maxJsonBytes or nested past limits.maxJsonDepth (scene/input_limits.h).
RenderJob renderJobFromJson(const std::string& text, const std::string& source,
                            const scene::InputLimits& limits = {});
void saveRenderJob(const std::string& path, const RenderJob& job);
RenderJob loadRenderJob(const std::string& path, const scene::InputLimits& limits = {});

}  // namespace penumbra::render
