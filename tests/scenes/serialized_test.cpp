// The `serialized` shape: files written here in Mitsuba's layout (its serialized.cpp format
// description: versions 3 and 4, single and double precision, optional normals, uvs and
// colors, several meshes and the offset dictionary) load through the XML loader with Mitsuba
// 3.8's semantics, and every kind of bad file is a one-line SceneError.
#include "scenes/serialized.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <optional>

#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

struct MeshData {
  std::string name;
  std::vector<glm::dvec3> positions, normals, colors;
  std::vector<glm::dvec2> uvs;
  std::vector<uint32_t> indices;
  uint32_t extra_flags = 0;
  // When set, the header claims these counts instead of the true ones.
  std::optional<uint64_t> claimed_vertices, claimed_triangles;
};

struct Written {
  std::string bytes;
  std::vector<size_t> offsets;  // where each mesh starts
  size_t dictionary = 0;        // where the offset dictionary starts
};

template <typename T>
void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

// Mitsuba's layout: per mesh a uint16 format id 0x041C and uint16 version, then a zlib stream
// of flags, (v4) name, counts and arrays; then one offset per mesh (uint64 in v4, uint32 in
// v3) and the uint32 mesh count.
Written serialized_file(const std::vector<MeshData>& meshes, uint16_t version, bool doubles,
                        bool dictionary = true) {
  Written w;
  for (const MeshData& m : meshes) {
    std::string data;
    uint32_t flags = (m.normals.empty() ? 0u : 0x1u) | (m.uvs.empty() ? 0u : 0x2u) |
                     (m.colors.empty() ? 0u : 0x8u) | (doubles ? 0x2000u : 0x1000u) | m.extra_flags;
    put(data, flags);
    if (version >= 4) data += m.name + '\0';
    put<uint64_t>(data, m.claimed_vertices.value_or(m.positions.size()));
    put<uint64_t>(data, m.claimed_triangles.value_or(m.indices.size() / 3));
    auto values = [&](const auto& vectors) {
      for (const auto& v : vectors)
        for (int c = 0; c < v.length(); ++c)
          doubles ? put<double>(data, v[c]) : put<float>(data, float(v[c]));
    };
    values(m.positions);
    values(m.normals);
    values(m.uvs);
    values(m.colors);
    for (uint32_t i : m.indices) put(data, i);
    uLongf size = compressBound(uLong(data.size()));
    std::string packed(size, '\0');
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(packed.data()), &size,
                        reinterpret_cast<const Bytef*>(data.data()), uLong(data.size()), 9),
              Z_OK);
    w.offsets.push_back(w.bytes.size());
    put<uint16_t>(w.bytes, 0x041C);
    put<uint16_t>(w.bytes, version);
    w.bytes += packed.substr(0, size);
  }
  w.dictionary = w.bytes.size();
  if (dictionary) {
    for (size_t o : w.offsets)
      version >= 4 ? put<uint64_t>(w.bytes, o) : put<uint32_t>(w.bytes, uint32_t(o));
    put<uint32_t>(w.bytes, uint32_t(meshes.size()));
  }
  return w;
}

// A quad in the z = `z` plane with every per-vertex array, values that floats cannot hold
// exactly (so the double files are told apart), and non-unit normals (Mitsuba normalises).
MeshData quad(double z) {
  MeshData m;
  m.name = "quad " + std::to_string(z);
  m.positions = {{-1.1, -1, z}, {1.1, -1, z}, {1.1, 1, z}, {-1.1, 1, z}};
  m.normals.assign(4, glm::dvec3(0, 0, 2.5));
  m.uvs = {{0.1, 0}, {1, 0}, {1, 1.3}, {0, 1}};
  m.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3, 0.3, 0.3}};
  m.indices = {0, 1, 2, 2, 3, 0};
  return m;
}

// A single triangle with positions only.
MeshData triangle(double x) {
  MeshData m;
  m.name = "tri";
  m.positions = {{x, 0, 0}, {x + 1, 0, 0}, {x, 0, 1}};
  m.indices = {0, 1, 2};
  return m;
}

// A bent strip of two triangles with uvs only (normals must be recomputed).
MeshData bent() {
  MeshData m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  m.indices = {0, 1, 2, 0, 3, 1};
  return m;
}

std::string shape(const std::string& file, int index, const std::string& extra = "") {
  return "<shape type=\"serialized\"><string name=\"filename\" value=\"" + file +
         "\"/><integer name=\"shape_index\" value=\"" + std::to_string(index) + "\"/>" + extra +
         "</shape>\n";
}

