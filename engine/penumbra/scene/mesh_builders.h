#pragma once
// Procedural meshes for tests and analytic scenes.
#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// A geodesic sphere (subdivided icosahedron) of `subdivisions` levels, vertices
// on the sphere. `inwardFacing` makes the counter-clockwise side face the
// centre (a closed room seen from inside).
Mesh makeIcosphere(uint32_t subdivisions, float radius, bool inwardFacing, uint32_t material);

// A parallelogram with corners origin, origin + edgeU, origin + edgeU +
// edgeV, origin + edgeV (two triangles). Its counter-clockwise (front) side
// faces cross(edgeU, edgeV).
Mesh makeQuad(glm::vec3 origin, glm::vec3 edgeU, glm::vec3 edgeV, uint32_t material);

// The axis-aligned box [minCorner, maxCorner] (12 triangles), closed, front
// faces outwards, or inwards with `inwardFacing` (a room seen from inside).
Mesh makeBox(glm::vec3 minCorner, glm::vec3 maxCorner, bool inwardFacing, uint32_t material);

// The analytic furnace: the camera at the centre of a closed sphere whose
// surface has albedo `albedo` and emits `emission` towards the inside. Every
// pixel's exact value is emission / (1 - albedo).
Scene makeFurnaceScene(float albedo, float emission, uint32_t subdivisions = 3);

}  // namespace penumbra::scene
