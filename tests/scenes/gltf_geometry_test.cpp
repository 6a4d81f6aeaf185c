// glTF 2.0 geometry (scenes/gltf/gltf_accessors.cpp): each node gets the mesh its own "mesh"
// index names, whatever order the scene lists the nodes in; accessors decode every layout the
// spec allows (strides, normalized integers, sparse substitution, index types); strips, fans
// and mirroring transforms keep the spec's winding; malformed accessors are one-line errors.
#include <gtest/gtest.h>

#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

#include "gltf_test_support.h"
#include "scene_test_files.h"

namespace tr {
namespace {

using namespace gltf_test;

// A glTF document under construction with one buffer (a data URI) holding every view.
struct Doc {
  json g = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", json::array()}}}},
      {"nodes", json::array()},
      {"meshes", json::array()},
      {"accessors", json::array()},
      {"bufferViews", json::array()},
      {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}}}};
  std::string bin;

  template <typename T>
  size_t view(const std::vector<T>& values, size_t stride = 0) {
    while (bin.size() % 4) bin += '\0';
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", values.size() * sizeof(T)}};
    if (stride) v["byteStride"] = stride;
    bin.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    g["bufferViews"].push_back(v);
    return g["bufferViews"].size() - 1;
  }
  size_t accessor(json a) {
    g["accessors"].push_back(a);
    return g["accessors"].size() - 1;
  }
  size_t positions(const std::vector<float>& xyz) {
    return accessor({{"bufferView", view(xyz)},
                     {"componentType", 5126},
                     {"count", xyz.size() / 3},
                     {"type", "VEC3"}});
  }
  size_t mesh(json primitive) {
    g["meshes"].push_back({{"primitives", {primitive}}});
    return g["meshes"].size() - 1;
  }
  size_t node(json n, bool root = true) {
    g["nodes"].push_back(n);
    size_t i = g["nodes"].size() - 1;
    if (root) g["scenes"][0]["nodes"].push_back(i);
    return i;
  }
  json done() {
    if (!g["nodes"].size() || !g["nodes"].back().contains("camera"))
      node({{"camera", 0}, {"translation", {0.0, 0.0, 10.0}}});
    g["buffers"] = {{{"byteLength", bin.size()},
                     {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    return g;
  }
};

// The shapes of an import, keyed by the x of their to_world translation.
std::map<double, Ply> shapes_by_x(const Imported& im) {
  std::map<double, Ply> out;
  for (const Node* s : all(*im.scene.parsed.root, "shape", "ply"))
    out[prop(*s, "to_world").matrix[3][0]] = read_ply(prop(*s, "filename").text);
  return out;
}

// Issue 48's repro: node 0 uses mesh 1 (a square), node 1 mesh 0 (a triangle). A reader that
// numbers meshes by first use (Assimp's glTF importer) swaps them.
TEST(GltfGeometry, NodesGetTheMeshTheirIndexNames) {
  Doc d;
  d.mesh({{"attributes", {{"POSITION", d.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}});
  d.mesh({{"attributes", {{"POSITION", d.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})}}},
          {"indices", d.accessor({{"bufferView", d.view(std::vector<uint16_t>{0, 1, 2, 0, 2, 3})},
                                  {"componentType", 5123},
                                  {"count", 6},
                                  {"type", "SCALAR"}})}});
  d.node({{"mesh", 1}, {"translation", {10.0, 0.0, 0.0}}});
  d.node({{"mesh", 0}, {"translation", {20.0, 0.0, 0.0}}});
  std::map<double, Ply> s = shapes_by_x(import(d.done()));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[10].faces.size(), 2u);  // the square
  EXPECT_EQ(s[10].positions.size(), 4u);
  EXPECT_EQ(s[20].faces.size(), 1u);  // the triangle
  EXPECT_EQ(s[20].positions.size(), 3u);
}

// Eight meshes, mesh k made of k + 1 triangles at height y = k, placed by nodes listed in a
// shuffled order, some as children: every node's shape must be its own mesh.
TEST(GltfGeometry, NoNodeGetsAnotherNodesMesh) {
  Doc d;
  for (int k = 0; k < 8; ++k) {
    std::vector<float> xyz;
    for (int t = 0; t <= k; ++t)
      for (float v : {0.f, float(k), 0.f, 1.f, float(k), 0.f, 0.f, float(k), 1.f}) xyz.push_back(v);
    d.mesh({{"attributes", {{"POSITION", d.positions(xyz)}}}});
  }
  const int order[8] = {5, 2, 7, 0, 3, 6, 1, 4};
  for (int i = 0; i < 8; ++i) {
    json n = {{"mesh", order[i]}, {"translation", {100.0 + order[i], 0.0, 0.0}}};
    if (i % 2) {  // as the child of an empty node, which adds nothing to x
      size_t child = d.node(n, false);
      d.node({{"children", {child}}});
    } else {
      d.node(n);
    }
  }
  std::map<double, Ply> s = shapes_by_x(import(d.done()));
  ASSERT_EQ(s.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    const Ply& p = s[100.0 + k];
    EXPECT_EQ(p.faces.size(), size_t(k + 1)) << "node of mesh " << k;
    ASSERT_FALSE(p.positions.empty());
    EXPECT_EQ(p.positions[0].y, float(k)) << "node of mesh " << k;
  }
}

// Interleaved positions and normals (byteStride 24), normalized unsigned-byte and -short
// texture coordinates, unsigned-byte indices, and a sparse accessor over a bufferView.
TEST(GltfGeometry, AccessorLayoutsDecodeAsTheSpecSays) {
  Doc d;
  std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 1, 0, 3, 0, 0, 0, 1};
  size_t view = d.view(interleaved, 24);
  size_t pos =
      d.accessor({{"bufferView", view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  size_t nrm = d.accessor({{"bufferView", view},
                           {"byteOffset", 12},
                           {"componentType", 5126},
                           {"count", 3},
                           {"type", "VEC3"}});
  size_t uv = d.accessor({{"bufferView", d.view(std::vector<uint8_t>{0, 255, 255, 51, 0, 0})},
                          {"componentType", 5121},
                          {"normalized", true},
                          {"count", 3},
                          {"type", "VEC2"}});
  size_t idx = d.accessor({{"bufferView", d.view(std::vector<uint8_t>{2, 1, 0})},
                           {"componentType", 5121},
                           {"count", 3},
                           {"type", "SCALAR"}});
  d.mesh(
      {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}, {"indices", idx}});
  // The same positions with vertex 1 moved by a sparse substitution (indices as unsigned short).
  size_t sparse = d.accessor(
      {{"bufferView", view},
       {"componentType", 5126},
       {"count", 3},
       {"type", "VEC3"},
       {"sparse",
        {{"count", 1},
         {"indices",
          {{"bufferView", d.view(std::vector<uint16_t>{1, 0})}, {"componentType", 5123}}},
         {"values", {{"bufferView", d.view(std::vector<float>{5, 6, 7})}}}}}});
  size_t short_uv =
      d.accessor({{"bufferView", d.view(std::vector<uint16_t>{0, 65535, 65535, 0, 0, 0})},
                  {"componentType", 5123},
                  {"normalized", true},
                  {"count", 3},
                  {"type", "VEC2"}});
  d.mesh({{"attributes", {{"POSITION", sparse}, {"TEXCOORD_0", short_uv}}}});
  d.node({{"mesh", 0}, {"translation", {1.0, 0.0, 0.0}}});
  d.node({{"mesh", 1}, {"translation", {2.0, 0.0, 0.0}}});
  std::map<double, Ply> s = shapes_by_x(import(d.done()));
  const Ply& a = s[1];
  ASSERT_EQ(a.positions.size(), 3u);
  EXPECT_EQ(a.positions[1], glm::vec3(2, 0, 0));
  EXPECT_EQ(a.positions[2], glm::vec3(0, 3, 0));
  EXPECT_EQ(a.normals[2], glm::vec3(0, 0, 1));
  EXPECT_EQ(a.uv[0], glm::vec2(0, 1));
  EXPECT_EQ(a.uv[1], glm::vec2(1, 0.2f));
  ASSERT_EQ(a.faces.size(), 1u);
  EXPECT_EQ(a.faces[0], glm::ivec3(2, 1, 0));
  const Ply& b = s[2];
  ASSERT_EQ(b.positions.size(), 3u);
  EXPECT_EQ(b.positions[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(b.positions[1], glm::vec3(5, 6, 7));
  EXPECT_EQ(b.positions[2], glm::vec3(0, 3, 0));
  EXPECT_EQ(b.uv[0], glm::vec2(0, 1));
  EXPECT_EQ(b.uv[1], glm::vec2(1, 0));
}

// Spec "Meshes": strip triangle i is (v_i, v_{i+1+i%2}, v_{i+2-i%2}), fan (v_{i+1}, v_{i+2},
// v_0); a node with a negative determinant reverses the winding (written reversed).
TEST(GltfGeometry, StripsFansAndMirrorsKeepTheSpecWinding) {
  Doc d;
  size_t five = d.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0});
  d.mesh({{"attributes", {{"POSITION", five}}}, {"mode", 5}});
  d.mesh({{"attributes", {{"POSITION", five}}}, {"mode", 6}});
  d.mesh({{"attributes", {{"POSITION", five}}}, {"mode", 1}});  // lines: warned, not drawn
  d.node({{"mesh", 0}, {"translation", {1.0, 0.0, 0.0}}});
  d.node({{"mesh", 1}, {"translation", {2.0, 0.0, 0.0}}});
  d.node({{"mesh", 0}, {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1}}});
  d.node({{"mesh", 2}, {"translation", {4.0, 0.0, 0.0}}});
  Imported im = import(d.done());
  std::map<double, Ply> s = shapes_by_x(im);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].faces, (std::vector<glm::ivec3>{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}}));
  EXPECT_EQ(s[2].faces, (std::vector<glm::ivec3>{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}}));
  EXPECT_EQ(s[3].faces, (std::vector<glm::ivec3>{{0, 2, 1}, {1, 2, 3}, {2, 4, 3}}));
  ASSERT_EQ(im.scene.warnings.size(), 1u);
  EXPECT_NE(im.scene.warnings[0].find("meshes[2].primitives[0].mode: points and lines"),
            std::string::npos);
}

