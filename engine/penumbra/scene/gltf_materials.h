#pragma once
// glTF 2.0 metallic-roughness materials and their KHR_materials_* extensions
// mapped onto the engine's Disney parameters with the Lambert diffuse
// (docs/materials.md, "glTF materials", states every choice and difference).
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/scene/scene.h"

namespace tinygltf {
struct Material;
}

namespace penumbra::scene::gltf {

// Extensions this loader understands; anything else in extensionsRequired is
// an error, in extensionsUsed a warning.
const std::vector<std::string_view>& supportedExtensions();
bool isSupportedExtension(std::string_view name);

struct MaterialConversion {
  Material material;
  // alphaMode MASK with a base-colour alpha factor below the cutoff and no
  // base-colour texture to vary alpha across the surface: it is cut away
  // entirely.
  bool invisible = false;
};

// The factors, alpha mode, normal scale and occlusion strength; the texture
// slots are left empty (TextureImporter::attach fills them). `warnings`
// collects one line per part of the material that cannot be represented
// (e.g. a volume's attenuation, an extension's textures).
MaterialConversion convertMaterial(const tinygltf::Material& material, const std::string& where,
                                   std::vector<std::string>& warnings);

// glTF's default material (spec 3.9.6: every factor at its default): white,
// metallic 1, roughness 1.
Material defaultMaterial();

// Normal-incidence reflectance of a dielectric of index `ior` in air.
float f0FromIor(float ior);

}  // namespace penumbra::scene::gltf
