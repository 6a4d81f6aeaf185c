// `--aov` guide buffers (scenes/guide_aovs.h) through LoadOptions::guide_aovs on the CPU: the
// wrapped sphere scene's albedo, shading normal and depth against the closed form, the colour
// left as the scene's own integrator renders it, every scene format, and the refusals.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "guide_aovs_check.h"
#include "render_fixture.h"

namespace tr {
namespace {

LoadOptions with_guides(const std::string& list) {
  LoadOptions load;
  load.guide_aovs = parse_guide_aovs(list);
  return load;
}

const std::vector<std::vector<std::string>> kGuideChannels = {
    {"albedo.R", "albedo.G", "albedo.B"},
    {"sh_normal.X", "sh_normal.Y", "sh_normal.Z"},
    {"depth.T"}};

TEST(GuideAovsCpu, SphereMatchesClosedForm) {
  Scene scene =
      load_scene(test::test_scene("guide_sphere.xml"), with_guides("albedo,sh_normal,depth"));
  EXPECT_EQ(scene.integrator_name, "aov(path)");
  EXPECT_EQ(scene.aov_channels, kGuideChannels);
  RenderOptions options;
  options.seed = 7;
  RenderResult r = render_cpu(scene, options);
  test::expect_guide_sphere_render(scene, r);
}

// The AOVs draw no random numbers and the nested integrator keeps its parameters (the scene's
// hide_emitters keeps the background black): the colour is bit for bit the unwrapped render's.
TEST(GuideAovsCpu, ColourIsTheScenesIntegrators) {
  RenderOptions options;
  options.seed = 3;
  options.spp = 4;
  RenderResult plain = test::render_file(test::test_scene("guide_sphere.xml"), options);
  RenderResult guided = test::render_file(test::test_scene("guide_sphere.xml"), options,
                                          with_guides("depth,n:sh_normal"));
  EXPECT_EQ(plain.aov_count, 0u);
  EXPECT_EQ(guided.aov_count, 2u);
  EXPECT_EQ(guided.mean, plain.mean);
}

TEST(GuideAovsCpu, ParsesTypesAndNames) {
  std::vector<GuideAov> a = parse_guide_aovs("albedo, nn:sh_normal ,d2:depth");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].name, "albedo");
  EXPECT_EQ(a[0].type, "albedo");
  EXPECT_EQ(a[1].name, "nn");
  EXPECT_EQ(a[1].type, "sh_normal");
  EXPECT_EQ(a[2].name, "d2");
  EXPECT_EQ(a[2].type, "depth");
}

// Every type the --aov list accepts is one the loader's aov integrator implements.
TEST(GuideAovsCpu, EveryListedTypeLoads) {
  Scene scene = load_scene(test::test_scene("guide_sphere.xml"), with_guides(guide_aov_types()));
  EXPECT_EQ(scene.buffers.globals.integrator.aov_count, 8u);
  ASSERT_EQ(scene.aov_channels.size(), 8u);
  EXPECT_EQ(scene.aov_channels[3], (std::vector<std::string>{"uv.U", "uv.V"}));
  EXPECT_EQ(scene.aov_channels[7], (std::vector<std::string>{"shape_index.I"}));
}

// A file in the temporary directory, named per process (several builds may test at once).
std::string write_file(const std::string& name, const std::string& text) {
  const std::string path =
      (std::filesystem::temp_directory_path() / (std::to_string(getpid()) + "_" + name)).string();
  std::ofstream(path) << text;
  return path;
}

// Without an integrator Mitsuba renders `path`: that is what gets wrapped.
TEST(GuideAovsCpu, SceneWithoutIntegratorWrapsPath) {
  const std::string path =
      write_file("twinray_guide_no_integrator.xml",
                 "<scene version=\"3.0.0\"><sensor type=\"perspective\"><film type=\"hdrfilm\">"
                 "<integer name=\"width\" value=\"4\"/><integer name=\"height\" value=\"4\"/>"
                 "</film></sensor><shape type=\"sphere\"/></scene>");
  Scene scene = load_scene(path, with_guides("albedo"));
  std::filesystem::remove(path);
  EXPECT_EQ(scene.integrator_name, "aov(path)");
  EXPECT_EQ(scene.buffers.globals.integrator.aov_count, 1u);
}

