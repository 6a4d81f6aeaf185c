// OpenEXR files through the Imf library (OpenEXR 3.1).
#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "io/image.h"
#include "io/image_formats.h"

namespace tr {

namespace {

// OpenImageIO 2.4's order of well-known channel names within a layer (its EXR reader).
int special_index(std::string_view suffix) {
  static const std::array<std::string_view, 20> special = {
      "R",     "Red", "G",  "Green", "B",  "Blue", "Y",  "real", "imag",  "A",
      "Alpha", "AR",  "RA", "AG",    "GA", "AB",   "BA", "Z",    "Depth", "Zback"};
  for (size_t i = 0; i < special.size(); ++i)
    if (std::equal(suffix.begin(), suffix.end(), special[i].begin(), special[i].end(),
                   [](char a, char b) { return std::tolower(a) == std::tolower(b); }))
      return int(i);
  return int(special.size());
}

struct ChannelOrder {
  std::string name;
  std::string layer;  // up to and including the last dot
  int special;
  int in_file;
};

std::vector<ChannelOrder> ordered_channels(const Imf::ChannelList& list) {
  std::vector<ChannelOrder> order;
  for (auto it = list.begin(); it != list.end(); ++it) {
    std::string name = it.name();
    size_t dot = name.rfind('.');
    std::string layer = dot == std::string::npos ? "" : name.substr(0, dot + 1);
    int special = special_index(std::string_view(name).substr(layer.size()));
    order.push_back({name, layer, special, int(order.size())});
  }
  std::stable_sort(order.begin(), order.end(), [](const ChannelOrder& a, const ChannelOrder& b) {
    if (a.layer != b.layer) return a.layer < b.layer;
    if (a.special != b.special) return a.special < b.special;
    return a.in_file < b.in_file;
  });
  return order;
}

}  // namespace

Samples read_exr_samples(const std::string& path, const HeaderCheck& check) try {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i data = header.dataWindow();
  Samples s;
  s.width = data.max.x - data.min.x + 1;
  s.height = data.max.y - data.min.y + 1;
  s.cropped = data != header.displayWindow();
  std::vector<ChannelOrder> channels = ordered_channels(header.channels());
  s.channels = int(channels.size());
  if (s.width <= 0 || s.height <= 0 || s.channels == 0) fail_image(path, "image has no pixels");
  s.floating = true;
  for (const ChannelOrder& c : channels) {
    const Imf::Channel& channel = header.channels()[c.name];
    if (channel.xSampling != 1 || channel.ySampling != 1)
      fail_image(path, "channel " + c.name + " is subsampled (not supported)");
    s.bytes_per_channel = std::max(s.bytes_per_channel, channel.type == Imf::HALF ? 2 : 4);
    s.channel_names.push_back(c.name);
  }
  for (auto it = header.begin(); it != header.end(); ++it)
    if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
      s.metadata[it.name()] = text->value();
  check(s.width, s.height, s.channels);

  s.values.resize(size_t(s.width) * s.height * s.channels);
  const size_t x_stride = sizeof(float) * s.channels;
  const size_t y_stride = x_stride * s.width;
  // The slices' base addresses point at pixel (0, 0) of the data window's coordinates.
  char* origin = reinterpret_cast<char*>(s.values.data()) - data.min.x * std::ptrdiff_t(x_stride) -
                 data.min.y * std::ptrdiff_t(y_stride);
  Imf::FrameBuffer frame;
  for (int c = 0; c < s.channels; ++c)
    frame.insert(s.channel_names[c],
                 Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), x_stride, y_stride));
  file.setFrameBuffer(frame);
  file.readPixels(data.min.y, data.max.y);
  return s;
} catch (const Iex::BaseExc& e) {
  fail_image(path, e.what());
}

void write_exr_file(const std::string& path, const std::string& file, const ImageRows& img,
                    const std::vector<std::string>& names, bool half) try {
  Imf::Header header(img.width, img.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const std::string& name : names)
    header.channels().insert(name, Imf::Channel(half ? Imf::HALF : Imf::FLOAT));
  for (const auto& [key, value] : img.metadata) header.insert(key, Imf::StringAttribute(value));
  Imf::OutputFile out(file.c_str(), header);
  // A strip of the scanlines that ZIP compresses together (16) is developed, converted and
  // handed to OpenEXR at a time. OpenEXR converts pixel types when reading only: half channels
  // are written from halves.
  const int strip = std::min(img.height, 16);
  const size_t row_values = size_t(img.width) * img.channels;
  std::vector<float> values(row_values * strip);
  std::vector<Imath::half> halves(half ? values.size() : 0);
  const size_t sample = half ? sizeof(Imath::half) : sizeof(float);
  const size_t x_stride = sample * img.channels;
  const size_t y_stride = x_stride * img.width;
  for (int y0 = 0; y0 < img.height; y0 += strip) {
    const int rows = std::min(strip, img.height - y0);
    for (int r = 0; r < rows; ++r) img.row(y0 + r, values.data() + r * row_values);
    std::copy(values.begin(), values.begin() + std::ptrdiff_t(halves.size()), halves.begin());
    // Slices address pixel (x, y) at base + x * x_stride + y * y_stride: base is the strip's
    // buffer moved back by y0 rows.
    const char* buffer = half ? reinterpret_cast<const char*>(halves.data())
                              : reinterpret_cast<const char*>(values.data());
    char* base = const_cast<char*>(buffer) - std::ptrdiff_t(y0) * std::ptrdiff_t(y_stride);
    Imf::FrameBuffer frame;
    for (int c = 0; c < img.channels; ++c)
      frame.insert(names[c], Imf::Slice(half ? Imf::HALF : Imf::FLOAT, base + c * sample, x_stride,
                                        y_stride));
    out.setFrameBuffer(frame);
    out.writePixels(rows);
  }
} catch (const Iex::BaseExc& e) {
  fail_image(path, e.what());
}

}  // namespace tr