Scene load_with(const std::filesystem::path& dir, const std::string& body) {
  return load_scene(write_file(dir, "scene.xml", scene_xml(body)), {});
}

// The shape's data as stored in the scene buffers must be the mesh's, with floats as the file
// gives them (doubles rounded to float) and unit normals.
void expect_mesh(const SceneBuffers& b, const Shape& s, const MeshData& m) {
  ASSERT_EQ(s.vertex_count, m.positions.size());
  ASSERT_EQ(s.triangle_count, m.indices.size() / 3);
  for (size_t v = 0; v < m.positions.size(); ++v) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(b.positions[s.first_vertex + v][c], float(m.positions[v][c])) << v;
    if (!m.normals.empty()) {
      glm::dvec3 n = glm::normalize(m.normals[v]);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(b.normals[s.first_vertex + v][c], n[c], 1e-6);
    }
    if (!m.uvs.empty()) {
      for (int c = 0; c < 2; ++c)
        EXPECT_EQ(b.uvs[s.first_vertex + v][c], float(m.uvs[v][c])) << v;  // not flipped
    }
  }
  for (size_t i = 0; i < m.indices.size(); ++i)
    EXPECT_EQ(b.indices[s.first_index + i], m.indices[i]);
  EXPECT_EQ(s.flags & SHAPE_HAS_UVS, m.uvs.empty() ? 0u : SHAPE_HAS_UVS);
  EXPECT_EQ(s.flags & SHAPE_HAS_NORMALS, SHAPE_HAS_NORMALS);  // given or recomputed
}

TEST(SerializedMeshes, EveryVersionPrecisionAndShapeIndex) {
  const std::vector<MeshData> meshes = {quad(0.25), triangle(3.7), bent(), quad(-0.5)};
  for (uint16_t version : {3, 4}) {
    for (bool doubles : {false, true}) {
      SCOPED_TRACE("version " + std::to_string(version) + (doubles ? " double" : " single"));
      std::filesystem::path dir = fresh_dir();
      write_file(dir, "m.serialized", serialized_file(meshes, version, doubles).bytes);
      // Reversed order, and the same file and index twice (loaded once, used twice).
      std::string body;
      for (int i = 3; i >= 0; --i) body += shape("m.serialized", i);
      body += shape("m.serialized", 1);
      Scene s = load_with(dir, body);
      const SceneBuffers& b = s.buffers;
      ASSERT_EQ(b.shapes.size(), 5u);
      for (int i = 0; i < 4; ++i) expect_mesh(b, b.shapes[3 - i], meshes[i]);
      expect_mesh(b, b.shapes[4], meshes[1]);
    }
  }
}

TEST(SerializedMeshes, DefaultIndexNamesAndVertexColors) {
  std::filesystem::path dir = fresh_dir();
  const std::vector<MeshData> meshes = {quad(1), triangle(0)};
  for (uint16_t version : {3, 4}) {
    std::string path = write_file(dir, "v" + std::to_string(version) + ".serialized",
                                  serialized_file(meshes, version, version == 3).bytes);
    SerializedMesh first = load_serialized_mesh(path, 0);
    EXPECT_EQ(first.name, version == 4 ? meshes[0].name : "");
    const VertexAttribute& color = first.mesh.attributes.at("vertex_color");
    EXPECT_EQ(color.dim, 3);
    ASSERT_EQ(color.values.size(), 12u);
    for (size_t v = 0; v < 4; ++v)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(color.values[3 * v + c], float(meshes[0].colors[v][c]));
    SerializedMesh second = load_serialized_mesh(path, 1);
    EXPECT_EQ(second.name, version == 4 ? "tri" : "");
    EXPECT_TRUE(second.mesh.attributes.empty());
  }
  // shape_index defaults to 0, which Mitsuba reads without the dictionary, so a file that
  // has none still loads there.
  write_file(dir, "bare.serialized", serialized_file({quad(1)}, 4, false, false).bytes);
  Scene s = load_with(dir,
                      "<shape type=\"serialized\"><string name=\"filename\" "
                      "value=\"bare.serialized\"/></shape>");
  expect_mesh(s.buffers, s.buffers.shapes[0], quad(1));
}

