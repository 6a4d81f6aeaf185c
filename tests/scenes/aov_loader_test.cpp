// Mitsuba's `aov` integrator (src/integrators/aov.cpp) in the loader: the `aovs` list, channel
// names per type, the nested integrator, Mitsuba's shape_index order, and every refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

Scene load_body(const std::string& body) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.obj", QUAD_OBJ);
  return load_scene(write_file(dir, "scene.xml", scene_xml(body)), {});
}

// The error of loading `body`, which must name the line holding `marker`.
std::string error_of(const std::string& body, const std::string& marker) {
  std::filesystem::path dir = fresh_dir();
  std::string xml = scene_xml(body);
  std::string path = write_file(dir, "scene.xml", xml);
  int line = 1 + int(std::count(xml.begin(), xml.begin() + xml.find(marker), '\n'));
  try {
    load_scene(path, {});
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ":" + std::to_string(line) + ": ", 0), 0u) << m;
    return m;
  }
  ADD_FAILURE() << "no SceneError for:\n" << body;
  return "";
}

std::string aov(const std::string& list, const std::string& nested = "") {
  return "<integrator type=\"aov\">\n<string name=\"aovs\" value=\"" + list + "\"/>" + nested +
         "</integrator>";
}

TEST(AovLoader, EveryTypeWithItsChannels) {
  Scene s =
      load_body(aov("a:albedo, d.y:depth p:position,t:uv,,g:geo_normal  n:sh_normal,"
                    "i:prim_index,s:shape_index",
                    "<integrator type=\"direct\" name=\"image\"/>"));
  const Integrator& it = s.buffers.globals.integrator;
  ASSERT_EQ(it.aov_count, 8u);
  const uint types[8] = {AOV_ALBEDO,     AOV_DEPTH,     AOV_POSITION,   AOV_UV,
                         AOV_GEO_NORMAL, AOV_SH_NORMAL, AOV_PRIM_INDEX, AOV_SHAPE_INDEX};
  for (uint i = 0; i < 8; ++i) EXPECT_EQ(it.aov_types[i / 4][i % 4], types[i]) << i;
  const std::vector<std::vector<std::string>> channels = {{"a.R", "a.G", "a.B"},
                                                          {"d.y.T"},
                                                          {"p.X", "p.Y", "p.Z"},
                                                          {"t.U", "t.V"},
                                                          {"g.X", "g.Y", "g.Z"},
                                                          {"n.X", "n.Y", "n.Z"},
                                                          {"i.I"},
                                                          {"s.I"}};
  EXPECT_EQ(s.aov_channels, channels);
  EXPECT_EQ(it.type, INTEGRATOR_DIRECT);
  EXPECT_EQ(s.integrator_name, "aov(direct)");
}

// The nested integrator renders the colour with its own parameters, exactly as it would alone.
TEST(AovLoader, NestedIntegratorAsAlone) {
  const std::string path =
      "<integrator type=\"path\"><integer name=\"max_depth\" value=\"3\"/>"
      "<boolean name=\"hide_emitters\" value=\"true\"/></integrator>";
  Scene alone = load_body(path);
  Scene nested = load_body(aov("dd:depth", path));
  Integrator a = alone.buffers.globals.integrator, b = nested.buffers.globals.integrator;
  EXPECT_EQ(b.aov_count, 1u);
  b.aov_count = 0;
  b.aov_types[0] = uvec4(0u);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(Integrator)), 0);
}

// Without a nested integrator Mitsuba's colour channels are zero (aov.cpp: result {0, false}):
// a path integrator with max_depth 0 renders exactly that.
TEST(AovLoader, NoNestedIntegratorIsBlack) {
  Scene s = load_body(aov("dd:depth"));
  EXPECT_EQ(s.buffers.globals.integrator.type, INTEGRATOR_PATH);
  EXPECT_EQ(s.buffers.globals.integrator.max_depth, 0);
  EXPECT_EQ(s.integrator_name, "aov");
}

