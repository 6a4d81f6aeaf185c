// OpenEXR files read through the Imf library (OpenEXR 3.1), built as a module that twinray
// loads on the first EXR it reads (io/exr_read.cpp): the C++ library and its Iex and Imath
// hold about 1.1 MiB of resident pages in every process that maps them, and most renders read
// no EXR. Writing goes through OpenEXR's C core (io/exr_write.cpp).
#include "io/exr_read_module.h"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <array>
#include <string_view>

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

// What is wrong with an image the library reads.
struct ExrError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws what the C++ library throws, ExrError, or what `check` throws.
Samples read_exr(const std::string& path, const HeaderCheck& check) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i data = header.dataWindow();
  Samples s;
  s.width = data.max.x - data.min.x + 1;
  s.height = data.max.y - data.min.y + 1;
  s.cropped = data != header.displayWindow();
  std::vector<ChannelOrder> channels = ordered_channels(header.channels());
  s.channels = int(channels.size());
  if (s.width <= 0 || s.height <= 0 || s.channels == 0) throw ExrError("image has no pixels");
  s.floating = true;
  for (const ChannelOrder& c : channels) {
    const Imf::Channel& channel = header.channels()[c.name];
    if (channel.xSampling != 1 || channel.ySampling != 1)
      throw ExrError("channel " + c.name + " is subsampled (not supported)");
    s.bytes_per_channel = std::max(s.bytes_per_channel, channel.type == Imf::HALF ? 2 : 4);
    s.channel_names.push_back(c.name);
  }
  // "type" (scanlineimage, tiledimage, ...), which OpenEXR's C core writes in every file, is the
  // part's layout, not metadata.
  for (auto it = header.begin(); it != header.end(); ++it)
    if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
      if (std::string_view(it.name()) != "type") s.metadata[it.name()] = text->value();
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
}

}  // namespace

}  // namespace tr

extern "C" __attribute__((visibility("default"))) bool twinray_read_exr(
    const char* path, const tr::HeaderCheck* check, tr::Samples* out, std::string* error) {
  try {
    *out = tr::read_exr(path, *check);
    return true;
  } catch (const Iex::BaseExc& e) {
    *error = e.what();
  } catch (const tr::ExrError& e) {
    *error = e.what();
  }
  return false;
}
