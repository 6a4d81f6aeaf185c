// A glTF primitive's normal-map tangent frames (glTF 2.0 "Meshes", TANGENT: xyz the tangent,
// w = +-1 the handedness, bitangent = w (normal x tangent)), written into the mesh's PLY for
// twinray's `vertex_tangents` (scenes/mesh.h).
#pragma once

#include <vector>

#include "scenes/assimp/imported_geometry.h"

namespace tr {

// The file's TANGENT, 4 values a vertex, on a mesh with normals.
void set_gltf_tangents(ImportedMesh& mesh, const std::vector<float>& tangent_xyzw);

// Without TANGENT the spec asks for MikkTSpace tangents (M. Mikkelsen, "Simulation of Wrinkled
// Surfaces Revisited", 2008, ch. 4), from the positions, normals (the face normal where the
// mesh has none) and uvs:
// - each triangle gives its corners dp/du, orthogonalized against the corner's normal and
//   normalized, weighted by the corner's angle in the plane normal to it;
// - a triangle preserves orientation where its uv area is positive with v running up the image
//   (glTF's v runs down: the sign is taken with v mirrored, as glTF viewers do);
// - corners with equal position, normal and uv (compared by value, not by index) and the same
//   orientation share one tangent, the normalized sum of their weighted ones, and the bitangent
//   +-(normal x tangent) by their orientation; a corner of a triangle without uv area takes a
//   tangent of its position's other corners, or Duff et al.'s basis where there is none.
// Mikkelsen's reference code also separates such corners by whether their triangles share
// edges (here corners meeting only at a vertex, a bow tie, share their tangent), and fills the
// corners of triangles without uv area from their neighbours by its own rules; so results may
// differ there. Vertices whose corners get different frames are split, and vertices no triangle
// uses are dropped.
void generate_tangents(ImportedMesh& mesh);

}  // namespace tr