TEST(SerializedMeshes, HintAndTangentFlagsAreIgnoredAsInMitsuba3) {
  // Mitsuba 3.8 never reads the face-normals hint (0x10) nor tangents (0x4): the file's
  // normals are used, and nothing is read for tangents.
  MeshData m = quad(0);
  m.extra_flags = 0x10 | 0x4;
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "m.serialized", serialized_file({m}, 4, false).bytes);
  Scene s = load_with(dir, shape("m.serialized", 0));
  expect_mesh(s.buffers, s.buffers.shapes[0], m);
}

TEST(SerializedMeshes, MeshSemanticsAsObjAndPly) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "m.serialized", serialized_file({quad(0), bent()}, 4, false).bytes);
  const std::string to_world =
      "<transform name=\"to_world\"><scale x=\"2\" y=\"1\" z=\"0.5\"/><rotate y=\"1\" "
      "angle=\"30\"/><translate x=\"1\" y=\"2\" z=\"3\"/></transform>";
  Scene s = load_with(
      dir, shape("m.serialized", 0, to_world) +
               shape("m.serialized", 0, "<boolean name=\"face_normals\" value=\"true\"/>") +
               shape("m.serialized", 0, "<boolean name=\"flip_normals\" value=\"true\"/>") +
               shape("m.serialized", 1, to_world) +
               shape("m.serialized", 1,
                     "<bsdf type=\"conductor\"/><emitter type=\"area\"><rgb name=\"radiance\" "
                     "value=\"1, 2, 3\"/></emitter>"));
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.shapes.size(), 5u);
  glm::dmat4 m(1.0);
  m = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
      glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(0, 1, 0)) *
      glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 0.5));
  glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));

  // to_world: points by M, the file's normals by M^-T, renormalised.
  const Shape& a = b.shapes[0];
  MeshData q = quad(0);
  for (size_t v = 0; v < 4; ++v) {
    glm::dvec3 p(m * glm::dvec4(q.positions[v], 1.0));
    glm::dvec3 n = glm::normalize(normal_matrix * q.normals[v]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(b.positions[a.first_vertex + v][c], p[c], 1e-5);
      EXPECT_NEAR(b.normals[a.first_vertex + v][c], n[c], 1e-6);
    }
  }
  // The quad's area 2.2 * 2 times |M e_x x M e_y| = |R 2e_x x R e_y| = 2.
  EXPECT_NEAR(a.area, 4.4 * 2.0, 1e-4);
  EXPECT_EQ(b.shapes[1].flags, SHAPE_HAS_UVS);  // face_normals drops the file's normals
  EXPECT_EQ(b.shapes[2].flags, SHAPE_HAS_NORMALS | SHAPE_HAS_UVS | SHAPE_FLIP_NORMALS);

  // No normals in the file: Mitsuba's angle-weighted normals of the world-space mesh.
  const Shape& d = b.shapes[3];
  TriangleMesh world;
  for (const glm::dvec3& p : bent().positions) world.positions.emplace_back(m * glm::dvec4(p, 1.0));
  world.indices = bent().indices;
  std::vector<glm::vec3> expected = mesh_vertex_normals(world);
  for (size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(b.normals[d.first_vertex + v][c], expected[v][c], 1e-5) << v;
  // Vertex 0 is shared by both faces at right angles: the bisector, not either face normal.
  EXPECT_GT(std::abs(expected[0].y), 0.1);
  EXPECT_GT(std::abs(expected[0].z), 0.1);

  // Nested bsdf and emitter as on any mesh.
  const Shape& e = b.shapes[4];
  ASSERT_NE(e.emitter, NO_INDEX);
  EXPECT_EQ(b.emitters[e.emitter].radiance, vec3(1, 2, 3));
  EXPECT_EQ(b.materials[e.material].type, BSDF_CONDUCTOR);
  EXPECT_EQ(b.materials[a.material].type, BSDF_DIFFUSE);
}

// ---- bad input

// Loads a scene whose line 2 is a serialized shape and returns the SceneError's message after
// "scene.xml:"; fails the test when it loads.
std::string error_of(const std::filesystem::path& dir, const std::string& bytes, int index) {
  write_file(dir, "bad.serialized", bytes);
  std::string path = write_file(
      dir, "scene.xml",
      "<scene version=\"3.0.0\">\n<shape type=\"serialized\"><string name=\"filename\" "
      "value=\"bad.serialized\"/><integer name=\"shape_index\" value=\"" +
          std::to_string(index) + "\"/></shape>\n<sensor type=\"perspective\"/></scene>\n");
  try {
    load_scene(path, {});
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(m.rfind(path + ":2: ", 0), 0u) << m;
    EXPECT_NE(m.find("bad.serialized: "), std::string::npos) << m;  // names the mesh file
    return m.substr(path.size() + 1);
  }
  ADD_FAILURE() << "loaded";
  return "";
}

