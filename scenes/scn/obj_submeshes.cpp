#include "scenes/scn/obj_submeshes.h"

#include <cctype>
#include <stdexcept>

#include "scenes/assimp/assimp_loader.h"
#include "scenes/assimp/imported_ply.h"

namespace tr {

namespace {

std::string file_safe(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return out;
}

}  // namespace

std::vector<ObjSubmesh> write_obj_submeshes(const std::string& obj_path,
                                            const std::filesystem::path& out_dir,
                                            const std::string& prefix) {
  const ImportedGeometry geometry = read_geometry_with_assimp(obj_path);
  std::vector<ObjSubmesh> out;
  for (std::size_t i = 0; i < geometry.size(); ++i) {
    const ImportedMesh& m = geometry[i];
    if (m.points_or_lines)
      throw std::runtime_error("group " + std::to_string(i) +
                               " has points or lines; only faces of 3 or more corners are read");
    ObjSubmesh s;
    s.material = m.material;
    s.ply_file =
        out_dir / (prefix + "_" + std::to_string(i) + "_" + file_safe(s.material) + ".ply");
    s.has_normals = !m.normals.empty();
    s.has_uv = !m.uv.empty();
    // Texture coordinates as in the file: the shape flips v, as Mitsuba's obj plugin does.
    write_imported_ply(m, s.ply_file, "written by twinray from an OBJ group");
    out.push_back(s);
  }
  if (out.empty()) throw std::runtime_error("no faces");
  return out;
}

}  // namespace tr
