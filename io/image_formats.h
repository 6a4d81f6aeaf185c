// The image file formats twinray reads, each through its reference library: OpenEXR (Imf),
// PNG (libpng), JPEG (libjpeg), Radiance RGBE, BMP and TGA (stb_image), and Netpbm's PGM, PPM
// and PFM (a reader of its own). They deliver the file's samples unconverted: integer samples
// scaled to [0, 1], float samples as stored, no colour transfer function applied.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace tr {

struct ImageRows;  // io/image.h

struct Samples {
  int width = 0, height = 0, channels = 0;
  int bytes_per_channel = 0;  // of the widest channel in the file
  bool floating = false;      // half or float samples (EXR, RGBE, PFM)
  // The file's image is a crop of a larger display window (EXR data window != display window).
  bool cropped = false;
  // Row-major, top row first, channels interleaved.
  std::vector<float> values;
  // EXR: the channel names in OpenImageIO's order (see read_exr_samples); other formats: Y, YA,
  // RGB or RGBA.
  std::vector<std::string> channel_names;
  // String attributes: EXR string header attributes, PNG text chunks.
  std::map<std::string, std::string> metadata;
};

// Throws ImageError("path: what"), the message on one line.
[[noreturn]] void fail_image(const std::string& path, const std::string& what);

// Called with the header's width, height and channel count before anything is allocated for
// the pixels; throws to refuse the image.
using HeaderCheck = std::function<void(int width, int height, int channels)>;

// Picks the reader by the file's first bytes. Throws ImageError ("path: what went wrong").
Samples read_samples(const std::string& path, const HeaderCheck& check);

// Any channel names and types; tiled and multi-resolution files are read at full resolution.
// Channels are ordered as OpenImageIO 2.4 orders them: grouped by layer (the name up to its last
// dot, the unnamed layer first, then layers in name order), within a layer R, G, B, A (and their
// long forms) and other well-known names first, then the rest in the file's (alphabetical)
// order.
Samples read_exr_samples(const std::string& path, const HeaderCheck& check);
Samples read_png_samples(const std::string& path, const HeaderCheck& check);
Samples read_jpeg_samples(const std::string& path, const HeaderCheck& check);
// Radiance RGBE (.hdr), BMP and TGA.
Samples read_stb_samples(const std::string& path, const HeaderCheck& check);
// Binary PGM/PPM (P5, P6) and portable float maps (PF, Pf).
Samples read_pnm_samples(const std::string& path, const HeaderCheck& check);
Samples read_pfm_samples(const std::string& path, const HeaderCheck& check);

// img.row's values in the order of `names`; 16-bit floats when `half`; ZIP compression;
// metadata as string attributes. Writes to `file` (the caller makes the write atomic).
void write_exr_file(const std::string& path, const std::string& file, const ImageRows& img,
                    const std::vector<std::string>& names, bool half);

// 8-bit samples, 1 to 4 channels (Y, YA, RGB, RGBA), tagged sRGB; metadata as text chunks.
// row(y, out) fills `out` with row y's width * channels bytes.
void write_png_file(const std::string& path, const std::string& file, int width, int height,
                    int channels, const std::function<void(int y, unsigned char* out)>& row,
                    const std::map<std::string, std::string>& metadata);

}  // namespace tr
