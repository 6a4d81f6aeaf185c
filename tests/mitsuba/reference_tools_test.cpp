// The tools of validation/mitsuba/make_reference: the pass scene (includes inlined, integrator
// wrapped in `moment`, float32 film, per-pass seed and spp) and the merge of the passes'
// moments in double precision.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <pugixml.hpp>
#include <string>

#include "validation/mitsuba/moment_merge.h"
#include "validation/mitsuba/pass_scene.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

class PassSceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pass_scene_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "fragments");
    fs::create_directories(dir_ / "assets");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  std::string derive(const PassSettings& s) {
    return pass_scene_xml((dir_ / "main.xml").string(), s);
  }

  fs::path dir_;
};

const char* kSensor = R"(
  <sensor type="perspective">
    <sampler type="independent">
      <integer name="sample_count" value="$spp"/>
      <integer name="seed" value="5"/>
    </sampler>
    <film type="hdrfilm">
      <integer name="width" value="4"/>
      <string name="component_format" value="float16"/>
    </film>
  </sensor>)";

TEST_F(PassSceneTest, InlinesIncludesWrapsTheIntegratorAndSetsSeedSppAndFloat32) {
  write("fragments/base.xml", std::string(R"(<scene version="3.0.0">
  <default name="spp" value="64"/>
  <integrator type="path"><integer name="max_depth" value="3"/></integrator>)") +
                                  kSensor + "\n</scene>");
  write("main.xml", R"(<scene version="3.0.0">
  <path value="assets"/>
  <include filename="fragments/base.xml"/>
  <bsdf type="diffuse" id="white"/>
</scene>)");
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(derive({7, 256, {}}).c_str()));
  pugi::xml_node scene = doc.child("scene");
  EXPECT_FALSE(scene.child("include"));
  EXPECT_EQ(fs::path(scene.child("path").attribute("value").value()),
            fs::absolute(dir_ / "assets").lexically_normal());
  pugi::xml_node moment = scene.child("integrator");
  EXPECT_STREQ(moment.attribute("type").value(), "moment");
  EXPECT_FALSE(moment.next_sibling("integrator"));
  pugi::xml_node path = moment.child("integrator");
  EXPECT_STREQ(path.attribute("type").value(), "path");
  EXPECT_STREQ(path.child("integer").attribute("value").value(), "3");
  pugi::xml_node sampler = scene.child("sensor").child("sampler");
  EXPECT_STREQ(sampler.find_child_by_attribute("name", "seed").attribute("value").value(), "7");
  EXPECT_STREQ(sampler.find_child_by_attribute("name", "sample_count").attribute("value").value(),
               "256");
  EXPECT_EQ(std::distance(sampler.children().begin(), sampler.children().end()), 2);
  pugi::xml_node film = scene.child("sensor").child("film");
  EXPECT_STREQ(film.find_child_by_attribute("name", "component_format").attribute("value").value(),
               "float32");
  EXPECT_STREQ(scene.child("bsdf").attribute("id").value(), "white");
}

TEST_F(PassSceneTest, KeepsAMomentIntegratorAndResolvesDollarTypes) {
  write("main.xml", std::string(R"(<scene version="2.0.0">
  <default name="integrator" value="moment"/>
  <integrator type="$integrator"><integrator type="direct"/></integrator>)") +
                        kSensor + "\n</scene>");
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(derive({0, 16, {}}).c_str()));
  pugi::xml_node outer = doc.child("scene").child("integrator");
  EXPECT_STREQ(outer.attribute("type").value(), "$integrator");
  EXPECT_STREQ(outer.child("integrator").attribute("type").value(), "direct");

  // A -D value overrides the <default>: the integrator is then `path` and gets wrapped.
  ASSERT_TRUE(doc.load_string(derive({0, 16, {{"integrator", "path"}}}).c_str()));
  outer = doc.child("scene").child("integrator");
  EXPECT_STREQ(outer.attribute("type").value(), "moment");
  EXPECT_STREQ(outer.child("integrator").attribute("type").value(), "$integrator");
}

