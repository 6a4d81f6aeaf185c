// An imported mesh as a binary little-endian PLY file, the form in which the Mitsuba XML loader
// (and Mitsuba's `ply` plugin, scenes/mesh.cpp) reads it: float x y z, float nx ny nz when the
// mesh has normals, float u v when it has texture coordinates, float tangent_x _y _z and
// bitangent_x _y _z when it has tangents (the mesh attributes vertex_tangent, vertex_bitangent
// that `vertex_tangents` reads), faces as `list uchar int vertex_indices`.
#pragma once

#include <filesystem>
#include <string>

#include "scenes/assimp/imported_geometry.h"

namespace tr {

// Throws std::runtime_error when the file cannot be written.
void write_imported_ply(const ImportedMesh& mesh, const std::filesystem::path& file,
                        const std::string& comment);

}  // namespace tr
