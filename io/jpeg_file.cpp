// JPEG files through libjpeg (libjpeg-turbo's libjpeg 6.2 API, the decoder OpenImageIO uses,
// with its default settings: islow DCT, fancy upsampling). libjpeg reports errors through
// error_exit, which longjmps to a setjmp: every sequence of libjpeg calls runs inside guarded(),
// whose callers hold everything that has a destructor.
#include <csetjmp>
#include <cstdio>
#include <cstring>
// clang-format off
#include <jpeglib.h>
// clang-format on

#include "io/image_formats.h"

namespace tr {

namespace {

struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = "";
};

void on_error(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  info->err->format_message(info, errors->message);
  std::longjmp(errors->jump, 1);
}

void on_message(j_common_ptr, int) {}

// Runs `calls` (libjpeg calls only, nothing with a destructor); false if libjpeg failed.
template <class Calls>
bool guarded(JpegErrors& errors, const Calls& calls) {
  if (setjmp(errors.jump)) return false;
  calls();
  return true;
}

class JpegReader {
 public:
  explicit JpegReader(const std::string& path) : file(std::fopen(path.c_str(), "rb")) {
    info.err = jpeg_std_error(&errors.manager);
    errors.manager.error_exit = on_error;
    errors.manager.emit_message = on_message;
  }
  ~JpegReader() {
    if (created) jpeg_destroy_decompress(&info);
    if (file) std::fclose(file);
  }
  std::FILE* file;
  jpeg_decompress_struct info{};
  JpegErrors errors;
  bool created = false;
};

}  // namespace

Samples read_jpeg_samples(const std::string& path, const HeaderCheck& check) {
  JpegReader r(path);
  if (!r.file) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
  Samples s;
  std::vector<unsigned char> row;
  const bool header_read = guarded(r.errors, [&] {
    jpeg_create_decompress(&r.info);
    r.created = true;
    jpeg_stdio_src(&r.info, r.file);
    jpeg_read_header(&r.info, TRUE);
    if (r.info.jpeg_color_space != JCS_CMYK && r.info.jpeg_color_space != JCS_YCCK) {
      r.info.out_color_space = r.info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
      jpeg_calc_output_dimensions(&r.info);
    }
  });
  if (!header_read) fail_image(path, r.errors.message);
  if (r.info.jpeg_color_space == JCS_CMYK || r.info.jpeg_color_space == JCS_YCCK)
    fail_image(path, "CMYK JPEG images are not supported");
  s.width = int(r.info.output_width);
  s.height = int(r.info.output_height);
  s.channels = r.info.output_components;
  s.bytes_per_channel = 1;
  s.channel_names =
      s.channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
  check(s.width, s.height, s.channels);

  if (!guarded(r.errors, [&] { jpeg_start_decompress(&r.info); }))
    fail_image(path, r.errors.message);
  const size_t row_size = size_t(s.width) * s.channels;
  row.resize(row_size);
  s.values.resize(row_size * s.height);
  while (r.info.output_scanline < r.info.output_height) {
    const size_t y = r.info.output_scanline;
    JSAMPROW rows[1] = {row.data()};
    if (!guarded(r.errors, [&] { jpeg_read_scanlines(&r.info, rows, 1); }))
      fail_image(path, r.errors.message);
    for (size_t i = 0; i < row_size; ++i)
      s.values[y * row_size + i] = float(row[i]) * (1.0f / 255.0f);
  }
  if (!guarded(r.errors, [&] { jpeg_finish_decompress(&r.info); }))
    fail_image(path, r.errors.message);
  return s;
}

}  // namespace tr
