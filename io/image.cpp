#include "io/image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "io/srgb.h"
#include "io/temp_file.h"

namespace tr {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  std::string line = path + ": " + what;
  std::replace(line.begin(), line.end(), '\n', ' ');
  throw ImageError(line);
}

bool is_alpha_name(const std::string& name) { return name == "A" || name == "a"; }

// Writes `data` (already in `type`) through the OpenImageIO plugin `format`, atomically.
void write_atomic(const std::string& path, const char* format, const OIIO::ImageSpec& spec,
                  OIIO::TypeDesc type, const void* data) try {
  TempFile tmp(path);
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(format);
  if (!out) fail(path, std::string("no ") + format + " writer: " + OIIO::geterror());
  if (!out->open(tmp.name(), spec)) fail(path, out->geterror());
  if (!out->write_image(type, data)) {
    std::string err = out->geterror();
    out->close();
    fail(path, err);
  }
  if (!out->close()) fail(path, out->geterror());
  tmp.commit();
} catch (const ImageError&) {
  throw;
} catch (const FileError& e) {
  throw ImageError(e.what());
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
    fail(path, "image has no pixels (" + std::to_string(img.width) + "x" +
                   std::to_string(img.height) + "x" + std::to_string(img.channels) + ")");
  size_t expected = size_t(img.width) * img.height * img.channels;
  if (img.pixels.size() != expected)
    fail(path, "image holds " + std::to_string(img.pixels.size()) + " values, its shape needs " +
                   std::to_string(expected));
  if (!img.channel_names.empty() && int(img.channel_names.size()) != img.channels)
    fail(path, "image has " + std::to_string(img.channels) + " channels but " +
                   std::to_string(img.channel_names.size()) + " channel names");
}

Image read_image(const std::string& path) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) fail(path, OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.depth != 1) fail(path, "volume images are not supported");
  if (spec.x != spec.full_x || spec.y != spec.full_y || spec.width != spec.full_width ||
      spec.height != spec.full_height)
    fail(path,
         "the data window differs from the display window (cropped images are not supported)");

  Image img;
  img.width = spec.width;
  img.height = spec.height;
  img.channels = spec.nchannels;
  img.channel_names = spec.channelnames;
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
    fail(path, in->geterror());
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING) img.metadata[p.name().string()] = p.get_string();

  if (spec.get_string_attribute("oiio:ColorSpace") == "sRGB") {
    for (int c = 0; c < img.channels; ++c) {
      if (c == spec.alpha_channel || is_alpha_name(img.channel_names[c])) continue;
      for (size_t i = c; i < img.pixels.size(); i += img.channels)
        img.pixels[i] = srgb_decode(img.pixels[i]);
    }
  }
  in->close();
  return img;
}

void write_exr(const std::string& path, const Image& img, bool half) {
  check_image_shape(path, img);
  OIIO::ImageSpec spec(img.width, img.height, img.channels,
                       half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = names_of(img);
  for (const auto& [key, value] : img.metadata) spec.attribute(key, value);
  spec.attribute("compression", "zip");
  write_atomic(path, "openexr", spec, OIIO::TypeDesc::FLOAT, img.pixels.data());
}

void write_png_srgb(const std::string& path, const Image& img) {
  check_image_shape(path, img);
  if (img.channels > 4)
    fail(path, "PNG holds at most 4 channels, image has " + std::to_string(img.channels));
  std::vector<std::string> names = names_of(img);
  std::vector<std::uint8_t> bytes(img.pixels.size());
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    float v = img.pixels[i];
    float encoded = is_alpha_name(names[i % img.channels])
                        ? std::fmin(std::fmax(v, 0.0f), 1.0f)  // fmax maps NaN to 0
                        : srgb_encode(v);
    bytes[i] = std::uint8_t(std::lround(encoded * 255.0f));
  }
  OIIO::ImageSpec spec(img.width, img.height, img.channels, OIIO::TypeDesc::UINT8);
  spec.channelnames = names;
  for (const auto& [key, value] : img.metadata) spec.attribute(key, value);
  spec.attribute("oiio:ColorSpace", "sRGB");
  write_atomic(path, "png", spec, OIIO::TypeDesc::UINT8, bytes.data());
}

}  // namespace tr
