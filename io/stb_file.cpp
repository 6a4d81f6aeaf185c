// Radiance RGBE, BMP and TGA files through stb_image (Debian's libstb-dev), with its other
// decoders left out: those formats have their own readers. The dimension limit is lifted to let
// HeaderCheck give the reason for refusing a large image.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_HDR
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_MAX_DIMENSIONS (1 << 30)
#include <stb/stb_image.h>

#include <cstdio>
#include <cstring>
#include <memory>

#include "io/image_formats.h"

namespace tr {

Samples read_stb_samples(const std::string& path, const HeaderCheck& check) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
  Samples s;
  if (!stbi_info_from_file(file.get(), &s.width, &s.height, &s.channels))
    fail_image(path, std::string("cannot read the header: ") + stbi_failure_reason());
  s.floating = stbi_is_hdr_from_file(file.get()) != 0;
  s.bytes_per_channel = s.floating ? 4 : 1;
  static const char* const names[][4] = {{"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  if (s.channels < 1 || s.channels > 4)
    fail_image(path, "unsupported channel count " + std::to_string(s.channels));
  s.channel_names.assign(names[s.channels - 1], names[s.channels - 1] + s.channels);
  check(s.width, s.height, s.channels);

  // stb_image reads past the end of a file as zeros: a file must at least hold its texels at the
  // densest encoding of these formats (TGA run-length packets: 2 bytes for 128 texels).
  std::fseek(file.get(), 0, SEEK_END);
  const long size = std::ftell(file.get());
  std::rewind(file.get());
  if (double(s.width) * s.height > 64.0 * double(size))
    fail_image(path, "the file's " + std::to_string(size) + " bytes cannot hold " +
                         std::to_string(s.width) + " x " + std::to_string(s.height) + " texels");

  // Decoded through callbacks, which see whether the decoder asked for bytes past the end of
  // the file (stb_image itself would go on with zeros).
  struct Reader {
    std::FILE* file;
    bool past_end;
  } reader{file.get(), false};
  const stbi_io_callbacks callbacks = {
      [](void* user, char* data, int size) {
        auto* r = static_cast<Reader*>(user);
        const size_t n = std::fread(data, 1, size_t(size), r->file);
        if (n == 0) r->past_end = true;
        return int(n);
      },
      [](void* user, int n) { std::fseek(static_cast<Reader*>(user)->file, n, SEEK_CUR); },
      [](void* user) { return std::feof(static_cast<Reader*>(user)->file); }};

  int width = 0, height = 0, channels = 0;
  const size_t count = size_t(s.width) * s.height * s.channels;
  s.values.resize(count);
  auto decoded = [&](void* pixels) {
    if (!pixels) fail_image(path, std::string("cannot decode: ") + stbi_failure_reason());
    const char* wrong = reader.past_end ? "the file ends inside its texels"
                        : width != s.width || height != s.height || channels != s.channels
                            ? "the image's size differs from its header's"
                            : nullptr;
    if (wrong) {
      stbi_image_free(pixels);
      fail_image(path, wrong);
    }
    return pixels;
  };
  if (s.floating) {
    float* pixels = static_cast<float*>(
        decoded(stbi_loadf_from_callbacks(&callbacks, &reader, &width, &height, &channels, 0)));
    std::copy(pixels, pixels + count, s.values.begin());
    stbi_image_free(pixels);
  } else {
    auto* pixels = static_cast<stbi_uc*>(
        decoded(stbi_load_from_callbacks(&callbacks, &reader, &width, &height, &channels, 0)));
    for (size_t i = 0; i < count; ++i) s.values[i] = float(pixels[i]) * (1.0f / 255.0f);
    stbi_image_free(pixels);
  }
  return s;
}

}  // namespace tr