// The wrapping works on the parsed tree: a .scn scene gets the same guides.
TEST(GuideAovsCpu, ScnSceneGetsTheGuides) {
  const std::string path = write_file(
      "twinray_guide_sphere.scn",
      "{\"resolution\": [8, 8], \"camera\": {\"position\": [0, 1, 3], \"lookat\": [0, 1, 0], "
      "\"fov\": 40}, \"entities\": [{\"type\": \"sphere\"}]}");
  Scene plain = load_scene(path, {});
  Scene scene = load_scene(path, with_guides("albedo,sh_normal,depth"));
  std::filesystem::remove(path);
  EXPECT_EQ(scene.integrator_name, "aov(" + plain.integrator_name + ")");
  EXPECT_EQ(scene.aov_channels, kGuideChannels);
  EXPECT_EQ(scene.buffers.globals.integrator.max_depth, plain.buffers.globals.integrator.max_depth);
}

// ... and so does a glTF 2.0 one (a triangle seen by a camera node; one data-URI buffer of its
// three float32 positions).
TEST(GuideAovsCpu, GltfSceneGetsTheGuides) {
  const std::string path =
      write_file("twinray_guide_triangle.gltf",
                 R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
 "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [-1, -1, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri":
   "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]})");
  Scene plain = load_scene(path, {});
  Scene scene = load_scene(path, with_guides("albedo,sh_normal,depth"));
  std::filesystem::remove(path);
  EXPECT_EQ(plain.buffers.globals.integrator.aov_count, 0u);
  EXPECT_EQ(scene.integrator_name, "aov(" + plain.integrator_name + ")");
  EXPECT_EQ(scene.aov_channels, kGuideChannels);
}

void expect_invalid(const std::string& list, const std::string& message) {
  try {
    parse_guide_aovs(list);
    ADD_FAILURE() << "'" << list << "' accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(GuideAovsCpu, RefusesBadLists) {
  expect_invalid("albedo,normal",
                 "unknown AOV type 'normal' (valid: albedo, depth, position, uv, geo_normal, "
                 "sh_normal, prim_index, shape_index)");
  expect_invalid("albedo, ,depth",
                 "empty entry in 'albedo, ,depth' (expected TYPE or NAME:TYPE, comma-separated)");
  expect_invalid("", "empty entry in '' (expected TYPE or NAME:TYPE, comma-separated)");
  expect_invalid("depth,depth", "AOV name 'depth' given twice");
  expect_invalid("a.b:depth", "invalid AOV name 'a.b' (a letter, then letters, digits or '_')");
  expect_invalid("_arg_0:albedo",
                 "invalid AOV name '_arg_0' (a letter, then letters, digits or '_')");
  expect_invalid("x:dp_du",
                 "unknown AOV type 'dp_du' (valid: albedo, depth, position, uv, geo_normal, "
                 "sh_normal, prim_index, shape_index)");
}

TEST(GuideAovsCpu, RefusesASceneThatIsAlreadyAov) {
  const std::string path = test::test_scene("aov_sphere.xml");
  try {
    load_scene(path, with_guides("albedo"));
    ADD_FAILURE() << "an aov scene accepted --aov";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              path +
                  ":4: --aov: the scene's integrator is already <integrator type=\"aov\">; put "
                  "the guide AOVs into its aovs list or drop --aov");
  }
}

TEST(GuideAovsCpu, RefusesAMomentScene) {
  const std::string path = write_file(
      "twinray_guide_moment.xml",
      "<scene version=\"3.0.0\">\n<integrator type=\"moment\"><integrator type=\"path\"/>"
      "</integrator><sensor type=\"perspective\"/><shape type=\"sphere\"/></scene>");
  try {
    load_scene(path, with_guides("depth"));
    ADD_FAILURE() << "a moment scene accepted --aov";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              path +
                  ":2: --aov: the scene's integrator is <integrator type=\"moment\">, which "
                  "twinray cannot nest in aov; use the integrator it wraps (OUT_var.exr holds "
                  "the variance anyway)");
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace tr
