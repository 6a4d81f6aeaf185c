// The one translation unit that links Assimp, built as a module that twinray loads only when a
// scene imports an OBJ through .scn or a glTF file (scenes/assimp/assimp_loader.cpp): Assimp
// and the libraries it brings (draco, minizip) cost about 3.3 MiB of resident memory in every
// process that loads them, whether it imports anything or not.
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "scenes/assimp/imported_geometry.h"

namespace {

tr::ImportedMesh copy_mesh(const aiScene& scene, const aiMesh& m) {
  tr::ImportedMesh out;
  out.material = scene.mMaterials[m.mMaterialIndex]->GetName().C_Str();
  // (Assimp also sets aiPrimitiveType_NGONEncodingFlag on triangulated polygons.)
  out.points_or_lines = (m.mPrimitiveTypes & (aiPrimitiveType_POINT | aiPrimitiveType_LINE)) != 0;
  for (unsigned k = 0; k < m.mNumVertices; ++k) {
    out.positions.insert(out.positions.end(),
                         {m.mVertices[k].x, m.mVertices[k].y, m.mVertices[k].z});
    if (m.HasNormals())
      out.normals.insert(out.normals.end(), {m.mNormals[k].x, m.mNormals[k].y, m.mNormals[k].z});
    if (m.HasTextureCoords(0))
      out.uv.insert(out.uv.end(), {m.mTextureCoords[0][k].x, m.mTextureCoords[0][k].y});
  }
  if (out.points_or_lines) return out;
  for (unsigned k = 0; k < m.mNumFaces; ++k)
    for (int c = 0; c < 3; ++c) out.triangles.push_back(m.mFaces[k].mIndices[c]);
  return out;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) bool twinray_assimp_read_geometry(
    const char* path, tr::ImportedGeometry* out, std::string* error) {
  try {
    Assimp::Importer importer;
    // aiProcess_Triangulate (Assimp's TriangulateProcess.cpp) splits a quad on one diagonal and
    // larger polygons by ear clipping, glTF's strips and fans into triangles. Vertices stay as
    // the format's importer makes them (per corner for OBJ).
    const aiScene* scene =
        importer.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
      *error = importer.GetErrorString();
      return false;
    }
    out->clear();
    for (unsigned i = 0; i < scene->mNumMeshes; ++i)
      out->push_back(copy_mesh(*scene, *scene->mMeshes[i]));
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}
