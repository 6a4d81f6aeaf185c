// The scenes of an area emitter with a textured radiance (core/emitters/area.h), shared by the CPU
// and GPU tests: their bitmaps, written as float EXRs when first needed, and the closed form of
// tests/cpu/scenes/textured_emitter_view.xml.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io/image.h"
#include "render/render.h"
#include "scenes/load_scene.h"

namespace tr::test {

// The view scene's 4 x 2 texels, row 0 at the top of the image: every channel differs, so that
// a texel read from the wrong place or in the wrong channel order shows.
const int kViewTexelsWide = 4;
const int kViewTexelsHigh = 2;
const glm::vec3 kViewTexels[kViewTexelsHigh][kViewTexelsWide] = {
    {{0.5f, 1.0f, 2.0f}, {3.0f, 0.25f, 1.5f}, {0.0f, 4.0f, 0.75f}, {2.5f, 2.0f, 0.0f}},
    {{1.25f, 0.0f, 3.5f}, {6.0f, 5.0f, 4.0f}, {0.125f, 0.375f, 0.625f}, {1.0f, 7.0f, 0.5f}}};

// The floor scene's texel columns: the light's x < 0 half, then its x > 0 half (each twice, as a
// 2 x 2 bitmap: Mitsuba resamples bitmaps of one row, which twinray refuses).
const glm::vec3 kFloorTexels[2] = {{4.0f, 1.0f, 0.5f}, {0.5f, 2.0f, 6.0f}};

// Writes `texels` (row-major, top row first) as a float EXR in a temporary folder.
inline std::string write_texture(const std::string& name, int width, int height,
                                 const glm::vec3* texels) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "twinray_textured_emitter";
  std::filesystem::create_directories(dir);
  Image image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  for (int i = 0; i < width * height; ++i)
    image.pixels.insert(image.pixels.end(), {texels[i].x, texels[i].y, texels[i].z});
  const std::string path = (dir / (name + ".exr")).string();
  write_exr(path, image);
  return path;
}

inline std::string rgb_value(const glm::vec3& c) {
  return std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z);
}

inline LoadOptions view_scene_options() {
  LoadOptions load;
  load.defines = {
      {"texture", write_texture("view", kViewTexelsWide, kViewTexelsHigh, &kViewTexels[0][0])}};
  return load;
}

inline LoadOptions floor_scene_options() {
  LoadOptions load;
  const glm::vec3 texels[4] = {kFloorTexels[0], kFloorTexels[1], kFloorTexels[0], kFloorTexels[1]};
  load.defines = {{"texture", write_texture("floor", 2, 2, texels)}};
  return load;
}

// textured_emitter_view.xml's closed form. Pixel (c, r) of the 8 x 8 film sees the rectangle
// [-1, 1]^2 at x = -1 + (c + 1/2) / 4, y = 1 - (r + 1/2) / 4 (Mitsuba's look-at: +x to the right
// of the image here), whose uv is ((x + 1) / 2, (y + 1) / 2) (Mitsuba's rectangle), so that it
// reads texel (floor(4 u), floor(2 v)) = (c / 2, r < 4 ? 1 : 0): the texture's top row is at
// v = 0, the rectangle's bottom edge. Every sample of a pixel lands in its texel, so each pixel
// is its texel up to the float rounding of the mean.
inline void expect_texel_view(const RenderResult& r, const std::string& what) {
  ASSERT_EQ(r.width, 8u);
  ASSERT_EQ(r.height, 8u);
  EXPECT_EQ(r.stats.rejected_nonfinite, 0u) << what;
  for (uint32_t row = 0; row < 8; ++row)
    for (uint32_t col = 0; col < 8; ++col) {
      const glm::vec3 texel = kViewTexels[row < 4 ? 1 : 0][col / 2];
      for (int k = 0; k < 3; ++k) {
        const double value = r.mean[(size_t(row) * 8 + col) * 3 + k];
        EXPECT_NEAR(value, double(texel[k]), 1e-6 * double(texel[k]))
            << what << ": pixel (" << col << ", " << row << ") channel " << k;
      }
    }
}

}  // namespace tr::test
