// An imported mesh in plain arrays: what the Assimp module (scenes/assimp/assimp_module.cpp,
// loaded on first use) reads from an OBJ file for scenes/scn/, and what scenes/gltf/ reads from
// a glTF primitive; both write it as a PLY file. Faces are triangles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tr {

struct ImportedMesh {
  std::string material;  // the name of Assimp's material for the mesh (Assimp only)
  // Assimp found points or lines in it (aiPrimitiveType_POINT | aiPrimitiveType_LINE): its
  // faces are then not all triangles, and no importer reads it (Assimp only).
  bool points_or_lines = false;
  std::vector<float> positions;  // x y z per vertex
  std::vector<float> normals;    // nx ny nz per vertex, or empty
  std::vector<float> uv;         // the first texture coordinates, u v per vertex, or empty
  // A normal map's tangent frame, x y z per vertex each, or empty (glTF only: its TANGENT, or
  // scenes/gltf/gltf_tangents.h).
  std::vector<float> tangents;
  std::vector<float> bitangents;
  std::vector<std::uint32_t> triangles;  // three vertex indices per face
};

// The meshes in Assimp's order (aiScene::mMeshes).
using ImportedGeometry = std::vector<ImportedMesh>;

// The module's entry point: reads `path` into `out`; on failure returns false and sets `error`
// to Assimp's message.
using ReadGeometryFunction = bool (*)(const char* path, ImportedGeometry* out, std::string* error);
inline constexpr const char* kReadGeometrySymbol = "twinray_assimp_read_geometry";

}  // namespace tr
