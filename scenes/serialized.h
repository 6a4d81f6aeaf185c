// Mitsuba's `.serialized` mesh files, read as Mitsuba 3.8's src/shapes/serialized.cpp reads
// them (the format is described there). Each mesh is a little-endian uint16 format id 0x041C
// and uint16 version (3 or 4) followed by one zlib stream; meshes are concatenated, and the
// file ends with an offset dictionary (one offset per mesh: uint64 in version 4, uint32 in
// version 3; then the uint32 mesh count) through which `shape_index` > 0 finds its mesh.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "scenes/mesh.h"

namespace tr {

struct SerializedMesh {
  std::string name;   // stored from version 4 on; empty for version 3
  TriangleMesh mesh;  // object space, as stored; vertex colors as attribute "vertex_color"
};

// The file holds no mesh with the requested index.
class ShapeIndexError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads mesh `shape_index` of the file. Any problem (unreadable file, bad format id or
// version, truncation, corrupt zlib data, counts the file cannot hold, indices past the
// vertices, NaN values) throws std::runtime_error with a one-line reason; a `shape_index` past
// the last mesh throws ShapeIndexError. Memory grows with the data actually decompressed,
// never with the counts a header claims.
SerializedMesh load_serialized_mesh(const std::string& path, uint32_t shape_index);

}  // namespace tr
