// `twinray compare`: exit status, JSON summary and heatmap.
#include "app/compare_command.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/image.h"
#include "synthetic.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

class CompareCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("twinray_compare_" + std::to_string(getpid()));
    fs::create_directories(dir_);
    RgbImage ref = read_rgb(testing::arealight_refs() + ".exr");
    RgbImage var = read_rgb(testing::arealight_refs() + "_var.exr");
    write(path("good.exr"), testing::noisy_render(ref, var, 868.0, 1));
    RgbImage scaled = testing::noisy_render(ref, var, 868.0, 1);
    for (double& v : scaled.rgb) v *= 1.02;
    write(path("scaled.exr"), scaled);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  static void write(const std::string& p, const RgbImage& rgb) {
    Image img;
    img.width = rgb.width;
    img.height = rgb.height;
    img.channels = 3;
    img.pixels.assign(rgb.rgb.begin(), rgb.rgb.end());
    write_exr(p, img);
  }

  static int run(std::vector<std::string> args) {
    args.insert(args.begin(), "compare");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    int status = compare_command(int(argv.size()), argv.data());
    ::testing::internal::GetCapturedStdout();
    ::testing::internal::GetCapturedStderr();
    return status;
  }

  std::vector<std::string> with_variance(const std::string& image) const {
    return {image,     testing::arealight_refs() + ".exr",
            "--var-b", testing::arealight_refs() + "_var.exr",
            "--spp-a", "868",
            "--spp-b", "32000"};
  }

  static std::string slurp(const std::string& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  fs::path dir_;
};

TEST_F(CompareCommand, UnbiasedPassesWithJsonAndHeatmap) {
  std::vector<std::string> args = with_variance(path("good.exr"));
  args.insert(args.end(), {"--json", path("good.json"), "--heatmap", path("good.png")});
  EXPECT_EQ(run(args), 0);
  std::string json = slurp(path("good.json"));
  EXPECT_NE(json.find("\"verdict\": \"pass\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"block_z\""), std::string::npos);
  Image heat = read_image(path("good.png"));
  EXPECT_EQ(heat.width, 48);
}

TEST_F(CompareCommand, ScaledFails) {
  std::vector<std::string> args = with_variance(path("scaled.exr"));
  args.insert(args.end(),
              {"--json", path("scaled.json"), "--heatmap", path("z.png"), "--heatmap-metric", "z"});
  EXPECT_EQ(run(args), 1);
  EXPECT_NE(slurp(path("scaled.json")).find("\"verdict\": \"fail\""), std::string::npos);
  EXPECT_TRUE(fs::exists(path("z.png")));
}

TEST_F(CompareCommand, LockstepOfIdenticalImagesPasses) {
  EXPECT_EQ(run({path("good.exr"), path("good.exr"), "--lockstep"}), 0);
  EXPECT_EQ(run({path("scaled.exr"), path("good.exr"), "--lockstep"}), 1);
}

// A 4x4 patch off by 1% in alternating directions is a cluster; a rounding control that moves
// the patch marks it rounding-sensitive; a control of another size is bad input.
TEST_F(CompareCommand, RoundingControlExcusesSensitivePixels) {
  RgbImage good = read_rgb(path("good.exr"));
  int bx = 0, by = 0;  // the 4x4 block whose darkest value is the brightest
  double best = -1.0;
  for (int y0 = 0; y0 + 4 <= good.height; ++y0)
    for (int x0 = 0; x0 + 4 <= good.width; ++x0) {
      double darkest = INFINITY;
      for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 3; ++c) darkest = std::min(darkest, good.at(x0 + i % 4, y0 + i / 4, c));
      if (darkest > best) best = darkest, bx = x0, by = y0;
    }
  RgbImage patched = good, control = good;
  testing::scale_block(patched, bx, by, 0.99, 1.01);
  testing::scale_block(control, bx, by, 1.005, 1.005);
  write(path("patched.exr"), patched);
  write(path("control.exr"), control);
  EXPECT_EQ(run({path("patched.exr"), path("good.exr"), "--lockstep"}), 1);
  EXPECT_EQ(run({path("patched.exr"), path("good.exr"), "--lockstep", "--rounding-control",
                 path("control.exr")}),
            0);
  EXPECT_EQ(run({path("patched.exr"), path("good.exr"), "--lockstep", "--rounding-control",
                 path("good.exr")}),
            1);
  Image small;
  small.width = small.height = 8;
  small.channels = 3;
  small.pixels.assign(8 * 8 * 3, 0.5f);
  write_exr(path("small_control.exr"), small);
  EXPECT_EQ(run({path("patched.exr"), path("good.exr"), "--lockstep", "--rounding-control",
                 path("small_control.exr")}),
            2);
}

TEST_F(CompareCommand, SampleCountComesFromTwinrayMetadata) {
  Image good = read_image(path("good.exr"));
  good.metadata["twinray:spp"] = "868";
  write_exr(path("tagged.exr"), good);
  EXPECT_EQ(run({path("tagged.exr"), testing::arealight_refs() + ".exr", "--var-b",
                 testing::arealight_refs() + "_var.exr", "--spp-b", "32000", "--json",
                 path("tagged.json")}),
            0);
  EXPECT_NE(slurp(path("tagged.json")).find("\"gain_z\""), std::string::npos);
  // Without metadata or --spp-a the variance tests cannot run: a usage error.
  EXPECT_EQ(run({path("good.exr"), testing::arealight_refs() + ".exr", "--var-b",
                 testing::arealight_refs() + "_var.exr", "--spp-b", "32000"}),
            2);
}

TEST_F(CompareCommand, UnwritableOutputIsStatusFive) {
  EXPECT_EQ(run({path("good.exr"), path("good.exr"), "--json", path("no/such/dir/x.json")}), 5);
  EXPECT_EQ(run({path("good.exr"), path("good.exr"), "--heatmap", path("no/such/dir/x.png")}), 5);
}

TEST_F(CompareCommand, BadInputIsStatusTwo) {
  EXPECT_EQ(run({path("good.exr"), path("missing.exr")}), 2);
  EXPECT_EQ(run({path("good.exr")}), 2);
  EXPECT_EQ(run({path("good.exr"), path("good.exr"), "--spp-a", "zero"}), 2);
  EXPECT_EQ(run({path("good.exr"), path("good.exr"), "--bogus"}), 2);
  EXPECT_EQ(run({path("good.exr"), path("good.exr"), "--var-b", path("good.exr")}), 2);
  Image small;
  small.width = small.height = 8;
  small.channels = 3;
  small.pixels.assign(8 * 8 * 3, 0.5f);
  write_exr(path("small.exr"), small);
  EXPECT_EQ(run({path("small.exr"), path("good.exr")}), 2);
  EXPECT_EQ(run({"--help"}), 0);
}

}  // namespace
}  // namespace tr
