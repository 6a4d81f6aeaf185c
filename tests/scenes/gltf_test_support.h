// What the glTF importer's tests share: base64 for data URIs, importing a document written to
// a fresh folder, finding nodes and properties in the tree it builds, and reading back the
// PLY files it writes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "scene_test_files.h"
#include "scenes/gltf/gltf_import.h"

namespace tr::gltf_test {

using json = nlohmann::json;

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 2]));
    size_t n = std::min<size_t>(3, bytes.size() - i);  // RFC 4648 section 4: pad with '='
    for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

struct Imported {
  GltfScene scene;
  std::filesystem::path dir;
};

// Writes `g` as dir/scene.gltf and imports it (dir: a test's folder, where its images lie).
inline Imported import_in(const std::filesystem::path& dir, const json& g,
                          const LoadOptions& options = {}) {
  std::filesystem::create_directories(dir / "work");
  std::string path = testing_files::write_file(dir, "scene.gltf", g.dump(1));
  return {import_gltf(path, options, dir / "work"), dir};
}

inline Imported import(const json& g, const LoadOptions& options = {}) {
  return import_in(testing_files::fresh_dir(), g, options);
}

inline std::vector<const Node*> all(const Node& n, const std::string& tag,
                                    const std::string& type) {
  std::vector<const Node*> out;
  if (n.tag == tag && n.type == type) out.push_back(&n);
  for (const Property& p : n.props)
    if (p.kind == PropertyKind::Object)
      for (const Node* c : all(*p.object, tag, type))
        if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  return out;
}

inline const Node& one(const Node& root, const std::string& tag, const std::string& type) {
  std::vector<const Node*> v = all(root, tag, type);
  EXPECT_EQ(v.size(), 1u) << tag << " " << type;
  if (v.empty()) throw std::runtime_error("no " + tag + " " + type);
  return *v[0];
}

inline const Property& prop(const Node& n, const std::string& name) {
  for (const Property& p : n.props)
    if (p.name == name) return p;
  throw std::runtime_error("no property " + name + " on " + n.type);
}

inline void expect_vec(glm::dvec3 a, glm::dvec3 b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// A PLY file written by the importer (scenes/assimp/imported_ply.h): float x y z [nx ny nz]
// [u v] per vertex, then faces as uchar 3 and three int32 indices.
struct Ply {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uv;
  std::vector<glm::ivec3> faces;
};

inline Ply read_ply(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t body = data.find("end_header\n");
  EXPECT_NE(body, std::string::npos) << file;
  std::istringstream header(data.substr(0, body));
  size_t vertices = 0, faces = 0;
  bool normals = data.find("property float nx") < body, uv = data.find("property float u") < body;
  for (std::string line; std::getline(header, line);) {
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoul(line.substr(15));
    if (line.rfind("element face ", 0) == 0) faces = std::stoul(line.substr(13));
  }
  const char* p = data.data() + body + 11;
  auto get = [&](auto& v) { std::memcpy(&v, p, sizeof v), p += sizeof v; };
  Ply ply;
  for (size_t i = 0; i < vertices; ++i) {
    glm::vec3 x, n;
    glm::vec2 t;
    get(x), ply.positions.push_back(x);
    if (normals) get(n), ply.normals.push_back(n);
    if (uv) get(t), ply.uv.push_back(t);
  }
  for (size_t i = 0; i < faces; ++i) {
    uint8_t three;
    glm::ivec3 f;
    get(three), get(f);
    EXPECT_EQ(three, 3);
    ply.faces.push_back(f);
  }
  return ply;
}

}  // namespace tr::gltf_test