TEST_F(PassSceneTest, AddsMomentOfPathWithoutAnIntegrator) {
  write("main.xml", std::string(R"(<scene version="3.0.0">)") + kSensor + "\n</scene>");
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(derive({0, 16, {}}).c_str()));
  pugi::xml_node outer = doc.child("scene").child("integrator");
  EXPECT_STREQ(outer.attribute("type").value(), "moment");
  EXPECT_STREQ(outer.child("integrator").attribute("type").value(), "path");
}

void expect_error(const std::string& message, const std::string& expected) {
  EXPECT_NE(message.find(expected), std::string::npos) << message;
}

TEST_F(PassSceneTest, RejectsWhatItCannotTurnIntoAPass) {
  const std::string two_sensors =
      std::string(R"(<scene version="3.0.0">)") + kSensor + kSensor + "\n</scene>";
  write("main.xml", two_sensors);
  try {
    derive({0, 16, {}});
    ADD_FAILURE() << "two sensors accepted";
  } catch (const PassSceneError& e) {
    expect_error(e.what(), "exactly one <sensor>, found 2");
  }

  write("main.xml", R"(<scene version="3.0.0">
  <include filename="fragments/missing.xml"/>
</scene>)");
  try {
    derive({0, 16, {}});
    ADD_FAILURE() << "missing include accepted";
  } catch (const PassSceneError& e) {
    expect_error(e.what(), "main.xml:2: included file 'fragments/missing.xml' not found");
  }

  write("main.xml", R"(<scene version="3.0.0">
  <integrator type="$kind"/>
</scene>)");
  try {
    derive({0, 16, {}});
    ADD_FAILURE() << "unresolved $kind accepted";
  } catch (const PassSceneError& e) {
    expect_error(e.what(), "main.xml:2: '$kind' has no -D value and no <default>");
  }

  write("main.xml", R"(<scene version="1.0.0"/>)");
  EXPECT_THROW(derive({0, 16, {}}), PassSceneError);

  std::string specfilm = std::string(R"(<scene version="3.0.0">)") + kSensor + "\n</scene>";
  specfilm.replace(specfilm.find("hdrfilm"), 7, "specfilm");
  write("main.xml", specfilm);
  try {
    derive({0, 16, {}});
    ADD_FAILURE() << "specfilm accepted";
  } catch (const PassSceneError& e) {
    expect_error(e.what(), "film type 'specfilm' is not supported");
  }
}

// A 1x1 pass whose `moment` channels hold the mean and second moment of `samples` (the same
// value in X, Y and Z), plus film colour channels the merge must ignore.
Image pass_of(std::initializer_list<double> samples) {
  double mean = 0.0, m2 = 0.0;
  for (double s : samples) {
    mean += s / samples.size();
    m2 += s * s / samples.size();
  }
  Image img;
  img.width = img.height = 1;
  img.channel_names = {"R",        "G",           "B",           "nested.X",   "nested.Y",
                       "nested.Z", "m2_nested.X", "m2_nested.Y", "m2_nested.Z"};
  img.channels = int(img.channel_names.size());
  img.pixels = {9, 9, 9, float(mean), float(mean), float(mean), float(m2), float(m2), float(m2)};
  return img;
}

TEST(MomentMerge, MeanAndPerSampleVarianceOfAllSamples) {
  // Samples {1, 3} and {5, 7}: mean 4, per-sample variance (1 + 9 + 25 + 49) / 4 - 16 = 5.
  MergedPasses m = merge_moment_passes({pass_of({1, 3}), pass_of({5, 7})}, {"a", "b"});
  EXPECT_EQ(m.clamped_variances, 0u);
  // Bitmap's XYZ -> RGB weights (Mitsuba 3.8.0 src/core/bitmap.cpp), row sums.
  const double row_sum[3] = {3.240479 - 1.537150 - 0.498535, -0.969256 + 1.875991 + 0.041556,
                             0.055648 - 0.204043 + 1.057311};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(m.mean.pixels[c], 4.0 * row_sum[c], 1e-6);
    EXPECT_NEAR(m.variance.pixels[c], 5.0 * row_sum[c], 1e-6);
  }
  EXPECT_EQ(m.mean.channel_names, (std::vector<std::string>{"R", "G", "B"}));
}

