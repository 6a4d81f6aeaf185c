#include "scenes/assimp/imported_ply.h"

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace tr {

void write_imported_ply(const ImportedMesh& mesh, const std::filesystem::path& file,
                        const std::string& comment) {
  std::ofstream f(file, std::ios::binary);
  const bool normals = !mesh.normals.empty(), uv = !mesh.uv.empty();
  const bool tangents = !mesh.tangents.empty();
  const std::size_t vertices = mesh.positions.size() / 3, faces = mesh.triangles.size() / 3;
  f << "ply\nformat binary_little_endian 1.0\ncomment " << comment << "\nelement vertex "
    << vertices << "\nproperty float x\nproperty float y\nproperty float z\n"
    << (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "")
    << (uv ? "property float u\nproperty float v\n" : "")
    << (tangents ? "property float tangent_x\nproperty float tangent_y\nproperty float "
                   "tangent_z\nproperty float bitangent_x\nproperty float bitangent_y\n"
                   "property float bitangent_z\n"
                 : "")
    << "element face " << faces << "\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&](auto value) { f.write(reinterpret_cast<const char*>(&value), sizeof value); };
  for (std::size_t k = 0; k < vertices; ++k) {
    for (int c = 0; c < 3; ++c) put(mesh.positions[3 * k + c]);
    if (normals)
      for (int c = 0; c < 3; ++c) put(mesh.normals[3 * k + c]);
    if (uv) put(mesh.uv[2 * k]), put(mesh.uv[2 * k + 1]);
    if (tangents) {
      for (int c = 0; c < 3; ++c) put(mesh.tangents[3 * k + c]);
      for (int c = 0; c < 3; ++c) put(mesh.bitangents[3 * k + c]);
    }
  }
  for (std::size_t k = 0; k < faces; ++k) {
    put(std::uint8_t(3));
    for (int c = 0; c < 3; ++c) put(std::int32_t(mesh.triangles[3 * k + c]));
  }
  if (!f.flush()) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace tr
