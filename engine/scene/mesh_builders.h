#pragma once
// Procedural meshes for tests and analytic scenes.
#include "scene/scene.h"

namespace penumbra::scene {

// A geodesic sphere (subdivided icosahedron) of `subdivisions` levels, vertices
// on the sphere. `inwardFacing` makes the counter-clockwise side face the
// centre (a closed room seen from inside).
Mesh makeIcosphere(uint32_t subdivisions, float radius, bool inwardFacing, uint32_t material);

// The analytic furnace: the camera at the centre of a closed sphere whose
// surface has albedo `albedo` and emits `emission` towards the inside. Every
// pixel's exact value is emission / (1 - albedo).
Scene makeFurnaceScene(float albedo, float emission, uint32_t subdivisions = 3);

}  // namespace penumbra::scene