void expect_words(const std::string& message, const std::string& words) {
  EXPECT_NE(message.find(words), std::string::npos)
      << "expected \"" << words << "\" in " << message;
}

TEST(SerializedErrors, TruncatedFiles) {
  std::filesystem::path dir = fresh_dir();
  for (uint16_t version : {3, 4}) {
    Written w = serialized_file({quad(0), bent()}, version, version == 4);
    // Mesh 1 needs every byte, the dictionary included; mesh 0 every byte of its stream.
    for (size_t cut = 0; cut < w.bytes.size(); ++cut) {
      SCOPED_TRACE("version " + std::to_string(version) + ", cut at " + std::to_string(cut));
      error_of(dir, w.bytes.substr(0, cut), 1);
      if (cut < w.offsets[1]) {
        std::string e = error_of(dir, w.bytes.substr(0, cut), 0);
        if (cut >= 4) expect_words(e, "truncated file: the zlib stream breaks off");
      }
    }
    expect_words(error_of(dir, w.bytes.substr(0, 3), 0),
                 "truncated file: it ends inside the file header");
    expect_words(error_of(dir, w.bytes.substr(0, w.bytes.size() - 1), 1), "offset dictionary");
  }
}

TEST(SerializedErrors, BadHeaderAndVersion) {
  std::filesystem::path dir = fresh_dir();
  std::string bytes = serialized_file({quad(0)}, 4, false).bytes;
  std::string swapped = bytes;
  std::swap(swapped[0], swapped[1]);
  expect_words(error_of(dir, swapped, 0), "format identifier 0x1C04, expected 0x041C");
  expect_words(error_of(dir, "ply\nformat ascii 1.0\n", 0), "not a Mitsuba serialized mesh");
  for (uint16_t version : {0, 2, 5, 0x0400}) {
    std::string v = bytes;
    std::memcpy(&v[2], &version, 2);
    expect_words(error_of(dir, v, 0),
                 "unsupported serialized format version " + std::to_string(version));
  }
  // A dictionary offset that does not lead to a mesh header.
  Written w = serialized_file({quad(0), triangle(0)}, 4, false);
  uint64_t wrong = w.offsets[1] + 1;
  std::memcpy(&w.bytes[w.dictionary + 8], &wrong, 8);
  expect_words(error_of(dir, w.bytes, 1), "no mesh header at byte");
  wrong = w.bytes.size();
  std::memcpy(&w.bytes[w.dictionary + 8], &wrong, 8);
  expect_words(error_of(dir, w.bytes, 1), "past the mesh data");
}

TEST(SerializedErrors, ShapeIndexOutOfRange) {
  std::filesystem::path dir = fresh_dir();
  for (uint16_t version : {3, 4}) {
    std::string bytes = serialized_file({quad(0), triangle(0)}, version, false).bytes;
    expect_words(error_of(dir, bytes, 2),
                 "shape_index 2 is out of range: the file's offset "
                 "dictionary lists 2 meshes");
    expect_words(error_of(dir, bytes, 1000), "shape_index 1000 is out of range");
    expect_words(error_of(dir, bytes, -1), "shape_index must be a non-negative int");
  }
  // Without a dictionary the last bytes are the zlib checksum, not a plausible mesh count.
  expect_words(error_of(dir, serialized_file({quad(0)}, 4, false, false).bytes, 1),
               "bad.serialized");
}

TEST(SerializedErrors, CorruptZlibStreams) {
  std::filesystem::path dir = fresh_dir();
  Written w = serialized_file({quad(0), bent()}, 4, false);
  std::string bad = w.bytes;
  bad[4] = 0x00;  // the zlib header's CMF byte
  expect_words(error_of(dir, bad, 0),
               "corrupt zlib stream (incorrect header check), reading the flags of mesh 0");
  bad = w.bytes;
  bad[w.offsets[1] - 1] ^= 0x55;  // the last byte of mesh 0's Adler-32
  expect_words(error_of(dir, bad, 0), "(incorrect data check)");
  // Any byte of mesh 1's stream changed: zlib or the layout checks notice.
  for (size_t i = w.offsets[1] + 4; i < w.dictionary; ++i) {
    SCOPED_TRACE("byte " + std::to_string(i));
    bad = w.bytes;
    bad[i] ^= 0xFF;
    error_of(dir, bad, 1);
  }
}

