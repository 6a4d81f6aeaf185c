// PNG files through libpng 1.6. libpng reports errors by longjmp to a setjmp: every sequence of
// libpng calls runs inside guarded(), whose callers hold everything that has a destructor.
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

#include "io/image_formats.h"

namespace tr {

namespace {

struct PngErrors {
  char message[256] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  std::snprintf(errors->message, sizeof(errors->message), "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

FilePtr open_file(const std::string& path, const std::string& file, const char* mode) {
  FilePtr f(std::fopen(file.c_str(), mode));
  if (!f) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
  return f;
}

// Runs `calls` (libpng calls only, nothing with a destructor); false if libpng failed.
template <class Calls>
bool guarded(png_structp png, const Calls& calls) {
  if (setjmp(png_jmpbuf(png))) return false;
  calls();
  return true;
}

// libpng allocates what a chunk's length field claims before reading the chunk (a tEXt
// chunk claiming 2 GB in a 370-byte file, found by scripts/fuzz): every chunk up to IEND must
// fit in the file. The signature is left to libpng.
void check_chunk_lengths(const std::string& path, std::FILE* file) {
  std::fseek(file, 0, SEEK_END);
  const long size = std::ftell(file);
  long at = 8;
  unsigned char header[8];
  while (at + 12 <= size && std::fseek(file, at, SEEK_SET) == 0 &&
         std::fread(header, 1, 8, file) == 8) {
    const unsigned long length =
        (unsigned long)header[0] << 24 | header[1] << 16 | header[2] << 8 | header[3];
    if (length > static_cast<unsigned long>(size - at - 12))
      fail_image(path, "a PNG chunk claims " + std::to_string(length) + " bytes, the file has " +
                           std::to_string(size - at - 12) + " left");
    if (std::memcmp(header + 4, "IEND", 4) == 0) break;
    at += 12 + long(length);
  }
  std::rewind(file);
}

class PngReader {
 public:
  PngReader() {
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
    if (png) info = png_create_info_struct(png);
  }
  ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngErrors errors;
};

class PngWriter {
 public:
  PngWriter() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
    if (png) info = png_create_info_struct(png);
  }
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngErrors errors;
};

}  // namespace

Samples read_png_samples(const std::string& path, const HeaderCheck& check) {
  FilePtr file = open_file(path, path, "rb");
  PngReader r;
  if (!r.info) fail_image(path, "out of memory");
  Samples s;
  std::vector<unsigned char> data;
  std::vector<png_bytep> rows;
  check_chunk_lengths(path, file.get());
  const bool header_read = guarded(r.png, [&] {
    png_init_io(r.png, file.get());
    png_read_info(r.png, r.info);
    const int color = png_get_color_type(r.png, r.info);
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r.png);
    if (color == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(r.png, r.info) < 8)
      png_set_expand_gray_1_2_4_to_8(r.png);
    if (png_get_valid(r.png, r.info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(r.png);
    if (png_get_bit_depth(r.png, r.info) == 16) png_set_swap(r.png);  // native little-endian
    png_set_interlace_handling(r.png);
    png_read_update_info(r.png, r.info);
  });
  if (!header_read) fail_image(path, r.errors.message);
  s.width = int(png_get_image_width(r.png, r.info));
  s.height = int(png_get_image_height(r.png, r.info));
  s.channels = png_get_channels(r.png, r.info);
  const int depth = png_get_bit_depth(r.png, r.info);
  s.bytes_per_channel = depth == 16 ? 2 : 1;
  check(s.width, s.height, s.channels);

  const size_t row_bytes = png_get_rowbytes(r.png, r.info);
  data.resize(row_bytes * s.height);
  rows.resize(s.height);
  for (int y = 0; y < s.height; ++y) rows[y] = data.data() + row_bytes * y;
  if (!guarded(r.png, [&] {
        png_read_image(r.png, rows.data());
        png_read_end(r.png, r.info);
      }))
    fail_image(path, r.errors.message);

  png_textp text = nullptr;
  int text_count = png_get_text(r.png, r.info, &text, nullptr);
  for (int i = 0; i < text_count; ++i)
    s.metadata[text[i].key] = std::string(text[i].text, text[i].text_length);
  static const char* const names[][4] = {{"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  s.channel_names.assign(names[s.channels - 1], names[s.channels - 1] + s.channels);

  // OpenImageIO's integer-to-float conversion: value * (1 / max).
  const size_t count = size_t(s.width) * s.height * s.channels;
  s.values.resize(count);
  if (depth == 16) {
    const auto* words = reinterpret_cast<const std::uint16_t*>(data.data());
    for (size_t i = 0; i < count; ++i) s.values[i] = float(words[i]) * (1.0f / 65535.0f);
  } else {
    for (size_t i = 0; i < count; ++i) s.values[i] = float(data[i]) * (1.0f / 255.0f);
  }
  return s;
}

void write_png_file(const std::string& path, const std::string& file_name, int width, int height,
                    int channels, const std::function<void(int y, unsigned char* out)>& row,
                    const std::map<std::string, std::string>& metadata) {
  static const int color_types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                    PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
  FilePtr file = open_file(path, file_name, "wb");
  PngWriter w;
  if (!w.info) fail_image(path, "out of memory");
  std::vector<png_text> text(metadata.size());
  std::vector<unsigned char> bytes(size_t(width) * channels);
  size_t i = 0;
  for (const auto& [key, value] : metadata) {
    text[i].compression = PNG_TEXT_COMPRESSION_NONE;
    text[i].key = const_cast<char*>(key.c_str());
    text[i].text = const_cast<char*>(value.c_str());
    text[i].text_length = value.size();
    ++i;
  }
  bool written = guarded(w.png, [&] {
    png_init_io(w.png, file.get());
    png_set_IHDR(w.png, w.info, width, height, 8, color_types[channels - 1], PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(w.png, w.info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (!text.empty()) png_set_text(w.png, w.info, text.data(), int(text.size()));
    png_write_info(w.png, w.info);
  });
  // Each row is made outside guarded(), whose longjmp would skip its destructors.
  for (int y = 0; y < height && written; ++y) {
    row(y, bytes.data());
    written = guarded(w.png, [&] { png_write_row(w.png, bytes.data()); });
  }
  written = written && guarded(w.png, [&] { png_write_end(w.png, w.info); });
  if (!written) fail_image(path, w.errors.message);
  if (std::fflush(file.get()) != 0)
    fail_image(path, std::string("write failed: ") + std::strerror(errno));
}

}  // namespace tr
