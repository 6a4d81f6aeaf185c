// Portable float map (PFM): a text header "PF" (RGB) or "Pf" (grey), the width and height, and
// a scale whose sign gives the byte order (negative: little-endian), then 32-bit floats with the
// bottom row first (Netpbm's PFM description).
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "io/image_formats.h"

namespace tr {

Samples read_pfm_samples(const std::string& path, const HeaderCheck& check) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
  std::string magic;
  double scale = 0.0;
  Samples s;
  in >> magic >> s.width >> s.height >> scale;
  if (!in || (magic != "PF" && magic != "Pf") || scale == 0.0 || !std::isspace(in.get()))
    fail_image(path, "not a PFM file (expected \"PF\" or \"Pf\", width, height, scale)");
  if (s.width <= 0 || s.height <= 0) fail_image(path, "image has no pixels");
  s.channels = magic == "PF" ? 3 : 1;
  s.bytes_per_channel = 4;
  s.floating = true;
  s.channel_names =
      s.channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
  check(s.width, s.height, s.channels);

  const size_t row = size_t(s.width) * s.channels;
  std::vector<std::uint32_t> words(row * s.height);
  if (!in.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * 4)))
    fail_image(path, "the file ends before its " + std::to_string(s.width) + " x " +
                         std::to_string(s.height) + " pixels");
  const bool little = scale < 0.0;
  if (little != (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__))
    for (std::uint32_t& w : words) w = __builtin_bswap32(w);
  s.values.resize(words.size());
  for (int y = 0; y < s.height; ++y)
    std::memcpy(&s.values[size_t(s.height - 1 - y) * row], &words[size_t(y) * row], row * 4);
  return s;
}

}  // namespace tr
