#include "validation/mitsuba/moment_merge.h"

#include <algorithm>
#include <cmath>

namespace tr {
namespace {

// Mitsuba 3.8.0 src/core/bitmap.cpp, Bitmap::convert: the blend weights of R, G, B from X, Y, Z.
const double kXyzToSrgb[3][3] = {{3.240479, -1.537150, -0.498535},
                                 {-0.969256, 1.875991, 0.041556},
                                 {0.055648, -0.204043, 1.057311}};

int channel_index(const std::vector<std::string>& names, const std::string& name) {
  auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : int(it - names.begin());
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

Image rgb_image(int width, int height) {
  Image img;
  img.width = width;
  img.height = height;
  img.channels = 3;
  img.channel_names = {"R", "G", "B"};
  img.pixels.assign(size_t(width) * height * 3, 0.0f);
  return img;
}

}  // namespace

MomentChannels find_moment_channels(const Image& img, const std::string& what) {
  const std::vector<std::string> names =
      img.channel_names.empty() ? default_channel_names(img.channels) : img.channel_names;
  std::vector<MomentChannels> found;
  for (const std::string& n : names) {
    if (!ends_with(n, ".X") || n.rfind("m2_", 0) == 0) continue;
    MomentChannels m;
    m.name = n.substr(0, n.size() - 2);
    bool complete = true;
    for (int c = 0; c < 3; ++c) {
      const std::string suffix = std::string(".") + "XYZ"[c];
      m.mean[c] = channel_index(names, m.name + suffix);
      m.m2[c] = channel_index(names, "m2_" + m.name + suffix);
      complete = complete && m.mean[c] >= 0 && m.m2[c] >= 0;
    }
    if (complete) found.push_back(m);
  }
  if (found.size() != 1)
    throw ImageError(what + ": expected the channels NAME.X/Y/Z and m2_NAME.X/Y/Z of exactly one " +
                     "integrator nested in Mitsuba's `moment` integrator, found " +
                     std::to_string(found.size()));
  return found.front();
}

MergedPasses merge_moment_passes(const std::vector<Image>& passes,
                                 const std::vector<std::string>& names) {
  if (passes.empty()) throw ImageError("merge_moment_passes: no passes");
  const int width = passes.front().width, height = passes.front().height;
  const size_t pixels = size_t(width) * height;
  std::vector<double> sum_mean(3 * pixels, 0.0), sum_m2(3 * pixels, 0.0);
  for (size_t k = 0; k < passes.size(); ++k) {
    const Image& img = passes[k];
    const std::string& what = names[k];
    check_image_shape(what, img);
    if (img.width != width || img.height != height)
      throw ImageError(what + ": " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                       ", the first pass is " + std::to_string(width) + "x" +
                       std::to_string(height));
    const MomentChannels m = find_moment_channels(img, what);
    for (size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) {
        const double mean = img.pixels[p * img.channels + m.mean[c]];
        const double m2 = img.pixels[p * img.channels + m.m2[c]];
        if (!std::isfinite(mean) || !std::isfinite(m2))
          throw ImageError(what + ": a moment value is not finite at pixel (" +
                           std::to_string(p % width) + ", " + std::to_string(p / width) + ")");
        sum_mean[3 * p + c] += mean;
        sum_m2[3 * p + c] += m2;
      }
  }

  MergedPasses out{rgb_image(width, height), rgb_image(width, height)};
  const double count = double(passes.size());
  for (size_t p = 0; p < pixels; ++p) {
    double mean_xyz[3], var_xyz[3];
    for (int c = 0; c < 3; ++c) {
      mean_xyz[c] = sum_mean[3 * p + c] / count;
      var_xyz[c] = sum_m2[3 * p + c] / count - mean_xyz[c] * mean_xyz[c];
      if (var_xyz[c] < 0.0) {
        ++out.clamped_variances;
        out.most_negative_variance = std::min(out.most_negative_variance, var_xyz[c]);
        var_xyz[c] = 0.0;
      }
    }
    for (int c = 0; c < 3; ++c) {
      double mean = 0.0, var = 0.0;
      for (int k = 0; k < 3; ++k) {
        mean += kXyzToSrgb[c][k] * mean_xyz[k];
        var += kXyzToSrgb[c][k] * var_xyz[k];
      }
      out.mean.pixels[3 * p + c] = float(mean);
      out.variance.pixels[3 * p + c] = float(var);
    }
  }
  return out;
}

}  // namespace tr