// Mitsuba's `aov` integrator nested in `moment`: its AOVs arrive as NAME.A / m2_NAME.A, an XYZ
// triple among them (NAME.pos.X/Y/Z) included; they are merged as they are, after R, G, B.
TEST(MomentMerge, MergesAovChannelsUnconvertedAfterTheColour) {
  auto with_aovs = [](std::initializer_list<double> samples, double depth_mean, double depth_m2) {
    Image img = pass_of(samples);
    const std::vector<std::pair<std::string, float>> extra = {{"nested.dd.T", float(depth_mean)},
                                                              {"nested.pos.X", 1.0f},
                                                              {"nested.pos.Y", 2.0f},
                                                              {"nested.pos.Z", 3.0f},
                                                              {"m2_nested.dd.T", float(depth_m2)},
                                                              {"m2_nested.pos.X", 1.0f},
                                                              {"m2_nested.pos.Y", 4.0f},
                                                              {"m2_nested.pos.Z", 9.0f}};
    for (const auto& [name, value] : extra) {
      img.channel_names.push_back(name);
      img.pixels.push_back(value);
    }
    img.channels = int(img.channel_names.size());
    return img;
  };
  // Depth samples {1, 3} and {5, 7} as in the colour test: mean 4, per-sample variance 5.
  MergedPasses m =
      merge_moment_passes({with_aovs({1, 3}, 2.0, 5.0), with_aovs({5, 7}, 6.0, 37.0)}, {"a", "b"});
  EXPECT_EQ(m.mean.channel_names,
            (std::vector<std::string>{"R", "G", "B", "dd.T", "pos.X", "pos.Y", "pos.Z"}));
  EXPECT_EQ(m.variance.channel_names, m.mean.channel_names);
  EXPECT_NEAR(m.mean.pixels[3], 4.0, 1e-6);
  EXPECT_NEAR(m.variance.pixels[3], 5.0, 1e-6);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(m.mean.pixels[4 + c], c + 1.0, 1e-6);
    EXPECT_NEAR(m.variance.pixels[4 + c], 0.0, 1e-6);
  }

  Image missing = with_aovs({1}, 1.0, 1.0);
  missing.channel_names[13] = "m2_nested.other";  // m2_nested.dd.T
  EXPECT_THROW(merge_moment_passes({missing}, {"missing"}), ImageError);
  EXPECT_THROW(merge_moment_passes({with_aovs({1}, 1.0, 1.0), pass_of({1})}, {"a", "plain"}),
               ImageError);
}

TEST(MomentMerge, SetsCancelledNegativeVariancesToZeroAndCountsThem) {
  Image img = pass_of({2, 2});
  for (int c = 6; c < 9; ++c) img.pixels[c] = std::nextafter(4.0f, 0.0f);
  MergedPasses m = merge_moment_passes({img}, {"a"});
  EXPECT_EQ(m.clamped_variances, 3u);
  EXPECT_LT(m.most_negative_variance, 0.0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(m.variance.pixels[c], 0.0f);
}

TEST(MomentMerge, RejectsPassesWithoutExactlyOneMomentSetOrOfOtherSizes) {
  Image none = pass_of({1});
  none.channel_names[6] = "other.X";
  EXPECT_THROW(merge_moment_passes({none}, {"none"}), ImageError);

  Image two = pass_of({1});
  for (const char* n : {"b.X", "b.Y", "b.Z", "m2_b.X", "m2_b.Y", "m2_b.Z"}) {
    two.channel_names.push_back(n);
    two.pixels.push_back(1.0f);
  }
  two.channels = int(two.channel_names.size());
  EXPECT_THROW(merge_moment_passes({two}, {"two"}), ImageError);

  Image wide = pass_of({1});
  wide.width = 2;
  wide.pixels.insert(wide.pixels.end(), wide.pixels.begin(), wide.pixels.end());
  EXPECT_THROW(merge_moment_passes({pass_of({1}), wide}, {"a", "wide"}), ImageError);
}

}  // namespace
}  // namespace tr