// Mitsuba 3.8's Scene::shapes() (scenes/build_shapes.cpp, number_shapes_as_mitsuba): area
// emitters first, then the other shapes and instances in document order, then the meshes,
// those with equal BSDFs and attributes merged into one with their triangles appended.
TEST(AovLoader, ShapeIndexIsMitsubasShapeOrder) {
  const std::string quad = "<string name=\"filename\" value=\"quad.obj\"/>";
  Scene s = load_body(aov("s:shape_index") + "<shape type=\"obj\">" + quad +
                      "</shape>\n"                  // mesh group 5
                      "<shape type=\"sphere\"/>\n"  // 1
                      "<shape type=\"shapegroup\" id=\"g\"><shape type=\"disk\"/></shape>\n"  // -
                      "<shape type=\"obj\">" +
                      quad +
                      "<bsdf type=\"conductor\"/></shape>\n"                       // mesh group 6
                      "<shape type=\"instance\"><ref id=\"g\"/></shape>\n"         // 2
                      "<shape type=\"cylinder\"/>\n"                               // 3
                      "<shape type=\"rectangle\"/>\n"                              // merged into 5
                      "<shape type=\"instance\"><ref id=\"g\"/></shape>\n"         // 4
                      "<shape type=\"disk\"><emitter type=\"area\"/></shape>\n");  // 0
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.instances.size(), 3u);
  ASSERT_EQ(b.instances[0].shape_count, 6u);
  const uint scene_index[6] = {5, 1, 6, 3, 5, 0};
  const uint prim_offset[6] = {0, NO_INDEX, 0, NO_INDEX, 2, NO_INDEX};
  for (uint i = 0; i < 6; ++i) {
    EXPECT_EQ(b.shapes[i].scene_index, scene_index[i]) << i;
    EXPECT_EQ(b.shapes[i].prim_offset, prim_offset[i]) << i;
  }
  EXPECT_EQ(b.instances[1].scene_index, 2u);
  EXPECT_EQ(b.instances[2].scene_index, 4u);
}

TEST(AovLoader, Refusals) {
  EXPECT_NE(error_of(aov("dd:velocity"), "aovs").find("invalid AOV type \"velocity\""),
            std::string::npos);
  EXPECT_NE(error_of(aov("dd:dp_du"), "aovs").find("\"dp_du\" is not supported by twinray"),
            std::string::npos);
  for (const std::string bad : {"depth", ":depth", "dd:", "dd:depth:x", "dd"})
    EXPECT_NE(error_of(aov(bad), "aovs").find("invalid AOV \"" + bad + "\""), std::string::npos)
        << bad;
  EXPECT_NE(error_of(aov("a:depth,a:depth"), "aovs").find("duplicate channel name \"a.T\""),
            std::string::npos);
  // The nested integrator's channels (name.R/G/B/A) collide with an albedo of the same name.
  EXPECT_NE(error_of(aov("image:albedo", "<integrator type=\"path\" name=\"image\"/>"), "aovs")
                .find("duplicate channel name \"image.R\""),
            std::string::npos);
  std::string many;
  for (int i = 0; i <= 16; ++i) many += "d" + std::to_string(i) + ":depth,";
  EXPECT_NE(error_of(aov(many), "aovs").find("more than 16 AOVs"), std::string::npos);
  EXPECT_NE(error_of("<integrator type=\"aov\">\n<integer name=\"aovs\" value=\"1\"/>"
                     "</integrator>",
                     "aovs")
                .find("aovs"),
            std::string::npos);
  EXPECT_NE(error_of("<integrator type=\"aov\">\n</integrator>", "aov").find("aovs"),
            std::string::npos);
  EXPECT_NE(error_of(aov("dd:depth", "<integrator type=\"path\"/>\n<integrator type=\"direct\"/>"),
                     "direct")
                .find("one nested integrator"),
            std::string::npos);
  EXPECT_NE(error_of(aov("dd:depth", "\n<integrator type=\"aov\"/>"), "type=\"aov\"/>")
                .find("nested aov integrators are not supported"),
            std::string::npos);
}

}  // namespace
}  // namespace tr
