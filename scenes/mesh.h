// Triangle meshes: loading PLY with Mitsuba's semantics, the built-in rectangle and cube,
// Mitsuba's angle-weighted vertex normals, and transformation into world space.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

namespace tr {

// Per-vertex or per-triangle data a texture may read by name (Mitsuba's mesh attributes: a
// name starting with "vertex_" has `dim` values per vertex, "face_" per triangle).
struct VertexAttribute {
  int dim = 0;
  std::vector<float> values;
};

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty: no shading normals (face normals)
  std::vector<glm::vec2> uvs;      // empty: no uvs
  std::vector<uint32_t> indices;   // 3 per triangle
  // By Mitsuba's attribute name, e.g. "vertex_color".
  std::map<std::string, VertexAttribute> attributes;
};

// Loads every face of a PLY file with the semantics of Mitsuba's `ply` shape (its normals, uvs
// and mesh attributes); uv.y = 1 - uv.y when `flip_tex_coords`. OBJ files: scenes/obj_file.h.
// Throws std::runtime_error with a one-line reason.
TriangleMesh load_ply_mesh(const std::string& path, bool flip_tex_coords);

// Throws std::runtime_error when a position, normal, uv or attribute value is NaN or infinite.
void check_finite(const TriangleMesh& mesh);

// Mitsuba `rectangle`: [-1, 1]^2 in the z = 0 plane, normal +z, uv = (p.xy + 1) / 2.
TriangleMesh make_rectangle();
// Mitsuba `cube`: [-1, 1]^3, 24 vertices with per-face normals and uvs, as its cube.cpp.
TriangleMesh make_cube();

// Angle-weighted vertex normals: Thürmer & Wüthrich, "Computing Vertex Normals from Polygonal
// Facets", JGT 3(1), 1998 (the scheme Mitsuba's Mesh::recompute_vertex_normals uses).
std::vector<glm::vec3> mesh_vertex_normals(const TriangleMesh& mesh);

// Applies an affine transform: points by M, normals by M^-T (renormalised).
void transform_mesh(TriangleMesh& mesh, const glm::dmat4& m);

// twinray's `vertex_tangents` (glTF's TANGENT, scenes/gltf/): the mesh attributes
// vertex_tangent and vertex_bitangent (3 values a vertex each) through to_world's linear part,
// all tangents then all bitangents (Shape.tangent_frames). Throws std::runtime_error when either
// is missing, has another size, or is not finite.
std::vector<float> mesh_tangent_frames(const TriangleMesh& mesh, const glm::dmat4& to_world);

double triangle_area(const TriangleMesh& mesh, size_t triangle);

}  // namespace tr
