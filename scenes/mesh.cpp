#include "scenes/mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unordered_map>

#include "scenes/ply_check.h"

namespace tr {

namespace {

// Merges vertices whose position, normal and uv are bitwise equal: Mitsuba's OBJ loader keys
// its vertices by (v, vt, vn) index triples, which this reproduces on Assimp's per-corner data.
void join_identical_vertices(TriangleMesh& mesh) {
  struct Key {
    float f[8];
    bool operator==(const Key& o) const { return std::memcmp(f, o.f, sizeof(f)) == 0; }
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      uint64_t h = 1469598103934665603ull;  // FNV-1a over the bytes
      const unsigned char* b = reinterpret_cast<const unsigned char*>(k.f);
      for (size_t i = 0; i < sizeof(k.f); ++i) h = (h ^ b[i]) * 1099511628211ull;
      return size_t(h);
    }
  };
  std::unordered_map<Key, uint32_t, Hash> index_of;
  TriangleMesh out;
  std::vector<uint32_t> remap(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    Key k{};
    glm::vec3 n = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[v];
    glm::vec2 t = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[v];
    const float values[8] = {
        mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z, n.x, n.y, n.z, t.x, t.y};
    std::memcpy(k.f, values, sizeof(values));
    auto [it, inserted] = index_of.emplace(k, uint32_t(out.positions.size()));
    if (inserted) {
      out.positions.push_back(mesh.positions[v]);
      if (!mesh.normals.empty()) out.normals.push_back(n);
      if (!mesh.uvs.empty()) out.uvs.push_back(t);
    }
    remap[v] = it->second;
  }
  for (uint32_t i : mesh.indices) out.indices.push_back(remap[i]);
  mesh = std::move(out);
}

}  // namespace

TriangleMesh load_mesh_file(const std::string& path, bool flip_tex_coords) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".ply" || ext == ".PLY") check_ply_file(path);
  Assimp::Importer importer;
  // No vertex joining (Assimp's merges within an absolute epsilon) and no normal generation
  // (the caller follows Mitsuba); corners are joined exactly below.
  const aiScene* ai = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType);
  if (!ai || !ai->mRootNode) throw std::runtime_error(importer.GetErrorString());

  TriangleMesh mesh;
  bool any_normals = false, all_normals = true, any_uvs = false, all_uvs = true;
  for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
    const aiMesh* am = ai->mMeshes[m];
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    any_normals |= am->HasNormals();
    all_normals &= am->HasNormals();
    any_uvs |= am->HasTextureCoords(0);
    all_uvs &= am->HasTextureCoords(0);
  }
  for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
    const aiMesh* am = ai->mMeshes[m];
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    uint32_t base = uint32_t(mesh.positions.size());
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& p = am->mVertices[v];
      mesh.positions.emplace_back(p.x, p.y, p.z);
      if (any_normals && all_normals) {
        const aiVector3D& n = am->mNormals[v];
        mesh.normals.emplace_back(n.x, n.y, n.z);
      }
      if (any_uvs && all_uvs) {
        const aiVector3D& t = am->mTextureCoords[0][v];
        mesh.uvs.emplace_back(t.x, flip_tex_coords ? 1.0f - t.y : t.y);
      }
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines are not surfaces
      for (int k = 0; k < 3; ++k) mesh.indices.push_back(base + face.mIndices[k]);
    }
  }
  if (mesh.indices.empty()) throw std::runtime_error("the file contains no triangles");
  join_identical_vertices(mesh);
  if (any_normals && !all_normals)
    throw std::runtime_error("only some parts of the mesh have vertex normals");
  if (any_uvs && !all_uvs)
    throw std::runtime_error("only some parts of the mesh have texture coordinates");
  check_finite(mesh);
  return mesh;
}

