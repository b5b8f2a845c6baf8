#pragma once
// The material-test row: spheres that share one base material and differ in a
// single Disney parameter, from 0 at the first sphere to 1 at the last
// (scenes/material-test.json; `penumbra render --vary P --set k=v,...`).
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/scene/scene.h"

namespace penumbra::scene {

struct MaterialRowDesc {
  Material base;
  std::string vary = "roughness";
  uint32_t count = 7;
  float radius = 0.4f;
  glm::vec3 first{-2.7f, 0.4f, 0.0f};  // centre of the first sphere
  glm::vec3 last{2.7f, 0.4f, 0.0f};
  uint32_t subdivisions = 5;  // of the icosphere meshes
};

// The Disney parameters a row can vary: those whose range is [0, 1].
const std::vector<std::string>& variableDisneyParameters();

// Sets a Disney parameter by its scene-file name ("roughness", "baseColor",
// ...); `values` holds 1 number, or 3 for baseColor/emission. Throws
// penumbra::Error naming the parameter on an unknown name or a bad count.
void setMaterialParameter(Material& material, std::string_view name,
                          const std::vector<float>& values);

// Adds the spheres and their materials (base with `vary` = i / (count - 1)) and
// records the row in scene.materialRow.
void addMaterialRow(Scene& scene, const MaterialRowDesc& desc);

// Changes the varied parameter and/or the base material's constants of the
// scene's row and recomputes the spheres' materials. `assignments` is the
// --set syntax: "metallic=1,baseColor=0.9,0.6,0.2" (a value list runs until
// the next name=). Throws penumbra::Error if the scene has no row.
void changeMaterialRow(Scene& scene, const std::string& vary, const std::string& assignments);

}  // namespace penumbra::scene
