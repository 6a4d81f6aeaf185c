#include "render/write_result.h"

#include <utility>

#include "io/image.h"
#include "render/error_estimate.h"

namespace tr {
namespace {

Image to_image(const RenderResult& r, const std::vector<double>& values) {
  Image img;
  img.width = int(r.width);
  img.height = int(r.height);
  img.channels = 3;
  img.pixels.assign(values.begin(), values.end());
  return img;
}

// R, G, B, then each AOV's channels, taken from its three values per pixel.
Image with_aovs(const RenderResult& r, const std::vector<double>& rgb,
                const std::vector<double>& aovs,
                const std::vector<std::vector<std::string>>& aov_channels) {
  Image img = to_image(r, rgb);
  if (aov_channels.empty()) return img;
  img.channel_names = {"R", "G", "B"};
  for (const std::vector<std::string>& names : aov_channels)
    img.channel_names.insert(img.channel_names.end(), names.begin(), names.end());
  img.channels = int(img.channel_names.size());
  const size_t pixels = size_t(r.width) * r.height;
  img.pixels.clear();
  img.pixels.reserve(pixels * img.channels);
  for (size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 3; ++c) img.pixels.push_back(float(rgb[3 * p + c]));
    for (size_t a = 0; a < aov_channels.size(); ++a)
      for (size_t c = 0; c < aov_channels[a].size(); ++c)
        img.pixels.push_back(float(aovs[3 * (p * r.aov_count + a) + c]));
  }
  return img;
}

}  // namespace

OutputPaths output_paths(const std::string& exr_path) {
  std::string stem = exr_path;
  const std::string ext = ".exr";
  if (stem.size() > ext.size() && stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0)
    stem.resize(stem.size() - ext.size());
  return {stem + ".exr", stem + "_var.exr", stem + ".png"};
}

void write_result(const RenderResult& result, const OutputPaths& paths,
                  const std::map<std::string, std::string>& extra, bool half,
                  const std::vector<std::vector<std::string>>& aov_channels) {
  std::map<std::string, std::string> meta = extra;
  meta["twinray:spp"] = std::to_string(result.spp);
  meta["twinray:seed"] = std::to_string(result.seed);
  meta["twinray:backend"] = result.backend;
  meta["twinray:device"] = result.device;
  meta["twinray:seconds"] = std::to_string(result.stats.seconds);
  meta["twinray:rejected_nonfinite"] = std::to_string(result.stats.rejected_nonfinite);
  meta["twinray:variance_estimate"] = variance_estimate_name(result.pass_size, result.spp);

  // One image at a time, each freed before the next is built: the peak memory of a render is
  // here, beside its film and result.
  {
    Image mean = with_aovs(result, result.mean, result.aov_mean, aov_channels);
    mean.metadata = meta;
    write_exr(paths.image, mean, half);
  }
  {
    Image var = with_aovs(result, result.variance, result.aov_variance, aov_channels);
    var.metadata = std::move(meta);
    var.metadata["twinray:content"] =
        "per-sample variance v of each pixel's value: v / spp estimates the value's variance "
        "(twinray:variance_estimate says from what)";
    write_exr(paths.variance, var, half);
  }
  write_png_srgb(paths.preview, to_image(result, result.mean));
}

}  // namespace tr
