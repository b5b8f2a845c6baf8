#pragma once
// What a scene holds, as one hash: every mesh, texture, material, instance,
// implicit object, light, the environment's texels and placement, and the
// camera. Two scenes with the same hash render the same image with the same
// settings; the name and the file it came from are not part of it, so the
// same scene read from another path (another machine's copy) hashes alike.
#include <string>

#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// 32 hex digits (util/content_hash.h).
std::string contentHash(const Scene& scene);

}  // namespace penumbra::scene
