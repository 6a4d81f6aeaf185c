// Normal-map tangent frames of glTF primitives (scenes/gltf/gltf_tangents.h): the file's
// TANGENT, twinray's MikkTSpace tangents where the file has none, and their way into the scene.
#include "scenes/gltf/gltf_tangents.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gltf_test_support.h"
#include "scenes/gltf/gltf_accessors.h"
#include "scenes/gltf/gltf_buffers.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

using namespace gltf_test;

glm::dvec3 at(const std::vector<float>& v, std::uint32_t i) {
  return glm::dvec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
}

// Two unit squares in z = 0 facing +z, the right one with its u mirrored: glTF uvs (v runs down
// the image, so v = 1 - y). The seam x = 0 shares positions, normals and uvs.
ImportedMesh mirrored_squares() {
  ImportedMesh m;
  const float xs[3] = {-1.0f, 0.0f, 1.0f}, us[3] = {0.0f, 1.0f, 0.0f};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 3; ++col) {
      m.positions.insert(m.positions.end(), {xs[col], float(row), 0.0f});
      m.normals.insert(m.normals.end(), {0.0f, 0.0f, 1.0f});
      m.uv.insert(m.uv.end(), {us[col], 1.0f - float(row)});
    }
  for (std::uint32_t c = 0; c < 2; ++c)  // counter-clockwise seen from +z
    m.triangles.insert(m.triangles.end(), {c, c + 1, c + 4, c, c + 4, c + 3});
  return m;
}

TEST(GltfTangents, MirroredUvsKeepTheBitangentUpTheImage) {
  ImportedMesh m = mirrored_squares();
  generate_tangents(m);
  ASSERT_EQ(m.triangles.size(), 12u);
  // The seam's two vertices split: one frame each side.
  EXPECT_EQ(m.positions.size() / 3, 8u);
  for (size_t k = 0; k < m.triangles.size(); ++k) {
    std::uint32_t v = m.triangles[k];
    bool right = k >= 6;
    expect_vec(at(m.tangents, v), glm::dvec3(right ? -1.0 : 1.0, 0.0, 0.0), 1e-6);
    // glTF: +y of the normal texture is up the image, here +y of the squares, on both.
    expect_vec(at(m.bitangents, v), glm::dvec3(0.0, 1.0, 0.0), 1e-6);
  }
}

TEST(GltfTangents, TheFilesTangentAndHandednessMakeTheBitangent) {
  ImportedMesh m = mirrored_squares();
  std::vector<float> xyzw;
  for (size_t v = 0; v < 6; ++v) xyzw.insert(xyzw.end(), {1.0f, 0.0f, 0.0f, v % 2 ? -1.0f : 1.0f});
  set_gltf_tangents(m, xyzw);
  for (std::uint32_t v = 0; v < 6; ++v) {
    expect_vec(at(m.tangents, v), glm::dvec3(1.0, 0.0, 0.0));
    expect_vec(at(m.bitangents, v), glm::dvec3(0.0, v % 2 ? -1.0 : 1.0, 0.0));
  }
}

TEST(GltfTangents, TrianglesWithoutUvAreaTakeTheirVertexsTangent) {
  ImportedMesh m = mirrored_squares();
  // A sliver under the left square's bottom edge, its uvs on one line (v = 1).
  m.positions.insert(m.positions.end(), {-0.5f, -0.5f, 0.0f});
  m.normals.insert(m.normals.end(), {0.0f, 0.0f, 1.0f});
  m.uv.insert(m.uv.end(), {0.0f, 1.0f});
  m.triangles.insert(m.triangles.end(), {0, 6, 1});
  generate_tangents(m);
  for (size_t k = 12; k < 15; ++k) {
    std::uint32_t v = m.triangles[k];
    EXPECT_TRUE(std::isfinite(m.tangents[3 * v]));
    EXPECT_NEAR(glm::length(at(m.tangents, v)), 1.0, 1e-6);
    EXPECT_NEAR(glm::length(at(m.bitangents, v)), 1.0, 1e-6);
  }
  // Corner 12 is the position of vertex 0, whose only other corners lie in the left square.
  expect_vec(at(m.tangents, m.triangles[12]), glm::dvec3(1.0, 0.0, 0.0), 1e-6);
}

// The Khronos sample NormalTangentMirrorTest supplies tangents exported by Blender's MikkTSpace:
// twinray's, made from the same positions, normals and uvs, must agree at every corner: the
// same handedness, directions within 0.1 degrees (measured: 0.017 at worst, of 15720 corners;
// the file holds its tangents in float32).
TEST(GltfTangents, AgreeWithTheMikkTSpaceTangentsOfKhronosNormalTangentMirrorTest) {
  std::filesystem::path dir = std::filesystem::path(TWINRAY_SOURCE_DIR) /
                              "tests/scenes/gltf_khronos/NormalTangentMirrorTest";
  std::ifstream f(dir / "NormalTangentMirrorTest.gltf");
  nlohmann::json doc = nlohmann::json::parse(f);
  GltfBuffers buffers(
      doc, [&](const std::string& name) { return dir / name; }, "", false);
  GltfAccessors accessors(doc, buffers);
  ImportedMesh file = accessors.primitive(0, 0);
  ASSERT_FALSE(file.tangents.empty());
  ImportedMesh ours = file;
  ours.tangents.clear();
  ours.bitangents.clear();
  generate_tangents(ours);
  ASSERT_EQ(ours.triangles.size(), file.triangles.size());
  size_t corners = file.triangles.size(), handedness_agrees = 0;
  double worst = 0.0;
  for (size_t k = 0; k < corners; ++k) {
    std::uint32_t a = file.triangles[k], b = ours.triangles[k];
    glm::dvec3 n = glm::normalize(at(file.normals, a));
    glm::dvec3 t_file = at(file.tangents, a);
    t_file = glm::normalize(t_file - n * glm::dot(n, t_file));
    double angle =
        std::acos(std::clamp(glm::dot(t_file, at(ours.tangents, b)), -1.0, 1.0)) * 180.0 / M_PI;
    worst = std::max(worst, angle);
    handedness_agrees += glm::dot(at(file.bitangents, a), at(ours.bitangents, b)) > 0.0;
  }
  EXPECT_EQ(handedness_agrees, corners);
  EXPECT_LT(worst, 0.1) << "degrees, of " << corners << " corners";
}

}  // namespace
}  // namespace tr
