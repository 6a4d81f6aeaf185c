// Mitsuba 3.8's mesh attributes: how its PLY loader names and stores extra vertex and face
// properties (src/shapes/ply.cpp, ply.h), and the `mesh_attribute` texture's loading
// (src/textures/mesh_attribute.cpp) with the errors Mitsuba raises when it renders, here
// raised when loading.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_test_files.h"
#include "scenes/mesh.h"

namespace tr {
namespace {

using namespace testing_files;

// A quad of two triangles with 16-bit colors and a 1-channel property per vertex, and a
// 3-channel and a 1-channel (8-bit) property per face.
const std::string kQuadPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty ushort red\nproperty ushort green\nproperty ushort blue\n"
    "property float weight_x\nelement face 2\nproperty list uchar int vertex_indices\n"
    "property float color_0\nproperty float color_1\nproperty float color_2\n"
    "property uchar id_x\nend_header\n"
    "-1 -1 0 65535 0 51 0.25\n1 -1 0 0 65535 102 0.5\n1 1 0 0 0 30000 0.75\n"
    "-1 1 0 65535 65535 60000 1\n"
    "3 0 1 2 0.1 0.2 0.3 7\n3 0 2 3 0.4 0.5 0.6 8\n";

// Mitsuba's StructConverter turns a 16-bit property into float by normalizing and decoding
// sRGB (IEC 61966-2-1); 8-bit ones are taken as they are (scenes/mesh.cpp, ply_float).
float decoded(int ushort_value) {
  double c = ushort_value / 65535.0;
  return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

std::string ply_header(const std::string& vertex_properties) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\n" +
         vertex_properties + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
}

TriangleMesh load_ply(const std::string& text) {
  return load_ply_mesh(write_file(fresh_dir(), "m.ply", text), false);
}

TEST(PlyAttributes, VertexAndFacePropertiesAsMitsubaNamesThem) {
  TriangleMesh m = load_ply(kQuadPly);
  ASSERT_EQ(m.attributes.size(), 4u);
  const VertexAttribute& color = m.attributes.at("vertex_color");
  EXPECT_EQ(color.dim, 3);
  const int stored[4][3] = {{65535, 0, 51}, {0, 65535, 102}, {0, 0, 30000}, {65535, 65535, 60000}};
  ASSERT_EQ(color.values.size(), 12u);
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(color.values[3 * v + c], decoded(stored[v][c]));
  EXPECT_EQ(m.attributes.at("vertex_weight").dim, 1);
  EXPECT_EQ(m.attributes.at("vertex_weight").values,
            (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));
  EXPECT_EQ(m.attributes.at("face_color").dim, 3);
  EXPECT_EQ(m.attributes.at("face_color").values,
            (std::vector<float>{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f}));
  // uchar is not normalized: Mitsuba's flag test (Int8 <= type <= UInt64 in its Struct::Type
  // order UInt8, Int8, ...) leaves UInt8 out.
  EXPECT_EQ(m.attributes.at("face_id").values, (std::vector<float>{7.0f, 8.0f}));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(PlyAttributes, MitsubaGroupingRules) {
  // r, g, b with a: a 4-channel vertex_color; runs of _0 _1 _2, _r _g _b (named *_color) and
  // _1 _2 _3 become attributes; a run of two, a name without '_x'-style postfix and a postfix
  // of more than one letter are ignored, as Mitsuba ignores them (with a warning).
  TriangleMesh m = load_ply(
      ply_header("property float r\nproperty float g\nproperty float b\nproperty float a\n"
                 "property float n_0\nproperty float n_1\nproperty float n_2\n"
                 "property float q_r\nproperty float q_g\nproperty float q_b\n"
                 "property float k_1\nproperty float k_2\nproperty float k_3\n"
                 "property float two_x\nproperty float two_y\nproperty float plain\n"
                 "property float long_xx\n") +
      "0 0 0 .1 .2 .3 .4 1 2 3 4 5 6 7 8 9 0 0 0 0\n1 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n"
      "0 1 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n3 0 1 2\n");
  std::vector<std::string> names;
  for (const auto& [name, a] : m.attributes) names.push_back(name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"vertex_color", "vertex_k", "vertex_n", "vertex_q_color"}));
  EXPECT_EQ(m.attributes.at("vertex_color").dim, 4);
  EXPECT_EQ(std::vector<float>(m.attributes.at("vertex_color").values.begin(),
                               m.attributes.at("vertex_color").values.begin() + 4),
            (std::vector<float>{0.1f, 0.2f, 0.3f, 0.4f}));
  EXPECT_EQ(std::vector<float>(m.attributes.at("vertex_n").values.begin(),
                               m.attributes.at("vertex_n").values.begin() + 3),
            (std::vector<float>{1, 2, 3}));
  EXPECT_EQ(m.attributes.at("vertex_q_color").values[2], 6.0f);
  EXPECT_EQ(m.attributes.at("vertex_k").values[0], 7.0f);
  // red, green, blue, alpha are r, g, b, a; uvs and normals are not attributes.
  TriangleMesh named = load_ply(
      ply_header("property float nx\nproperty float ny\nproperty float nz\nproperty float s\n"
                 "property float t\nproperty float red\nproperty float green\n"
                 "property float blue\n") +
      "0 0 0 0 0 1 0 0 1 0 0\n1 0 0 0 0 1 1 0 0 1 0\n0 1 0 0 0 1 0 1 0 0 1\n3 0 1 2\n");
  ASSERT_EQ(named.attributes.size(), 1u);
  EXPECT_EQ(named.attributes.at("vertex_color").values,
            (std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(named.uvs.size(), 3u);
  EXPECT_EQ(named.normals.size(), 3u);
}

TEST(PlyAttributes, PolygonsSplitIntoTrianglesKeepTheirFaceValues) {
  TriangleMesh m = load_ply(
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
      "property float w_x\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n"
      "4 0 1 2 3 0.5\n3 1 4 2 0.25\n");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
  EXPECT_EQ(m.attributes.at("face_w").values, (std::vector<float>{0.5f, 0.5f, 0.25f}));
}

TEST(PlyAttributes, BinaryFileSameAsAscii) {
  std::string body;
  auto put = [&](const void* p, size_t n) { body.append(static_cast<const char*>(p), n); };
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (int v = 0; v < 3; ++v) {
    put(xyz[v], 12);
    unsigned short h = (unsigned short)(v * 30000);
    put(&h, 2);
  }
  unsigned char n = 3;
  int idx[3] = {0, 1, 2};
  put(&n, 1);
  put(idx, 12);
  double f = 0.125;
  put(&f, 8);
  TriangleMesh m = load_ply(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nproperty ushort h_x\nelement face 1\n"
      "property list uchar int vertex_indices\nproperty double d_x\nend_header\n" +
      body);
  const std::vector<float>& h = m.attributes.at("vertex_h").values;
  ASSERT_EQ(h.size(), 3u);
  EXPECT_EQ(h[0], 0.0f);
  double c = 30000.0 / 65535.0;
  EXPECT_FLOAT_EQ(h[1], float(std::pow((c + 0.055) / 1.055, 2.4)));
  EXPECT_EQ(m.attributes.at("face_d").values, (std::vector<float>{0.125f}));
}

// ---- the mesh_attribute texture

std::string ply_shape(const std::string& bsdf, const std::string& file = "quad.ply") {
  return "<shape type=\"ply\"><string name=\"filename\" value=\"" + file + "\"/>" + bsdf +
         "</shape>";
}

std::string attribute(const std::string& param, const std::string& name,
                      const std::string& extra = "") {
  return "<texture type=\"mesh_attribute\" name=\"" + param + "\"><string name=\"name\" value=\"" +
         name + "\"/>" + extra + "</texture>";
}

Scene load_body(const std::string& body) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.ply", kQuadPly);
  return load_scene(write_file(dir, "scene.xml", scene_xml(body)), {});
}

std::string error_of(const std::string& body) {
  try {
    load_body(body);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError for:\n" << body;
  return "";
}

float word_float(uint w) { return glm::uintBitsToFloat(w); }

TEST(MeshAttributeTexture, RecordsAndAttributeTable) {
  Scene s = load_body(
      ply_shape("<bsdf type=\"diffuse\">" +
                attribute("reflectance", "vertex_color", "<float name=\"scale\" value=\"0.5\"/>") +
                "</bsdf>") +
      ply_shape("<bsdf type=\"roughconductor\">" + attribute("alpha", "face_id") + "</bsdf>"));
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.shapes.size(), 2u);
  const Material& diffuse = b.materials[b.shapes[0].material];
  const Texture& color = b.textures[diffuse.param[0].texture];
  EXPECT_EQ(color.type, TEXTURE_MESH_ATTRIBUTE);
  EXPECT_EQ(color.attribute_per_face, 0u);
  EXPECT_EQ(color.color0.x, 0.5f);
  const Texture& id = b.textures[b.materials[b.shapes[1].material].param[3].texture];
  EXPECT_EQ(id.type, TEXTURE_MESH_ATTRIBUTE);
  EXPECT_EQ(id.attribute_per_face, 1u);
  EXPECT_EQ(id.color0.x, 1.0f);
  EXPECT_NE(color.attribute_slot, id.attribute_slot);
  // Each mesh's table has an entry per attribute name; it fills those it reads.
  const uint t0 = b.shapes[0].attribute_table, t1 = b.shapes[1].attribute_table;
  ASSERT_NE(t0, NO_INDEX);
  ASSERT_NE(t1, NO_INDEX);
  EXPECT_EQ(b.attributes[t0 + 2 * color.attribute_slot + 1], 3u);
  const uint values = b.attributes[t0 + 2 * color.attribute_slot];
  EXPECT_FLOAT_EQ(word_float(b.attributes[values + 5]), decoded(102));
  EXPECT_EQ(b.attributes[t1 + 2 * id.attribute_slot + 1], 1u);
  EXPECT_EQ(word_float(b.attributes[b.attributes[t1 + 2 * id.attribute_slot] + 1]), 8.0f);
  // A mesh without mesh_attribute textures has no table.
  Scene plain = load_body(ply_shape(""));
  EXPECT_EQ(plain.buffers.shapes[0].attribute_table, NO_INDEX);
  EXPECT_TRUE(plain.buffers.attributes.empty());
}

TEST(MeshAttributeTexture, Refusals) {
  // Mitsuba refuses a name containing neither vertex_ nor face_ when loading.
  EXPECT_NE(
      error_of(ply_shape("<bsdf type=\"diffuse\">" + attribute("reflectance", "color") + "</bsdf>"))
          .find("invalid attribute name \"color\""),
      std::string::npos);
  // What Mitsuba refuses when rendering: a missing attribute, a shape that is not a mesh, a
  // 3-channel attribute read by eval_1, a 1-channel one read by eval_3 (normalmap).
  std::string missing =
      error_of(ply_shape("<bsdf type=\"twosided\"><bsdf type=\"diffuse\">" +
                         attribute("reflectance", "vertex_uv") + "</bsdf></bsdf>"));
  EXPECT_NE(missing.find("scene.xml:5: <shape type=\"ply\"> has no mesh attribute \"vertex_uv\""),
            std::string::npos)
      << missing;
  EXPECT_NE(missing.find("it has: face_color, face_id, vertex_color, vertex_weight"),
            std::string::npos)
      << missing;
  EXPECT_NE(error_of("<shape type=\"sphere\"><bsdf type=\"diffuse\">" +
                     attribute("reflectance", "vertex_color") + "</bsdf></shape>")
                .find("only meshes have attributes"),
            std::string::npos);
  EXPECT_NE(error_of(ply_shape("<bsdf type=\"roughconductor\">" + attribute("alpha", "face_color") +
                               "</bsdf>"))
                .find("\"face_color\" has 3 channels; the mesh_attribute texture at"),
            std::string::npos);
  EXPECT_NE(error_of(ply_shape("<bsdf type=\"normalmap\">" + attribute("normalmap", "face_id") +
                               "<bsdf type=\"diffuse\"/></bsdf>"))
                .find("read as a normal map (3 channels"),
            std::string::npos);
  // A blend's weight and a mask's opacity are read with eval_1 as well, in nested materials.
  EXPECT_NE(error_of(ply_shape("<bsdf type=\"blendbsdf\">" + attribute("weight", "vertex_color") +
                               "<bsdf type=\"diffuse\"/><bsdf type=\"mask\">" +
                               attribute("opacity", "vertex_weight") +
                               "<bsdf type=\"diffuse\"/></bsdf></bsdf>"))
                .find("\"vertex_color\" has 3 channels"),
            std::string::npos);
  // plastic needs Texture::mean, which Mitsuba does not implement for mesh_attribute.
  EXPECT_NE(error_of(ply_shape("<bsdf type=\"plastic\">" +
                               attribute("diffuse_reflectance", "vertex_color") + "</bsdf>"))
                .find("has no mean"),
            std::string::npos);
  // An emitter's texture is not evaluated on a mesh.
  EXPECT_NE(
      error_of("<emitter type=\"spot\">" + attribute("texture", "vertex_color") + "</emitter>")
          .find("cannot be a mesh_attribute texture"),
      std::string::npos);
  EXPECT_NE(error_of(ply_shape("<bsdf type=\"diffuse\">" +
                               attribute("reflectance", "vertex_color",
                                         "<float name=\"gamma\" value=\"2\"/>") +
                               "</bsdf>"))
                .find("gamma"),
            std::string::npos);
}

}  // namespace
}  // namespace tr
