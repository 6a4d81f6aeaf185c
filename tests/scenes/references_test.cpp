// Mitsuba's reference semantics: <ref> resolves to an object declared anywhere in the scene
// (before or after it, in any included file); top-level objects with ids of every kind.
#include <gtest/gtest.h>

#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

Scene load_body(const std::string& body) {
  return load_scene(write_file(fresh_dir(), "scene.xml", scene_xml(body)), {});
}

std::string error_of(const std::string& xml) {
  try {
    load_scene(write_file(fresh_dir(), "scene.xml", xml), {});
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError for:\n" << xml;
  return "";
}

TEST(SceneReferences, AnAreaEmitterAndABsdfDeclaredAfterTheShapeThatUsesThem) {
  // The layout of Mitsuba's Cornell box (cbox-rgb.xml): shapes first, then the emitter.
  Scene s = load_body(
      "<shape type=\"sphere\"><ref id=\"red\"/><ref id=\"light\"/></shape>"
      "<bsdf type=\"diffuse\" id=\"red\"><rgb name=\"reflectance\" value=\"0.5 0.1 0.1\"/></bsdf>"
      "<emitter type=\"area\" id=\"light\"><rgb name=\"radiance\" value=\"2 3 4\"/></emitter>");
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.emitters.size(), 1u);
  EXPECT_EQ(b.emitters[0].type, EMITTER_AREA);
  EXPECT_EQ(b.emitters[0].radiance, vec3(2, 3, 4));
  ASSERT_EQ(b.shapes.size(), 1u);
  EXPECT_EQ(b.shapes[0].emitter, 0u);
}

TEST(SceneReferences, ASamplerAndAFilmDeclaredAtTheTopLevel) {
  std::string xml =
      "<scene version=\"3.0.0\">\n"
      "  <sensor type=\"perspective\"><ref id=\"s\"/><ref id=\"f\"/></sensor>\n"
      "  <sampler type=\"independent\" id=\"s\"><integer name=\"sample_count\" value=\"7\"/>"
      "<integer name=\"seed\" value=\"5\"/></sampler>\n"
      "  <film type=\"hdrfilm\" id=\"f\"><integer name=\"width\" value=\"16\"/>"
      "<integer name=\"height\" value=\"4\"/><ref id=\"r\"/></film>\n"
      "  <rfilter type=\"box\" id=\"r\"/>\n"
      "</scene>\n";
  Scene s = load_scene(write_file(fresh_dir(), "scene.xml", xml), {});
  EXPECT_EQ(s.spp, 7u);
  EXPECT_EQ(s.seed, 5u);
  EXPECT_EQ(s.buffers.globals.camera.width, 16u);
  EXPECT_EQ(s.buffers.globals.camera.height, 4u);
  EXPECT_EQ(s.buffers.globals.camera.rfilter, uint(RFILTER_BOX));
}

TEST(SceneReferences, ReferencesIntoAndOutOfIncludedFiles) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "materials.xml",
             "<scene version=\"3.0.0\"><bsdf type=\"conductor\" id=\"metal\"/>"
             "<shape type=\"sphere\"><ref id=\"lamp\"/></shape></scene>");
  std::string path = write_file(dir, "scene.xml",
                                scene_xml("<shape type=\"sphere\"><ref id=\"metal\"/></shape>"
                                          "<include filename=\"materials.xml\"/>"
                                          "<emitter type=\"area\" id=\"lamp\"/>"));
  Scene s = load_scene(path, {});
  EXPECT_EQ(s.buffers.shapes.size(), 2u);
  EXPECT_EQ(s.buffers.emitters.size(), 1u);
}

TEST(SceneReferences, Errors) {
  std::string e = error_of(scene_xml("<shape type=\"sphere\">\n<ref id=\"nothing\"/></shape>"));
  EXPECT_NE(e.find(":6: <ref id=\"nothing\">: no object in the scene has this id"),
            std::string::npos)
      << e;
  e = error_of(scene_xml(
      "<shape type=\"sphere\"><bsdf type=\"twosided\" id=\"a\">\n<ref id=\"a\"/></bsdf></shape>"));
  EXPECT_NE(e.find(":6: <bsdf type=\"twosided\"> (id \"a\") contains itself"), std::string::npos)
      << e;
  // Objects that only act where something refers to them: refused when nothing does, as an
  // unread parameter is (Mitsuba would silently ignore them).
  e = error_of(scene_xml("\n<emitter type=\"area\" id=\"orphan\"/>"));
  EXPECT_NE(e.find(":6: <emitter type=\"area\"> (id \"orphan\") is declared at the top level "
                   "but nothing refers to it"),
            std::string::npos)
      << e;
  e = error_of(scene_xml("\n<sampler type=\"independent\"/>"));
  EXPECT_NE(e.find(":6: <sampler type=\"independent\"> is declared at the top level"),
            std::string::npos)
      << e;
}

}  // namespace
}  // namespace tr
