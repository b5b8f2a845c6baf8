#pragma once
// The "implicits" array of a scene file (format: scene_loader.h).
#include <cstdint>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "penumbra/scene/implicit_object.h"

namespace penumbra::scene {

// `unitScale` converts file units to metres (it scales the whole transform, so
// shape sizes stay in file units in object space). Throws penumbra::Error
// naming the object on bad input; validateImplicit runs later with the scene.
std::vector<ImplicitObject> parseImplicits(const nlohmann::json& implicits,
                                           const std::map<std::string, uint32_t>& materialIndex,
                                           float unitScale, const std::string& where);

}  // namespace penumbra::scene
