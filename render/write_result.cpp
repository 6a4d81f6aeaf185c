#include "render/write_result.h"

#include "io/image.h"

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

}  // namespace

OutputPaths output_paths(const std::string& exr_path) {
  std::string stem = exr_path;
  const std::string ext = ".exr";
  if (stem.size() > ext.size() && stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0)
    stem.resize(stem.size() - ext.size());
  return {stem + ".exr", stem + "_var.exr", stem + ".png"};
}

void write_result(const RenderResult& result, const OutputPaths& paths,
                  const std::map<std::string, std::string>& extra, bool half) {
  std::map<std::string, std::string> meta = extra;
  meta["twinray:spp"] = std::to_string(result.spp);
  meta["twinray:seed"] = std::to_string(result.seed);
  meta["twinray:backend"] = result.backend;
  meta["twinray:device"] = result.device;
  meta["twinray:seconds"] = std::to_string(result.stats.seconds);
  meta["twinray:rejected_nonfinite"] = std::to_string(result.stats.rejected_nonfinite);

  Image mean = to_image(result, result.mean);
  mean.metadata = meta;
  Image var = to_image(result, result.variance);
  var.metadata = meta;
  var.metadata["twinray:content"] = "per-sample variance of each pixel's samples";
  write_exr(paths.image, mean, half);
  write_exr(paths.variance, var, half);
  write_png_srgb(paths.preview, mean);
}

}  // namespace tr
