#include "render/write_result.h"

#include <functional>
#include <utility>

#include "io/image.h"
#include "render/error_estimate.h"

namespace tr {
namespace {

// Value v (0: mean, 1: variance) of accumulator i, three doubles, into out.
using Develop = std::function<void(std::size_t i, int v, double out[3])>;

// R, G, B, then each AOV's channels, taken from its three values per pixel, as floats, developed
// row by row as the file is written: no image of the whole render is made (the peak memory of
// a render, BENCHMARKS.md "Memory", is the film's).
ImageRows developed_rows(const RenderResult& r, int v, const Develop& pixel, const Develop& aov,
                         const std::vector<std::vector<std::string>>& aov_channels) {
  ImageRows img;
  img.width = int(r.width);
  img.height = int(r.height);
  img.channels = 3;
  if (!aov_channels.empty()) {
    img.channel_names = {"R", "G", "B"};
    for (const std::vector<std::string>& names : aov_channels)
      img.channel_names.insert(img.channel_names.end(), names.begin(), names.end());
    img.channels = int(img.channel_names.size());
  }
  img.row = [&r, v, &pixel, &aov, &aov_channels](int y, float* out) {
    double value[3];
    for (size_t p = size_t(y) * r.width; p < size_t(y + 1) * r.width; ++p) {
      pixel(p, v, value);
      for (int c = 0; c < 3; ++c) *out++ = float(value[c]);
      for (size_t a = 0; a < aov_channels.size(); ++a) {
        aov(p * r.aov_count + a, v, value);
        for (size_t c = 0; c < aov_channels[a].size(); ++c) *out++ = float(value[c]);
      }
    }
  };
  return img;
}

void write_developed(const RenderResult& result, const Develop& pixel, const Develop& aov,
                     const OutputPaths& paths, const std::map<std::string, std::string>& extra,
                     bool half, const std::vector<std::vector<std::string>>& aov_channels) {
  std::map<std::string, std::string> meta = extra;
  meta["twinray:spp"] = std::to_string(result.spp);
  meta["twinray:seed"] = std::to_string(result.seed);
  meta["twinray:backend"] = result.backend;
  meta["twinray:device"] = result.device;
  meta["twinray:seconds"] = std::to_string(result.stats.seconds);
  meta["twinray:rejected_nonfinite"] = std::to_string(result.stats.rejected_nonfinite);
  meta["twinray:variance_estimate"] = variance_estimate_name(result.pass_size, result.spp);
  ImageRows mean = developed_rows(result, 0, pixel, aov, aov_channels);
  mean.metadata = meta;
  write_exr(paths.image, mean, half);
  ImageRows var = developed_rows(result, 1, pixel, aov, aov_channels);
  var.metadata = std::move(meta);
  var.metadata["twinray:content"] =
      "per-sample variance v of each pixel's value: v / spp estimates the value's variance "
      "(twinray:variance_estimate says from what)";
  write_exr(paths.variance, var, half);
  const std::vector<std::vector<std::string>> colour_only;
  write_png_srgb(paths.preview, developed_rows(result, 0, pixel, aov, colour_only));
}

Develop from_vectors(const std::vector<double>& mean, const std::vector<double>& variance) {
  return [&mean, &variance](std::size_t i, int v, double out[3]) {
    const std::vector<double>& values = v == 0 ? mean : variance;
    for (int c = 0; c < 3; ++c) out[c] = values[3 * i + c];
  };
}

Develop from_film(const FilmMomentArray& moments, std::uint32_t samples, std::uint32_t pass_size) {
  return [&moments, samples, pass_size](std::size_t i, int v, double out[3]) {
    double mean[3], variance[3];
    develop_estimate(moments.at(i, samples), pass_size, mean, variance);
    for (int c = 0; c < 3; ++c) out[c] = v == 0 ? mean[c] : variance[c];
  };
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
  write_developed(result, from_vectors(result.mean, result.variance),
                  from_vectors(result.aov_mean, result.aov_variance), paths, extra, half,
                  aov_channels);
}

void write_film(const FilmState& film, const RenderResult& header, const OutputPaths& paths,
                const std::map<std::string, std::string>& extra, bool half,
                const std::vector<std::vector<std::string>>& aov_channels) {
  write_developed(header, from_film(film.pixels, film.samples, film.pass_size),
                  from_film(film.aovs, film.samples, film.pass_size), paths, extra, half,
                  aov_channels);
}

}  // namespace tr
