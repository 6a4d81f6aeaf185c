// Image I/O: EXR round trip with metadata, sRGB PNG encoding, atomic writes, colormaps.
#include <Imath/half.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/colormap.h"
#include "io/heatmap.h"
#include "io/image.h"
#include "io/srgb.h"
#include "io/temp_file.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

// A fresh empty directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("twinray_io_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

Image ramp(int width, int height, int channels, float scale) {
  Image img;
  img.width = width;
  img.height = height;
  img.channels = channels;
  for (int i = 0; i < width * height * channels; ++i)
    img.pixels.push_back(scale * (float(i) - 3.5f) * (i % 2 ? 1.0f : 0.125f));
  return img;
}

TEST_F(ImageIoTest, ExrRoundTripKeepsPixelsExactlyAndMetadata) {
  Image img = ramp(5, 3, 3, 1.7f);
  img.pixels[4] = 1e30f;
  img.pixels[5] = 1e-30f;
  img.metadata["twinray:spp"] = "868";
  img.metadata["twinray:scene"] = "bsdf_spheres/test_arealight_path.xml";
  std::string path = (dir_ / "a.exr").string();
  write_exr(path, img);

  Image back = read_image(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.channels, 3);
  EXPECT_EQ(back.channel_names, (std::vector<std::string>{"R", "G", "B"}));
  EXPECT_EQ(back.pixels, img.pixels);
  EXPECT_EQ(back.metadata, img.metadata);  // the file's "type" is layout, not metadata
  EXPECT_EQ(entries(), std::vector<std::string>{"a.exr"});  // no temporary file left
  mode_t mask = umask(0);
  umask(mask);
  EXPECT_EQ(fs::status(path).permissions(), fs::perms(0666 & ~mask));  // not mkstemp's 0600
}

// The render's AOV layout: R, G, B, then layers; EXR stores channels sorted by name, the reader
// restores R, G, B first and each layer's R, G, B in order. Half values round to nearest.
TEST_F(ImageIoTest, ExrKeepsAovChannelOrderInHalf) {
  Image img = ramp(3, 2, 8, 0.3f);
  img.channel_names = {"R", "G", "B", "alb.R", "alb.G", "alb.B", "dd.T", "id.I"};
  std::string path = (dir_ / "aov.exr").string();
  write_exr(path, img, true);
  Image back = read_image(path);
  EXPECT_EQ(back.channel_names, img.channel_names);
  ASSERT_EQ(back.pixels.size(), img.pixels.size());
  for (size_t i = 0; i < img.pixels.size(); ++i)
    EXPECT_EQ(back.pixels[i], float(Imath::half(img.pixels[i]))) << i;
}

// Files of more than one chunk (16 scanlines a ZIP block), the last one partial.
TEST_F(ImageIoTest, ExrRoundTripOverSeveralChunks) {
  for (bool half : {false, true}) {
    Image img = ramp(7, 37, 4, 0.9f);
    img.channel_names = {"R", "G", "B", "A"};
    std::string path = (dir_ / "tall.exr").string();
    write_exr(path, img, half);
    Image back = read_image(path);
    ASSERT_EQ(back.height, 37);
    ASSERT_EQ(back.pixels.size(), img.pixels.size());
    for (size_t i = 0; i < img.pixels.size(); ++i)
      EXPECT_EQ(back.pixels[i], half ? float(Imath::half(img.pixels[i])) : img.pixels[i]) << i;
  }
}

// Noisy float data barely compresses: where zlib's output is exactly as long as the packed
// chunk, OpenEXR 3.1's encoder stored the zlib bytes under the size that readers take for an
// uncompressed chunk (OpenEXR issue 2306), and the chunk read back as garbage. One of two chunks
// (the encoder is reused from chunk to chunk) holds random bits led by k zeros, scanned over k
// through the size where zlib stops paying.
TEST_F(ImageIoTest, ExrRoundTripOfIncompressibleChunks) {
  Image img;
  img.width = 64;
  img.height = 32;
  img.channels = 3;
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  const size_t chunk = img.pixels.size() / 2;
  std::string path = (dir_ / "noise.exr").string();
  for (size_t noisy : {0, 1})
    for (size_t zeros = 0; zeros < 400; ++zeros) {
      std::fill(img.pixels.begin(), img.pixels.end(), 0.25f);
      uint32_t state = 12345u;
      for (size_t i = 0; i < chunk; ++i) {
        state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
        img.pixels[noisy * chunk + i] = i < zeros ? 0.0f : float(state >> 8) * 0x1p-24f;
      }
      write_exr(path, img);
      ASSERT_EQ(read_image(path).pixels, img.pixels)
          << "chunk " << noisy << ", " << zeros << " zeros";
    }
}

TEST_F(ImageIoTest, ReadsTheMitsubaReference) {
  Image ref =
      read_image(TWINRAY_SHARED_DIR
                 "/mitsuba-tests/tests/scenes/bsdf_spheres/refs/test_arealight_ref_rgb.exr");
  EXPECT_EQ(ref.width, 48);
  EXPECT_EQ(ref.height, 48);
  EXPECT_EQ(ref.channels, 3);
  float sum = 0.0f;
  for (float v : ref.pixels) sum += v;
  EXPECT_GT(sum, 0.0f);
}

