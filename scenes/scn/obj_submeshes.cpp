#include "scenes/scn/obj_submeshes.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace tr {

namespace {

std::string file_safe(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return out;
}

template <typename T>
void put(std::ofstream& f, T value) {
  f.write(reinterpret_cast<const char*>(&value), sizeof value);
}

// Binary little-endian PLY (the format of Mitsuba's ply plugin, scenes/mesh.cpp): float x y z,
// with the OBJ's normals float nx ny nz, with its texture coordinates float u v (as in the
// file: the shape flips v, as Mitsuba's obj plugin does), faces as `list uchar int
// vertex_indices`.
void write_ply(const aiMesh& m, const std::filesystem::path& file) {
  std::ofstream f(file, std::ios::binary);
  bool normals = m.HasNormals(), uv = m.HasTextureCoords(0);
  f << "ply\nformat binary_little_endian 1.0\ncomment written by twinray from an OBJ group\n"
    << "element vertex " << m.mNumVertices << "\nproperty float x\nproperty float y\n"
    << "property float z\n"
    << (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "")
    << (uv ? "property float u\nproperty float v\n" : "") << "element face " << m.mNumFaces
    << "\nproperty list uchar int vertex_indices\n"
    << "end_header\n";
  for (unsigned i = 0; i < m.mNumVertices; ++i) {
    put(f, m.mVertices[i].x), put(f, m.mVertices[i].y), put(f, m.mVertices[i].z);
    if (normals) put(f, m.mNormals[i].x), put(f, m.mNormals[i].y), put(f, m.mNormals[i].z);
    if (uv) put(f, m.mTextureCoords[0][i].x), put(f, m.mTextureCoords[0][i].y);
  }
  for (unsigned i = 0; i < m.mNumFaces; ++i) {
    put(f, uint8_t(3));
    for (int k = 0; k < 3; ++k) put(f, int32_t(m.mFaces[i].mIndices[k]));
  }
  if (!f.flush()) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

std::vector<ObjSubmesh> write_obj_submeshes(const std::string& obj_path,
                                            const std::filesystem::path& out_dir,
                                            const std::string& prefix) {
  Assimp::Importer importer;
  // aiProcess_Triangulate (Assimp's TriangulateProcess.cpp) splits a quad on one diagonal and
  // larger polygons by ear clipping: for planar convex faces the surface of Mitsuba's fans.
  // Vertices stay per corner as Assimp's OBJ importer makes them, so no two groups share one.
  const aiScene* scene =
      importer.ReadFile(obj_path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw std::runtime_error(importer.GetErrorString());
  std::vector<ObjSubmesh> out;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh& m = *scene->mMeshes[i];
    // (Assimp also sets aiPrimitiveType_NGONEncodingFlag on triangulated polygons.)
    if (m.mPrimitiveTypes & (aiPrimitiveType_POINT | aiPrimitiveType_LINE))
      throw std::runtime_error("group " + std::to_string(i) +
                               " has points or lines; only faces of 3 or more corners are read");
    ObjSubmesh s;
    s.material = scene->mMaterials[m.mMaterialIndex]->GetName().C_Str();
    s.ply_file =
        out_dir / (prefix + "_" + std::to_string(i) + "_" + file_safe(s.material) + ".ply");
    s.has_normals = m.HasNormals();
    s.has_uv = m.HasTextureCoords(0);
    write_ply(m, s.ply_file);
    out.push_back(s);
  }
  if (out.empty()) throw std::runtime_error("no faces");
  return out;
}

}  // namespace tr
