// Reading a Wavefront OBJ file with the semantics of Mitsuba 3's `obj` shape (src/shapes/obj.cpp):
// the lines v, vt, vn and f; every other line (o, g, s, usemtl, mtllib, l, p, comments) is
// skipped, as there.
#pragma once

#include <string>

#include "scenes/mesh.h"

namespace tr {

// One mesh of every face of the file, as Mitsuba builds it:
// - `v x y z`, `vn x y z` and `vt u v` read their first 3, 3 and 2 numbers (more are ignored,
//   fewer are an error); `vn` lines are not read at all when `face_normals`;
// - `f` corners are `v`, `v/vt`, `v//vn` or `v/vt/vn` with 1-based indices; a face of n >= 3
//   corners is the fan (0, k, k + 1); a corner omitting vt or vn keeps the previous corner's
//   index of it on that line (Mitsuba reuses its key); relative (negative) indices are refused
//   there and here;
// - a `v` index must name a vertex defined above the face; `vt` and `vn` indices anywhere in
//   the file;
// - a vertex per distinct (v, vt, vn) triple, numbered in order of first use;
// - uv.y = 1 - uv.y when `flip_tex_coords`.
// Beyond Mitsuba (which reads uninitialized memory there) a file whose corners do not all name a
// texture coordinate, or all a normal, when it has any, is refused.
// Throws std::runtime_error ("line N: what") on a malformed line, an index naming nothing, a
// line of 1024 characters or more (Mitsuba's limit), non-finite or zero-length data, or a file
// without triangles.
TriangleMesh read_obj_file(const std::string& path, bool flip_tex_coords, bool face_normals);

}  // namespace tr
