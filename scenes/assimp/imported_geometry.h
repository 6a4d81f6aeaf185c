// The geometry Assimp reads from a file, in plain arrays: what crosses from the Assimp module
// (scenes/assimp/assimp_module.cpp, loaded on first use) to the importers that write it as PLY
// files (scenes/gltf/, scenes/scn/). Faces are triangles (Assimp's aiProcess_Triangulate).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tr {

struct ImportedMesh {
  std::string material;  // the name of Assimp's material for the mesh
  // Assimp found points or lines in it (aiPrimitiveType_POINT | aiPrimitiveType_LINE): its
  // faces are then not all triangles, and no importer reads it.
  bool points_or_lines = false;
  std::vector<float> positions;  // x y z per vertex
  std::vector<float> normals;    // nx ny nz per vertex, or empty
  std::vector<float> uv;         // Assimp's first texture coordinates, u v per vertex, or empty
  std::vector<std::uint32_t> triangles;  // three vertex indices per face
};

// The meshes in Assimp's order (aiScene::mMeshes).
using ImportedGeometry = std::vector<ImportedMesh>;

// The module's entry point: reads `path` into `out`; on failure returns false and sets `error`
// to Assimp's message.
using ReadGeometryFunction = bool (*)(const char* path, ImportedGeometry* out, std::string* error);
inline constexpr const char* kReadGeometrySymbol = "twinray_assimp_read_geometry";

}  // namespace tr
