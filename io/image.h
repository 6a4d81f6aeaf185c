// Image files: read EXR, PNG, JPEG, RGBE, PFM, PNM, BMP and TGA (io/image_formats.h), write float
// EXR and 8-bit sRGB PNG.
// Writes are atomic: the image goes to a temporary file in the destination's directory which
// is then renamed over the destination, so a reader sees the old file or the new one, never a
// partial one, and a failed write leaves the old file untouched.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "io/temp_file.h"

namespace tr {

// Thrown by every function here; what() is one line, "path: what went wrong".
struct ImageError : FileError {
  using FileError::FileError;
};

struct Image {
  int width = 0, height = 0, channels = 0;
  // Row-major, top row first, channels interleaved; linear values (8-bit sRGB-encoded inputs
  // such as PNG and JPEG are decoded to linear when read; alpha is left as stored).
  std::vector<float> pixels;
  // String attributes of the file (EXR header attributes, PNG text chunks, ...).
  std::map<std::string, std::string> metadata;
  // One name per channel ("R", "G", "B", "A", "Y", ...); empty means the defaults of
  // default_channel_names().
  std::vector<std::string> channel_names;

  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

// An image produced row by row as it is written, so that no whole copy of it need exist (a
// render's outputs are developed from its film this way). row(y, out) fills `out` with row y
// (top row first): width * channels values, channels interleaved.
struct ImageRows {
  int width = 0, height = 0, channels = 0;
  std::vector<std::string> channel_names;  // empty: default_channel_names(channels)
  std::map<std::string, std::string> metadata;
  std::function<void(int y, float* out)> row;
};

// "Y" for 1 channel, "Y","A" for 2, "R","G","B" for 3, "R","G","B","A" for 4, "C0".. beyond.
std::vector<std::string> default_channel_names(int channels);

Image read_image(const std::string& path);

// 32-bit float EXR (ZIP compression); metadata entries become string attributes.
// `half`: store 16-bit floats (Mitsuba's hdrfilm component_format float16) instead of 32-bit.
void write_exr(const std::string& path, const Image& img, bool half = false);
void write_exr(const std::string& path, const ImageRows& img, bool half = false);

// 8-bit PNG: colour channels clamped to [0, 1] and sRGB-encoded (IEC 61966-2-1), alpha
// clamped and stored linearly; 1 to 4 channels. Metadata entries become text chunks.
void write_png_srgb(const std::string& path, const Image& img);
void write_png_srgb(const std::string& path, const ImageRows& img);

// Throws ImageError unless img has width*height*channels pixels and positive dimensions.
void check_image_shape(const std::string& path, const Image& img);

}  // namespace tr