std::string import_error(json g) {
  try {
    import(g);
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find("scene.gltf:"), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(GltfGeometry, MalformedAccessorsAreOneLineErrors) {
  auto with = [](auto change) {
    Doc d;
    size_t pos = d.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    d.mesh({{"attributes", {{"POSITION", pos}}}});
    d.node({{"mesh", 0}});
    json g = d.done();
    change(g);
    return import_error(g);
  };
  auto has = [](const std::string& m, const char* words) {
    EXPECT_NE(m.find(words), std::string::npos) << words << " not in: " << m;
  };
  has(with([](json& g) { g["accessors"][0]["count"] = 4; }),
      "accessors[0]: 4 elements of 12 bytes");
  has(with([](json& g) { g["bufferViews"][0]["byteLength"] = 400; }),
      "bufferViews[0]: bytes 0..400");
  has(with([](json& g) { g["accessors"][0]["type"] = "VEC2"; }),
      "accessors[0].type: expected VEC3");
  has(with([](json& g) { g["accessors"][0]["componentType"] = 5124; }),
      "unknown component type 5124");
  has(with([](json& g) { g["bufferViews"][0]["byteStride"] = 2; }),
      "byteStride: must be a multiple");
  has(with([](json& g) { g["meshes"][0]["primitives"][0]["indices"] = 7; }),
      "meshes[0].primitives[0].indices: index 7 out of range");
  has(with([](json& g) { g["accessors"][0].erase("bufferView"); }),
      "neither \"bufferView\" nor \"sparse\"");
  has(with([](json& g) {
        g["accessors"].push_back({{"bufferView", 0},
                                  {"byteOffset", 12},
                                  {"componentType", 5125},
                                  {"count", 3},
                                  {"type", "SCALAR"}});
        g["meshes"][0]["primitives"][0]["indices"] = 1;
      }),
      "vertex index 1065353216 out of range (3 vertices)");
  has(with([](json& g) { g["accessors"][0]["count"] = 2; }),
      "2 vertices do not make whole triangles");
  has(with([](json& g) { g["buffers"][0]["byteLength"] = 100; }), "buffers[0].byteLength: is 100");
  // Counts far beyond the data are refused before anything is allocated for them.
  has(with([](json& g) { g["accessors"][0]["count"] = 1LL << 40; }),
      "accessors[0]: 1099511627776 elements of 12 bytes from byte 0 do not fit");
  has(with([](json& g) {
        g["accessors"][0].erase("bufferView");
        g["accessors"][0]["count"] = 1LL << 30;
      }),
      "accessors[0].count: more elements than twinray reads without a bufferView");
}

}  // namespace
}  // namespace tr
