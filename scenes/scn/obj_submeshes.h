// An OBJ file (with its MTL) read through Assimp and split by material: Assimp's OBJ importer
// gives one aiMesh per `usemtl` group of each object, and each becomes a binary PLY file, the
// form in which the Mitsuba XML loader (and Mitsuba's `ply` plugin) reads one group alone.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tr {

struct ObjSubmesh {
  std::string material;  // the group's `usemtl` name (Assimp's "DefaultMaterial" when none)
  std::filesystem::path ply_file;
  bool has_normals = false;  // the OBJ gave `vn` normals for this group
  bool has_uv = false;       // ... and `vt` texture coordinates
};

// Reads `obj_path` and writes its groups as `<out_dir>/<prefix>_<index>_<material>.ply`
// (material name reduced to [A-Za-z0-9_-]). Throws std::runtime_error with Assimp's message
// when the file cannot be read, or names a group that is not made of triangles and polygons.
std::vector<ObjSubmesh> write_obj_submeshes(const std::string& obj_path,
                                            const std::filesystem::path& out_dir,
                                            const std::string& prefix);

}  // namespace tr
