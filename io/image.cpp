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

std::vector<std::string> names_of(const Image& img) {
  return img.channel_names.empty() ? default_channel_names(img.channels) : img.channel_names;
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
  if (img.width <= 0 || img.height <= 0 || img.channels <= 0)
    fail_image(path, "image has no pixels (" + std::to_string(img.width) + "x" +
                         std::to_string(img.height) + "x" + std::to_string(img.channels) + ")");
  size_t expected = size_t(img.width) * img.height * img.channels;
  if (img.pixels.size() != expected)
    fail_image(path, "image holds " + std::to_string(img.pixels.size()) +
                         " values, its shape needs " + std::to_string(expected));
  if (!img.channel_names.empty() && int(img.channel_names.size()) != img.channels)
    fail_image(path, "image has " + std::to_string(img.channels) + " channels but " +
                         std::to_string(img.channel_names.size()) + " channel names");
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

void write_exr(const std::string& path, const Image& img, bool half) {
  check_image_shape(path, img);
  write_atomic(path, [&](const std::string& file) {
    write_exr_file(path, file, img.width, img.height, names_of(img), img.pixels, img.metadata,
                   half);
  });
}

void write_png_srgb(const std::string& path, const Image& img) {
  check_image_shape(path, img);
  if (img.channels > 4)
    fail_image(path, "PNG holds at most 4 channels, image has " + std::to_string(img.channels));
  std::vector<std::string> names = names_of(img);
  std::vector<std::uint8_t> bytes(img.pixels.size());
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    float v = img.pixels[i];
    float encoded = is_alpha_name(names[i % img.channels])
                        ? std::fmin(std::fmax(v, 0.0f), 1.0f)  // fmax maps NaN to 0
                        : srgb_encode(v);
    bytes[i] = std::uint8_t(std::lround(encoded * 255.0f));
  }
  write_atomic(path, [&](const std::string& file) {
    write_png_file(path, file, img.width, img.height, img.channels, bytes, img.metadata);
  });
}

}  // namespace tr
