// Reading a PLY file (Turk 1994; the format as paulbourke.net/dataformats/ply describes it),
// ASCII or binary, into its elements' values, checking its structure on the way: a truncated
// body or a face index past the vertex count is an error, never a crash.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tr {

// A scalar type of the format, resolved from its name (either spelling: int8 or char, ...).
struct PlyScalar {
  int size = 0;  // bytes
  bool floating = false;
  bool is_signed = false;
  // The largest value of an integer type (Mitsuba's Struct::range(type).second, by which it
  // normalizes integer properties); 0 for floating-point types.
  double integer_max = 0.0;
};

struct PlyProperty {
  std::string name, type, count_type;  // count_type non-empty: a list
  PlyScalar scalar, count_scalar;      // type and count_type resolved
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;  // header order
  // Per property, its `count` values as stored (empty for a list property).
  std::vector<std::vector<double>> columns;
  // The element "face": the corner count of each face and the vertex indices of its list
  // property "vertex_indices" (or "vertex_index"), back to back.
  std::vector<std::uint32_t> face_sizes;
  std::vector<std::uint32_t> face_indices;
};

// Throws std::runtime_error ("PLY: what") when the header is malformed or lacks a vertex
// element with x, y, z (or a face element's index list), the body holds fewer values than the
// header declares, a face has fewer than 3 corners or names a vertex that does not exist.
std::vector<PlyElement> read_ply_file(const std::string& path);

}  // namespace tr
