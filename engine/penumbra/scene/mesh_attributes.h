#pragma once
// Vertex attributes derived from a mesh's geometry, for files that leave them
// out (glTF: flat normals when NORMAL is absent, tangents when TANGENT is).
#include "penumbra/scene/scene.h"

namespace penumbra::scene {

// Gives every triangle its own three vertices carrying the face normal
// (counter-clockwise front), so shading is faceted as glTF requires for
// primitives without normals. Texture coordinates and colours follow their vertices;
// tangents are dropped (glTF: they must be ignored without normals).
// A degenerate triangle gets a zero normal, which the renderer reads as
// "use the geometric normal".
void makeFlatNormals(Mesh& mesh);

// Per-vertex tangents from positions, normals and uv0: each triangle's
// tangent and bitangent (Lengyel 2001), weighted by the triangle's UV area,
// are summed per vertex; the tangent is then made orthogonal to the
// normal (Gram-Schmidt) and w records the handedness, +1 when
// cross(normal, tangent) points along the bitangent. The bitangent points
// towards decreasing v, the image's "up" in glTF (whose v grows downwards),
// so an unmirrored mapping has w = +1 as in MikkTSpace exports. A vertex
// whose UVs give no direction gets an arbitrary unit tangent orthogonal to
// its normal, w = +1. Needs normals and uv0; does nothing without them.
void generateTangents(Mesh& mesh);

}  // namespace penumbra::scene