TEST_F(ImageIoTest, PngIsSrgbEncodedAndDecodedOnRead) {
  Image img;
  img.width = 5;
  img.height = 1;
  img.channels = 1;
  img.pixels = {-1.0f, 0.0f, 0.5f, 1.0f, 7.0f};
  std::string path = (dir_ / "g.png").string();
  write_png_srgb(path, img);
  Image back = read_image(path);
  ASSERT_EQ(back.pixels.size(), 5u);
  // IEC 61966-2-1: 0.5 linear encodes to 0.735357, i.e. byte 188; outside [0, 1] clamps.
  const float expected[] = {0.0f, 0.0f, srgb_decode(188.0f / 255.0f), 1.0f, 1.0f};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(back.pixels[i], expected[i], 1e-6f) << i;
  EXPECT_NEAR(srgb_encode(0.5f), 0.735357f, 1e-6f);
  EXPECT_NEAR(srgb_decode(srgb_encode(0.2f)), 0.2f, 1e-6f);
}

TEST_F(ImageIoTest, ReadingAMissingFileNamesThePath) {
  std::string path = (dir_ / "missing.exr").string();
  try {
    read_image(path);
    FAIL() << "no exception";
  } catch (const ImageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
}

TEST_F(ImageIoTest, RejectedWriteLeavesTheOldFileIntact) {
  std::string path = (dir_ / "keep.exr").string();
  Image old = ramp(4, 4, 3, 1.0f);
  write_exr(path, old);
  Image bad = ramp(4, 4, 3, 2.0f);
  bad.pixels.pop_back();
  EXPECT_THROW(write_exr(path, bad), ImageError);
  EXPECT_THROW(write_png_srgb((dir_ / "keep.png").string(), bad), ImageError);
  EXPECT_EQ(read_image(path).pixels, old.pixels);
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.exr"});
}

TEST_F(ImageIoTest, FailedRenameRemovesTheTemporaryFile) {
  // The destination is a non-empty directory: the image is written to the temporary file,
  // then the rename fails; the directory must survive and no temporary file may remain.
  fs::create_directories(dir_ / "taken.exr");
  std::ofstream(dir_ / "taken.exr" / "inside") << "x";
  EXPECT_THROW(write_exr((dir_ / "taken.exr").string(), ramp(2, 2, 3, 1.0f)), ImageError);
  EXPECT_TRUE(fs::exists(dir_ / "taken.exr" / "inside"));
  EXPECT_EQ(entries(), std::vector<std::string>{"taken.exr"});
}

TEST_F(ImageIoTest, MissingDirectoryFailsCleanly) {
  EXPECT_THROW(write_exr((dir_ / "no" / "such" / "dir.exr").string(), ramp(2, 2, 3, 1.0f)),
               ImageError);
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIoTest, TextFileIsReplacedAtomically) {
  std::string path = (dir_ / "summary.json").string();
  write_text_file(path, "{\"a\": 1}\n");
  write_text_file(path, "{\"a\": 2}\n");
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "{\"a\": 2}\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"summary.json"});
  EXPECT_THROW(write_text_file((dir_ / "missing" / "x.json").string(), "x"), FileError);
}

// Reference values: matplotlib's magma and viridis tables (BIDS/colormap, CC0) at entries
// 0, 128 and 255 of 256; the minimax polynomial fits deviate by up to about 0.02.
TEST(Colormap, PolynomialFitsMatchTheTables) {
  struct Anchor {
    Colormap map;
    float t;
    float rgb[3];
  };
  const Anchor anchors[] = {
      {Colormap::magma, 0.0f, {0.001462f, 0.000466f, 0.013866f}},
      {Colormap::magma, 128.0f / 255.0f, {0.716387f, 0.214982f, 0.475290f}},
      {Colormap::magma, 1.0f, {0.987053f, 0.991438f, 0.749504f}},
      {Colormap::viridis, 0.0f, {0.267004f, 0.004874f, 0.329415f}},
      {Colormap::viridis, 128.0f / 255.0f, {0.127568f, 0.566949f, 0.550556f}},
      {Colormap::viridis, 1.0f, {0.993248f, 0.906157f, 0.143936f}},
  };
  for (const Anchor& a : anchors) {
    std::array<float, 3> rgb = colormap_srgb(a.map, a.t);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], a.rgb[c], 0.025f) << a.t << " " << c;
  }
}

TEST_F(ImageIoTest, HeatmapShowsTheColormapEnds) {
  std::string path = (dir_ / "heat.png").string();
  write_heatmap_png(path, 3, 1, {-5.0f, 0.0f, 2.0f}, 0.0f, 1.0f);
  Image back = read_image(path);
  ASSERT_EQ(back.channels, 3);
  std::array<float, 3> lo = colormap_srgb(Colormap::magma, 0.0f);
  std::array<float, 3> hi = colormap_srgb(Colormap::magma, 1.0f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(srgb_encode(back.at(0, 0, c)), lo[c], 1.0f / 255.0f);
    EXPECT_NEAR(srgb_encode(back.at(1, 0, c)), lo[c], 1.0f / 255.0f);
    EXPECT_NEAR(srgb_encode(back.at(2, 0, c)), hi[c], 1.0f / 255.0f);
  }
  EXPECT_THROW(write_heatmap_png(path, 2, 2, {0.0f}, 0.0f, 1.0f), ImageError);
  EXPECT_THROW(write_heatmap_png(path, 1, 1, {0.0f}, 1.0f, 1.0f), ImageError);
}

}  // namespace
}  // namespace tr
