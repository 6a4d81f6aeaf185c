// EXR files written through OpenEXR's C core (libOpenEXRCore, OpenEXR 3.1): the C++ library
// (Imf with Iex and Imath) holds about 1.1 MiB of resident pages in every process that maps it,
// the small C core a third of that, and a render writes its outputs at its peak of memory.
// Reading stays with the C++ library (io/exr_read_module.cpp): the 3.1 core cannot decode
// DWAA/DWAB files.
#include <Imath/half.h>
#include <OpenEXR/openexr.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "io/image.h"
#include "io/image_formats.h"

namespace tr {

namespace {

// The core reports an error's details through the context's handler (by default to stderr):
// the last one is kept for the ImageError.
void keep_message(exr_const_context_t context, exr_result_t, const char* message) {
  void* user = nullptr;
  if (exr_get_user_data(context, &user) == EXR_ERR_SUCCESS && user)
    *static_cast<std::string*>(user) = message;
}

// OpenEXR 3.1's ZIP encoder keeps the zlib bytes of a chunk they do not shorten only when they
// are longer than the packed chunk; at exactly its length a reader takes them for an uncompressed
// chunk and decodes garbage (OpenEXR issue 2306, fixed upstream in March 2026 by pull request 2307;
// Debian 12 has 3.1.5). This compress step runs the library's and, in that case, stores the packed
// chunk itself, as the fixed encoder does.
struct CompressStep {
  exr_result_t (*library)(exr_encode_pipeline_t*) = nullptr;
};

exr_result_t compress_unambiguously(exr_encode_pipeline_t* encoder) {
  const auto* step = static_cast<const CompressStep*>(encoder->encoding_user_data);
  exr_result_t result = step->library(encoder);
  if (result == EXR_ERR_SUCCESS && encoder->compressed_bytes == encoder->packed_bytes &&
      encoder->compressed_buffer != encoder->packed_buffer)
    std::memcpy(encoder->compressed_buffer, encoder->packed_buffer, encoder->packed_bytes);
  return result;
}

class ExrWriter {
 public:
  ExrWriter(const std::string& path, const std::string& file) : path_(path) {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = keep_message;
    init.user_data = &message_;
    check(exr_start_write(&context_, file.c_str(), EXR_WRITE_FILE_DIRECTLY, &init));
  }
  ~ExrWriter() {
    if (!context_) return;
    if (encoding_) exr_encoding_destroy(context_, &encoder_);
    exr_finish(&context_);
  }
  ExrWriter(const ExrWriter&) = delete;
  ExrWriter& operator=(const ExrWriter&) = delete;

  exr_context_t context() const { return context_; }
  // The encoder of the scanline chunk that starts at y: set up for the first chunk, updated for
  // the next ones.
  exr_encode_pipeline_t& encoder(int part, int y) {
    exr_chunk_info_t chunk;
    check(exr_write_scanline_chunk_info(context_, part, y, &chunk));
    check(encoding_ ? exr_encoding_update(context_, part, &chunk, &encoder_)
                    : exr_encoding_initialize(context_, part, &chunk, &encoder_));
    encoding_ = true;
    return encoder_;
  }

  void check(exr_result_t result) const {
    if (result == EXR_ERR_SUCCESS) return;
    fail_image(path_, message_.empty() ? exr_get_error_code_as_string(result) : message_);
  }

  // Closes the file; its errors (the last writes) are the write's.
  void finish() {
    if (encoding_) check(exr_encoding_destroy(context_, &encoder_));
    encoding_ = false;
    exr_result_t result = exr_finish(&context_);
    context_ = nullptr;
    check(result);
  }

 private:
  std::string path_;
  std::string message_;
  exr_context_t context_ = nullptr;
  exr_encode_pipeline_t encoder_ = EXR_ENCODE_PIPELINE_INITIALIZER;
  bool encoding_ = false;
};

}  // namespace

void write_exr_file(const std::string& path, const std::string& file, const ImageRows& img,
                    const std::vector<std::string>& names, bool half) {
  ExrWriter writer(path, file);
  exr_context_t ctx = writer.context();
  int part = 0;
  writer.check(exr_add_part(ctx, nullptr, EXR_STORAGE_SCANLINE, &part));
  // The required attributes as Imf::Header(width, height) sets them: display and data window
  // (0, 0)-(width-1, height-1), pixel aspect 1, screen window centre (0, 0) and width 1,
  // increasing-y line order.
  writer.check(
      exr_initialize_required_attr_simple(ctx, part, img.width, img.height, EXR_COMPRESSION_ZIP));
  const exr_pixel_type_t type = half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT;
  for (const std::string& name : names)
    writer.check(exr_result_t(
        exr_add_channel(ctx, part, name.c_str(), type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1)));
  for (const auto& [key, value] : img.metadata)
    writer.check(exr_attr_set_string(ctx, part, key.c_str(), value.c_str()));
  writer.check(exr_write_header(ctx));

  // One chunk (16 scanlines for ZIP) is developed, converted and encoded at a time.
  int32_t strip = 0;
  writer.check(exr_get_scanlines_per_chunk(ctx, part, &strip));
  strip = std::min(img.height, strip);
  const size_t row_values = size_t(img.width) * img.channels;
  std::vector<float> values(row_values * strip);
  std::vector<Imath::half> halves(half ? values.size() : 0);
  const int sample = half ? int(sizeof(Imath::half)) : int(sizeof(float));
  const auto* buffer = half ? reinterpret_cast<const uint8_t*>(halves.data())
                            : reinterpret_cast<const uint8_t*>(values.data());
  CompressStep zip_step;
  for (int y0 = 0; y0 < img.height; y0 += strip) {
    const int rows = std::min(strip, img.height - y0);
    for (int r = 0; r < rows; ++r) img.row(y0 + r, values.data() + r * row_values);
    std::copy(values.begin(), values.begin() + std::ptrdiff_t(halves.size()), halves.begin());
    exr_encode_pipeline_t& encoder = writer.encoder(part, y0);
    // The encoder lists the channels in the file's (alphabetical) order.
    for (int16_t c = 0; c < encoder.channel_count; ++c) {
      exr_coding_channel_info_t& channel = encoder.channels[c];
      const auto named = std::find(names.begin(), names.end(), channel.channel_name);
      channel.encode_from_ptr = buffer + (named - names.begin()) * sample;
      channel.user_pixel_stride = sample * img.channels;
      channel.user_line_stride = sample * int(row_values);
      channel.user_data_type = uint16_t(type);
      channel.user_bytes_per_element = int16_t(sample);
    }
    if (y0 == 0) {
      writer.check(exr_encoding_choose_default_routines(ctx, part, &encoder));
      if (encoder.compress_fn) {
        zip_step.library = encoder.compress_fn;
        encoder.compress_fn = compress_unambiguously;
        encoder.encoding_user_data = &zip_step;
      }
    }
    writer.check(exr_encoding_run(ctx, part, &encoder));
  }
  writer.finish();
}

}  // namespace tr
