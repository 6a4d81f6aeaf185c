// The OBJ reader against the semantics of Mitsuba 3's `obj` shape (src/shapes/obj.cpp): which
// lines it reads, how corners become vertices and faces become triangles, and what it refuses.
#include "scenes/obj_file.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

TriangleMesh read(const std::string& text, bool flip = true, bool face_normals = false) {
  return read_obj_file(write_file(fresh_dir(), "m.obj", text), flip, face_normals);
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjFile, PolygonsAreFansAndVerticesAreDistinctIndexTriples) {
  TriangleMesh m = read(kSquare + "vt 0 0.25\nvt 1 0.5\nvn 0 0 2\n" +
                        "g quad\nusemtl red\ns 1\n# a comment\n"
                        "f 1/1/1 2/2/1 3/2/1 4/1/1 1/2/1\n"
                        "f 1/1/1 3/2/1 4/1/1\n");
  ASSERT_EQ(m.indices.size(), 12u);
  // Fan (0, k, k + 1) over the five corners; the 5th corner (1/2/1) is a vertex of its own.
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 2, 3}));
  ASSERT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.positions[4], glm::vec3(0, 0, 0));
  EXPECT_EQ(m.uvs[0], glm::vec2(0, 0.75f));  // flipped: 1 - v
  EXPECT_EQ(m.uvs[4], glm::vec2(1, 0.5f));
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 2));  // normalized with the transform, later
  EXPECT_EQ(read(kSquare + "vt 0 0.25\nf 1/1 2/1 3/1\n", false).uvs[0], glm::vec2(0, 0.25f));
}

TEST(ObjFile, CornersReuseTheLinesPreviousTextureAndNormalIndices) {
  // Mitsuba keeps one key per face line: "2" after "1/2/1" is 2/2/1.
  TriangleMesh m = read(kSquare + "vt 0 0\nvt 1 1\nvn 0 0 1\nf 1/2/1 2 3\n");
  ASSERT_EQ(m.uvs.size(), 3u);
  for (const glm::vec2& uv : m.uvs) EXPECT_EQ(uv, glm::vec2(1, 0));
  EXPECT_EQ(m.normals.size(), 3u);
}

TEST(ObjFile, TextureAndNormalIndicesMayPointForward) {
  TriangleMesh m = read(kSquare + "f 1//1 2//1 3//1\nvn 1 0 0\n");
  EXPECT_EQ(m.normals[0], glm::vec3(1, 0, 0));
  EXPECT_TRUE(m.uvs.empty());
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n")
                .find("line 3: reference to vertex 3, but 2 are defined above it"),
            std::string::npos);
}

TEST(ObjFile, FaceNormalsSkipVnLines) {
  TriangleMesh m = read(kSquare + "vn 0 0 0\nf 1//1 2//1 3//1\n", true, true);
  EXPECT_TRUE(m.normals.empty());
  EXPECT_EQ(m.indices.size(), 3u);
}

TEST(ObjFile, AFaceEndsAtTheFirstThingThatIsNotACorner) {
  EXPECT_EQ(read(kSquare + "f 1 2 3 # 4\n").indices.size(), 3u);
  EXPECT_EQ(read(kSquare + "f 1 2 3x 4\nf 1 2 3\n").indices.size(), 3u);
  EXPECT_EQ(read(kSquare + "\tf\t1 2 3\r\n").indices.size(), 3u);
}

TEST(ObjFile, RefusesWhatMitsubaRefusesWithTheLine) {
  auto expect = [](const std::string& text, const std::string& what) {
    std::string e = error_of(text);
    EXPECT_NE(e.find(what), std::string::npos) << e;
  };
  expect(kSquare + "f -1 -2 -3\n", "line 5: relative face index -1");
  expect(kSquare + "f 0 1 2\n", "line 5: reference to vertex 0");
  expect(kSquare + "f 1 2 99999999999\n", "line 5: face index beyond 32 bits");
  expect(kSquare + "f 1/1/1/1 2 3\n", "line 5: a face corner has more than v/vt/vn");
  expect(kSquare + "vt 0 0\nf 1/2 2/1 3/1\n", "line 6: reference to texture coordinate 2, but");
  expect(kSquare + "vn 0 0 1\nf 1//1 2//3 3//1\n", "line 6: reference to normal 3, but");
  expect(kSquare + "vt 0 0\nf 1/1 2/1 3/1\nf 1//0 2 3\n",
         "line 7: a face corner without a texture coordinate");
  expect(kSquare + "vn 0 0 1\nf 1//1 2//1 3//1\nf 1 2 4\n",
         "line 7: a face corner without a normal");
  expect("v 0 0\n", "line 1: expected 3 numbers");
  expect("vt 0\n", "line 1: expected 2 numbers");
  expect("v 1e99 0 0\n", "line 1: expected 3 numbers");  // out of float's range
  expect("v nan 0 0\n", "line 1: vertex position is NaN or infinite");
  expect("vn 0 0 0\n", "line 1: vertex normal is zero");
  expect(kSquare + "vt nan 0\nf 1/1 2/1 3/1\n", "texture coordinate is NaN");
  expect(kSquare + std::string(1024, '#') + "\n", "line 5: a line of 1024 characters");
  expect(kSquare + "f 1 2\n", "the file contains no triangles");
}

TEST(ObjFile, ALineOf1023CharactersIsRead) {
  EXPECT_EQ(read(kSquare + std::string(1023, '#') + "\nf 1 2 3").indices.size(), 3u);
}

}  // namespace
}  // namespace tr
