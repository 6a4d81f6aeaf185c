// Structural check of a PLY file (Turk 1994; the format as paulbourke.net/dataformats/ply
// describes it) before it is handed to Assimp, whose reader trusts the file: a truncated
// binary body or a face index past the vertex count must be an error, not a crash.
#pragma once

#include <string>

namespace tr {

// Throws std::runtime_error ("PLY: what") when the header is malformed or lacks a vertex
// element with x, y, z (or a face element's index list), the body holds fewer values than the
// header declares, or a face (an element "face" with a list property
// "vertex_indices" or "vertex_index") names a vertex that does not exist.
void check_ply_file(const std::string& path);

}  // namespace tr
