#include "io/image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "io/image_formats.h"
#include "io/srgb.h"
#include "io/temp_file.h"

namespace tr {

namespace {

bool is_alpha_name(const std::string& name) { return name == "A" || name == "a"; }

// Runs `write(temporary file name)`, then renames the temporary file over `path`.
template <class Write>
void write_atomic(const std::string& path, const Write& write) try {
  TempFile tmp(path);
  write(tmp.name());
  tmp.commit();
} catch (const ImageError&) {
  throw;
} catch (const FileError& e) {
  throw ImageError(e.what());
}

bool starts_with(const std::string& head, const char* magic) {
  return head.compare(0, std::strlen(magic), magic) == 0;
}

template <class ImageOrRows>
std::vector<std::string> names_of(const ImageOrRows& img) {
  return img.channel_names.empty() ? default_channel_names(img.channels) : img.channel_names;
}

template <class ImageOrRows>
void check_shape(const std::string& path, const ImageOrRows& img) {
  if (img.width <= 0 || img.height <= 0 || img.channels <= 0)
    fail_image(path, "image has no pixels (" + std::to_string(img.width) + "x" +
                         std::to_string(img.height) + "x" + std::to_string(img.channels) + ")");
  if (!img.channel_names.empty() && int(img.channel_names.size()) != img.channels)
    fail_image(path, "image has " + std::to_string(img.channels) + " channels but " +
                         std::to_string(img.channel_names.size()) + " channel names");
}

// The rows of a whole image (check_image_shape first); the result refers to img.
ImageRows rows_of(const Image& img) {
  ImageRows rows;
  rows.width = img.width;
  rows.height = img.height;
  rows.channels = img.channels;
  rows.channel_names = img.channel_names;
  rows.metadata = img.metadata;
  const size_t row_values = size_t(img.width) * img.channels;
  rows.row = [&img, row_values](int y, float* out) {
    std::copy_n(img.pixels.begin() + std::ptrdiff_t(size_t(y) * row_values), row_values, out);
  };
  return rows;
}

}  // namespace

std::vector<std::string> default_channel_names(int channels) {
  switch (channels) {
    case 1:
      return {"Y"};
    case 2:
      return {"Y", "A"};
    case 3:
      return {"R", "G", "B"};
    case 4:
      return {"R", "G", "B", "A"};
    default: {
      std::vector<std::string> names;
      for (int c = 0; c < channels; ++c) names.push_back("C" + std::to_string(c));
      return names;
    }
  }
}

void check_image_shape(const std::string& path, const Image& img) {
  check_shape(path, img);
  size_t expected = size_t(img.width) * img.height * img.channels;
  if (img.pixels.size() != expected)
    fail_image(path, "image holds " + std::to_string(img.pixels.size()) +
                         " values, its shape needs " + std::to_string(expected));
}

Samples read_samples(const std::string& path, const HeaderCheck& check) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
  std::string head(8, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  in.close();
  if (starts_with(head, "\x76\x2f\x31\x01")) return read_exr_samples(path, check);
  if (starts_with(head, "\x89PNG")) return read_png_samples(path, check);
  if (starts_with(head, "\xff\xd8\xff")) return read_jpeg_samples(path, check);
  if (starts_with(head, "PF") || starts_with(head, "Pf")) return read_pfm_samples(path, check);
  if (starts_with(head, "P5") || starts_with(head, "P6")) return read_pnm_samples(path, check);
  return read_stb_samples(path, check);
}

[[noreturn]] void fail_image(const std::string& path, const std::string& what) {
  std::string line = path + ": " + what;
  std::replace(line.begin(), line.end(), '\n', ' ');
  throw ImageError(line);
}

Image read_image(const std::string& path) {
  Samples s = read_samples(path, [](int, int, int) {});
  if (s.cropped)
    fail_image(
        path, "the data window differs from the display window (cropped images are not supported)");
  Image img;
  img.width = s.width;
  img.height = s.height;
  img.channels = s.channels;
  img.channel_names = std::move(s.channel_names);
  img.metadata = std::move(s.metadata);
  img.pixels = std::move(s.values);
  if (!s.floating) {
    for (int c = 0; c < img.channels; ++c) {
      if (is_alpha_name(img.channel_names[c])) continue;
      for (size_t i = c; i < img.pixels.size(); i += img.channels)
        img.pixels[i] = srgb_decode(img.pixels[i]);
    }
  }
  return img;
}

void write_exr(const std::string& path, const ImageRows& img, bool half) {
  check_shape(path, img);
  const std::vector<std::string> names = names_of(img);
  write_atomic(path,
               [&](const std::string& file) { write_exr_file(path, file, img, names, half); });
}

void write_exr(const std::string& path, const Image& img, bool half) {
  check_image_shape(path, img);
  write_exr(path, rows_of(img), half);
}

void write_png_srgb(const std::string& path, const ImageRows& img) {
  check_shape(path, img);
  if (img.channels > 4)
    fail_image(path, "PNG holds at most 4 channels, image has " + std::to_string(img.channels));
  const std::vector<std::string> names = names_of(img);
  std::vector<bool> alpha(img.channels);
  for (int c = 0; c < img.channels; ++c) alpha[c] = is_alpha_name(names[c]);
  std::vector<float> values(size_t(img.width) * img.channels);
  auto encoded_row = [&](int y, unsigned char* out) {
    img.row(y, values.data());
    for (size_t i = 0; i < values.size(); ++i) {
      float v = values[i];
      float encoded = alpha[i % img.channels]
                          ? std::fmin(std::fmax(v, 0.0f), 1.0f)  // fmax maps NaN to 0
                          : srgb_encode(v);
      out[i] = std::uint8_t(std::lround(encoded * 255.0f));
    }
  };
  write_atomic(path, [&](const std::string& file) {
    write_png_file(path, file, img.width, img.height, img.channels, encoded_row, img.metadata);
  });
}

void write_png_srgb(const std::string& path, const Image& img) {
  check_image_shape(path, img);
  write_png_srgb(path, rows_of(img));
}

}  // namespace tr
