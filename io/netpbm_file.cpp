// Netpbm's binary formats: PGM (P5, grey) and PPM (P6, RGB) with 8-bit samples (maxval < 256)
// or 16-bit ones stored most significant byte first, and PFM ("Pf" grey, "PF" RGB: 32-bit floats
// in the byte order of the scale's sign, negative meaning little-endian, bottom row first).
// As Mitsuba 3.8's read_ppm, integer samples are divided by 255 or 65535 whatever the maxval.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

#include "io/image_formats.h"

namespace tr {

namespace {

// Skips whitespace and '#' comments up to the next header field.
void skip_separators(std::istream& in) {
  for (int c = in.peek(); c != EOF; c = in.peek()) {
    if (c == '#') {
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    } else if (std::isspace(c)) {
      in.get();
    } else {
      break;
    }
  }
}

struct Header {
  std::string magic;
  int width = 0, height = 0;
  double last = 0.0;  // maxval (PNM) or scale (PFM)
};

Header read_header(std::ifstream& in, const std::string& path) {
  Header h;
  in >> h.magic;
  skip_separators(in);
  in >> h.width;
  skip_separators(in);
  in >> h.height;
  skip_separators(in);
  in >> h.last;
  // Exactly one whitespace character separates the header from the samples.
  if (!in || !std::isspace(in.get()))
    fail_image(path, "not a Netpbm file (expected magic, width, height, maxval or scale)");
  if (h.width <= 0 || h.height <= 0) fail_image(path, "image has no pixels");
  return h;
}

// The samples of s's pixels, `per_sample` words each; the file's length is checked first.
template <class Word>
std::vector<Word> read_words(std::ifstream& in, const std::string& path, const Samples& s,
                             size_t per_sample) {
  const std::streamoff start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff left = in.tellg() - start;
  in.seekg(start);
  const size_t count = size_t(s.width) * s.height * s.channels * per_sample;
  if (double(count) * sizeof(Word) > double(left))
    fail_image(path, "the file ends before its " + std::to_string(s.width) + " x " +
                         std::to_string(s.height) + " pixels");
  std::vector<Word> words(count);
  in.read(reinterpret_cast<char*>(words.data()), std::streamsize(count * sizeof(Word)));
  return words;
}

std::ifstream open(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
  return in;
}

}  // namespace

Samples read_pnm_samples(const std::string& path, const HeaderCheck& check) {
  std::ifstream in = open(path);
  const Header h = read_header(in, path);
  if ((h.magic != "P5" && h.magic != "P6") || h.last < 1.0 || h.last > 65535.0)
    fail_image(path, "not a binary PGM/PPM file (P5 or P6 with maxval 1 to 65535)");
  Samples s;
  s.width = h.width;
  s.height = h.height;
  s.channels = h.magic == "P6" ? 3 : 1;
  s.bytes_per_channel = h.last < 256.0 ? 1 : 2;
  s.channel_names =
      s.channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
  check(s.width, s.height, s.channels);
  const std::vector<std::uint8_t> bytes =
      read_words<std::uint8_t>(in, path, s, size_t(s.bytes_per_channel));
  if (s.bytes_per_channel == 1) {
    s.values.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) s.values[i] = float(bytes[i]) * (1.0f / 255.0f);
  } else {
    s.values.resize(bytes.size() / 2);
    for (size_t i = 0; i < s.values.size(); ++i)
      s.values[i] = float(bytes[2 * i] << 8 | bytes[2 * i + 1]) * (1.0f / 65535.0f);
  }
  return s;
}

Samples read_pfm_samples(const std::string& path, const HeaderCheck& check) {
  std::ifstream in = open(path);
  const Header h = read_header(in, path);
  if ((h.magic != "PF" && h.magic != "Pf") || h.last == 0.0)
    fail_image(path, "not a PFM file (PF or Pf with a non-zero scale)");
  Samples s;
  s.width = h.width;
  s.height = h.height;
  s.channels = h.magic == "PF" ? 3 : 1;
  s.bytes_per_channel = 4;
  s.floating = true;
  s.channel_names =
      s.channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
  check(s.width, s.height, s.channels);

  std::vector<std::uint32_t> words = read_words<std::uint32_t>(in, path, s, 1);
  const bool little = h.last < 0.0;
  if (little != (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__))
    for (std::uint32_t& w : words) w = __builtin_bswap32(w);
  const size_t row = size_t(s.width) * s.channels;
  s.values.resize(words.size());
  for (int y = 0; y < s.height; ++y)
    std::memcpy(&s.values[size_t(s.height - 1 - y) * row], &words[size_t(y) * row], row * 4);
  return s;
}

}  // namespace tr
