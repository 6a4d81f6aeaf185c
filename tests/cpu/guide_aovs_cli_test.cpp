// `twinray render SCENE --aov albedo,sh_normal,depth` end to end: the binary writes one EXR
// whose channels are R, G, B and the guides' (named as the aov integrator names them), the
// guide values in the file match the closed form of tests/cpu/scenes/guide_sphere.xml
// (guide_aovs_check.h; the CPU backend: tests/gpu/guide_aovs_test.cpp checks the
// GPU's guides, the file writing is shared), and bad --aov requests exit with the
// documented status (app/exit_codes.h), a one-line message first on stderr and no output file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "guide_aovs_check.h"
#include "io/image.h"
#include "io/temp_file.h"

namespace tr {
namespace {

const std::string kScene = std::string(TWINRAY_TEST_SCENES) + "/guide_sphere.xml";

struct Run {
  int status = -1;
  std::string err;
};

Run twinray(const std::string& args, const std::string& dir) {
  const std::string err = dir + "/stderr.txt";
  const std::string cmd = std::string(TWINRAY_EXE) + " render " + args + " >/dev/null 2>" + err;
  const int rc = std::system(cmd.c_str());
  Run r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  std::stringstream s;
  s << std::ifstream(err).rdbuf();
  r.err = s.str();
  return r;
}

void expect_guides_in_file(const std::string& backend) {
  TemporaryDirectory dir;
  const std::string out = dir.path() + "/guide.exr";
  Run r =
      twinray(kScene + " --seed 7 --backend " + backend + " --aov albedo,sh_normal,depth -o " + out,
              dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  Image img = read_image(out);
  std::vector<std::string> names = img.channel_names, expected = {"R", "G", "B"};
  for (int g = 0; g < 3; ++g)
    for (int c = 0; c < test::kGuideChannelCount[g]; ++c)
      expected.push_back(test::kGuideChannels[g][c]);
  std::sort(names.begin(), names.end());
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(names, expected);
  auto index = [&](const std::string& name) {
    return int(std::find(img.channel_names.begin(), img.channel_names.end(), name) -
               img.channel_names.begin());
  };
  int channel[3][3];
  for (int g = 0; g < 3; ++g)
    for (int c = 0; c < test::kGuideChannelCount[g]; ++c)
      channel[g][c] = index(test::kGuideChannels[g][c]);
  Scene scene = load_scene(kScene, {});
  ASSERT_EQ(img.width, int(scene.buffers.globals.camera.width));
  ASSERT_EQ(img.height, int(scene.buffers.globals.camera.height));
  test::expect_guide_sphere(
      scene, 7, [&](uint x, uint y, int g, int c) { return double(img.at(x, y, channel[g][c])); },
      1e-5);
  // The variance file carries the same channels.
  Image var = read_image(dir.path() + "/guide_var.exr");
  std::vector<std::string> var_names = var.channel_names;
  std::sort(var_names.begin(), var_names.end());
  EXPECT_EQ(var_names, expected);
}

TEST(GuideAovsCli, CpuWritesGuidesOfTheClosedForm) { expect_guides_in_file("cpu"); }

void expect_refused(const std::string& args, int status, const std::string& message) {
  TemporaryDirectory dir;
  const std::string out = dir.path() + "/refused.exr";
  Run r = twinray(args + " -o " + out, dir.path());
  EXPECT_EQ(r.status, status) << r.err;
  const std::string first_line = r.err.substr(0, r.err.find('\n'));
  EXPECT_EQ(first_line, message);
  for (const char* name : {"/refused.exr", "/refused_var.exr", "/refused.png"})
    EXPECT_FALSE(std::filesystem::exists(dir.path() + name)) << name;
}

TEST(GuideAovsCli, UnknownTypeIsAUsageError) {
  expect_refused(kScene + " --aov albedo,normal", 2,
                 "twinray render: --aov: unknown AOV type 'normal' (valid: albedo, depth, "
                 "position, uv, geo_normal, sh_normal, prim_index, shape_index)");
  expect_refused(kScene + " --aov ''", 2,
                 "twinray render: --aov: empty entry in '' (expected TYPE or NAME:TYPE, "
                 "comma-separated)");
  expect_refused(kScene + " --aov depth --aov depth", 2,
                 "twinray render: --aov: AOV name 'depth' given twice");
}

TEST(GuideAovsCli, AovSceneIsRefused) {
  const std::string scene = std::string(TWINRAY_TEST_SCENES) + "/aov_sphere.xml";
  expect_refused(scene + " --aov albedo", 3,
                 "twinray: " + scene +
                     ":4: --aov: the scene's integrator is already <integrator type=\"aov\">; "
                     "put the guide AOVs into its aovs list or drop --aov");
}

}  // namespace
}  // namespace tr