void check_finite(const TriangleMesh& mesh) {
  auto finite = [](glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  for (const glm::vec3& p : mesh.positions)
    if (!finite(p)) throw std::runtime_error("a vertex position is NaN or infinite");
  for (const glm::vec3& n : mesh.normals)
    if (!finite(n)) throw std::runtime_error("a vertex normal is NaN or infinite");
  for (const glm::vec2& t : mesh.uvs)
    if (!finite(glm::vec3(t, 0.0f)))
      throw std::runtime_error("a texture coordinate is NaN or infinite");
  for (const auto& [name, attribute] : mesh.attributes)
    for (float v : attribute.values)
      if (!std::isfinite(v)) throw std::runtime_error("a value of " + name + " is NaN or infinite");
}

TriangleMesh make_rectangle() {
  TriangleMesh m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.normals.assign(4, glm::vec3(0, 0, 1));
  for (const glm::vec3& p : m.positions) m.uvs.emplace_back(0.5f * (p.x + 1), 0.5f * (p.y + 1));
  m.indices = {0, 1, 2, 2, 3, 0};
  return m;
}

TriangleMesh make_cube() {
  TriangleMesh m;
  m.positions = {{1, -1, -1}, {1, -1, 1},   {-1, -1, 1}, {-1, -1, -1}, {1, 1, -1},   {-1, 1, -1},
                 {-1, 1, 1},  {1, 1, 1},    {1, -1, -1}, {1, 1, -1},   {1, 1, 1},    {1, -1, 1},
                 {1, -1, 1},  {1, 1, 1},    {-1, 1, 1},  {-1, -1, 1},  {-1, -1, 1},  {-1, 1, 1},
                 {-1, 1, -1}, {-1, -1, -1}, {1, 1, -1},  {1, -1, -1},  {-1, -1, -1}, {-1, 1, -1}};
  const glm::vec3 face_normal[6] = {{0, -1, 0}, {0, 1, 0},  {1, 0, 0},
                                    {0, 0, 1},  {-1, 0, 0}, {0, 0, -1}};
  const glm::vec2 corner_uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (int f = 0; f < 6; ++f) {
    for (int c = 0; c < 4; ++c) {
      m.normals.push_back(face_normal[f]);
      m.uvs.push_back(corner_uv[c]);
    }
    uint32_t b = uint32_t(4 * f);
    m.indices.insert(m.indices.end(), {b, b + 1, b + 2, b + 3, b, b + 2});
  }
  return m;
}

namespace {

// Angle between unit vectors, accurate near 0 and pi (as Mitsuba's unit_angle).
float unit_angle(glm::vec3 a, glm::vec3 b) {
  if (glm::dot(a, b) < 0.0f) return 3.14159265358979f - 2.0f * std::asin(0.5f * glm::length(a + b));
  return 2.0f * std::asin(0.5f * glm::length(a - b));
}

}  // namespace

std::vector<glm::vec3> mesh_vertex_normals(const TriangleMesh& mesh) {
  std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    glm::vec3 v[3] = {mesh.positions[i[0]], mesh.positions[i[1]], mesh.positions[i[2]]};
    glm::vec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    float len2 = glm::dot(n, n);
    if (!(len2 > 0.0f)) continue;
    n /= std::sqrt(len2);
    for (int k = 0; k < 3; ++k) {
      glm::vec3 e1 = v[(k + 1) % 3] - v[k], e2 = v[(k + 2) % 3] - v[k];
      float angle = unit_angle(glm::normalize(e1), glm::normalize(e2));
      normals[i[k]] += n * angle;
    }
  }
  for (glm::vec3& n : normals) {
    float len = glm::length(n);
    n = len != 0.0f ? n / len : glm::vec3(1, 0, 0);  // Mitsuba's placeholder for unused vertices
  }
  return normals;
}

void transform_mesh(TriangleMesh& mesh, const glm::dmat4& m) {
  glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(m * glm::dvec4(glm::dvec3(p), 1.0));
  for (glm::vec3& n : mesh.normals) {
    glm::dvec3 t = normal_matrix * glm::dvec3(n);
    double len = glm::length(t);
    n = len > 0.0 ? glm::vec3(t / len) : n;
  }
}

double triangle_area(const TriangleMesh& mesh, size_t triangle) {
  glm::dvec3 a(mesh.positions[mesh.indices[3 * triangle]]);
  glm::dvec3 b(mesh.positions[mesh.indices[3 * triangle + 1]]);
  glm::dvec3 c(mesh.positions[mesh.indices[3 * triangle + 2]]);
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

}  // namespace tr
