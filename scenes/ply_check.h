// Reading a PLY file (Turk 1994; the format as paulbourke.net/dataformats/ply describes it),
// ASCII or binary, into its elements' values, checking its structure on the way: a truncated
// body or a face index past the vertex count is an error, never a crash.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tr {

struct PlyProperty {
  std::string name, type, count_type;  // count_type non-empty: a list
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

// Whether a property type is an integer type, and its largest value (Mitsuba's
// Struct::range(type).second, by which it normalizes integer properties).
bool ply_is_integer(const std::string& type);
double ply_integer_max(const std::string& type);

}  // namespace tr