TEST(SerializedErrors, CountsAndIndicesThatTheDataDoesNotHold) {
  std::filesystem::path dir = fresh_dir();
  MeshData m = quad(0);
  m.claimed_vertices = uint64_t(1) << 31;
  expect_words(error_of(dir, serialized_file({m}, 4, true).bytes, 0),
               "claims 2147483648 vertices and 2 triangles (188978561048 bytes), more than the "
               "rest of the file can hold");
  m.claimed_vertices = uint64_t(1) << 40;
  expect_words(error_of(dir, serialized_file({m}, 4, true).bytes, 0),
               "more than 32-bit indices address");
  m = quad(0);
  m.claimed_triangles = 3;
  expect_words(error_of(dir, serialized_file({m}, 3, false).bytes, 0),
               "the zlib stream ends inside the triangle indices of mesh 0: the header's counts "
               "exceed the data");
  m.claimed_triangles = 1;
  expect_words(error_of(dir, serialized_file({m}, 3, false).bytes, 0),
               "holds 12 bytes after its triangle indices");
  m = quad(0);
  m.claimed_triangles = 0;
  m.indices.clear();
  expect_words(error_of(dir, serialized_file({m}, 4, false).bytes, 0), "mesh 0 has no triangles");
  m = quad(0);
  m.indices[4] = 4;
  expect_words(error_of(dir, serialized_file({m}, 4, false).bytes, 0),
               "triangle 1 of mesh 0 uses vertex 4, but it has 4 vertices");
  m = quad(0);
  m.positions[2].y = std::numeric_limits<double>::quiet_NaN();
  expect_words(error_of(dir, serialized_file({m}, 4, false).bytes, 0),
               "mesh 0: a vertex position is NaN or infinite");
  m = quad(0);
  m.colors[1].x = 1e300;  // infinite as a float
  expect_words(error_of(dir, serialized_file({m}, 4, true).bytes, 0),
               "a value of vertex_color is NaN or infinite");
}

TEST(SerializedErrors, UnknownParameterAndMissingFile) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "m.serialized", serialized_file({quad(0)}, 4, false).bytes);
  std::string path = write_file(
      dir, "scene.xml",
      scene_xml(shape("m.serialized", 0, "<boolean name=\"flip_tex_coords\" value=\"true\"/>") +
                shape("none.serialized", 0)));
  try {
    load_scene(path, {});
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    expect_words(e.what(), "unused parameter 'flip_tex_coords'");
  }
  path = write_file(dir, "scene.xml", scene_xml(shape("none.serialized", 0)));
  try {
    load_scene(path, {});
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    expect_words(e.what(), "mesh file \"none.serialized\" not found");
  }
}

// Never crash on hostile input: every single-byte change of a two-mesh file, read at either
// index, loads or fails with a one-line SceneError.
TEST(SerializedErrors, CorruptedFilesFailCleanly) {
  std::filesystem::path dir = fresh_dir();
  Written w = serialized_file({quad(0), bent()}, 4, true);
  std::string xml = scene_xml(shape("f.serialized", 0) + shape("f.serialized", 1));
  std::string path = write_file(dir, "scene.xml", xml);
  int loaded = 0, rejected = 0;
  for (size_t i = 0; i < w.bytes.size(); ++i) {
    for (unsigned char flip : {0x01, 0x80, 0xFF}) {
      std::string bad = w.bytes;
      bad[i] ^= char(flip);
      write_file(dir, "f.serialized", bad);
      ++(loads_or_fails_cleanly(path) ? loaded : rejected);
    }
  }
  // Only the dictionary's first entry (mesh 0's offset, which mesh 0 never consults) and a few
  // zlib header bits (compression level) may change without consequence.
  EXPECT_GT(rejected, int(3 * w.bytes.size()) - 40);
  EXPECT_GT(loaded, 0);
}

// Mitsuba 3.8 skips a serialized mesh's vertex colors: a mesh_attribute texture finds no
// vertex_color there, and twinray refuses it when loading.
TEST(SerializedMesh, VertexColorsAreNoMeshAttribute) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "m.serialized", serialized_file({quad(0)}, 4, false).bytes);
  try {
    load_with(dir, shape("m.serialized", 0,
                         "<bsdf type=\"diffuse\"><texture type=\"mesh_attribute\" "
                         "name=\"reflectance\"><string name=\"name\" value=\"vertex_color\"/>"
                         "</texture></bsdf>"));
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("has no mesh attribute \"vertex_color\""),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tr
