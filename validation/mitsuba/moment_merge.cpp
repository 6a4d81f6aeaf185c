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

Image output_image(int width, int height, const std::vector<std::string>& aov_names) {
  Image img;
  img.width = width;
  img.height = height;
  img.channel_names = {"R", "G", "B"};
  img.channel_names.insert(img.channel_names.end(), aov_names.begin(), aov_names.end());
  img.channels = int(img.channel_names.size());
  img.pixels.assign(size_t(width) * height * img.channels, 0.0f);
  return img;
}

// The per-sample variance (1/P) sum_k m2_k - mean^2 of a merged channel; a value that
// cancelled below zero is set to 0 and counted.
double merged_variance(double mean, double sum_m2, double count, MergedPasses& out) {
  double var = sum_m2 / count - mean * mean;
  if (var < 0.0) {
    ++out.clamped_variances;
    out.most_negative_variance = std::min(out.most_negative_variance, var);
    var = 0.0;
  }
  return var;
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
    if (m.name.find('.') != std::string::npos) continue;
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
  MomentChannels m = found.front();
  const std::string prefix = m.name + ".";
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string& n = names[i];
    if (n.rfind(prefix, 0) != 0) continue;
    const std::string aov = n.substr(prefix.size());
    if (aov == "X" || aov == "Y" || aov == "Z") continue;
    const int m2 = channel_index(names, "m2_" + n);
    if (m2 < 0) throw ImageError(what + ": AOV channel " + n + " without its m2_" + n);
    m.aov_names.push_back(aov);
    m.aov_mean.push_back(int(i));
    m.aov_m2.push_back(m2);
  }
  return m;
}

MergedPasses merge_moment_passes(const std::vector<Image>& passes,
                                 const std::vector<std::string>& names) {
  if (passes.empty()) throw ImageError("merge_moment_passes: no passes");
  const int width = passes.front().width, height = passes.front().height;
  const size_t pixels = size_t(width) * height;
  const std::vector<std::string> aov_names =
      find_moment_channels(passes.front(), names.front()).aov_names;
  // Per pixel: X, Y, Z, then the AOVs.
  const size_t values = 3 + aov_names.size();
  std::vector<double> sum_mean(values * pixels, 0.0), sum_m2(values * pixels, 0.0);
  for (size_t k = 0; k < passes.size(); ++k) {
    const Image& img = passes[k];
    const std::string& what = names[k];
    check_image_shape(what, img);
    if (img.width != width || img.height != height)
      throw ImageError(what + ": " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                       ", the first pass is " + std::to_string(width) + "x" +
                       std::to_string(height));
    const MomentChannels m = find_moment_channels(img, what);
    if (m.aov_names != aov_names)
      throw ImageError(what + ": its AOV channels differ from those of " + names.front());
    std::vector<int> mean_channel(m.mean, m.mean + 3), m2_channel(m.m2, m.m2 + 3);
    mean_channel.insert(mean_channel.end(), m.aov_mean.begin(), m.aov_mean.end());
    m2_channel.insert(m2_channel.end(), m.aov_m2.begin(), m.aov_m2.end());
    for (size_t p = 0; p < pixels; ++p)
      for (size_t c = 0; c < values; ++c) {
        const double mean = img.pixels[p * img.channels + mean_channel[c]];
        const double m2 = img.pixels[p * img.channels + m2_channel[c]];
        if (!std::isfinite(mean) || !std::isfinite(m2))
          throw ImageError(what + ": a moment value is not finite at pixel (" +
                           std::to_string(p % width) + ", " + std::to_string(p / width) + ")");
        sum_mean[values * p + c] += mean;
        sum_m2[values * p + c] += m2;
      }
  }

  MergedPasses out{output_image(width, height, aov_names), output_image(width, height, aov_names)};
  const double count = double(passes.size());
  for (size_t p = 0; p < pixels; ++p) {
    const double* mean_sums = &sum_mean[values * p];
    const double* m2_sums = &sum_m2[values * p];
    float* mean_out = &out.mean.pixels[values * p];
    float* var_out = &out.variance.pixels[values * p];
    double mean_xyz[3], var_xyz[3];
    for (int c = 0; c < 3; ++c) {
      mean_xyz[c] = mean_sums[c] / count;
      var_xyz[c] = merged_variance(mean_xyz[c], m2_sums[c], count, out);
    }
    for (int c = 0; c < 3; ++c) {
      double mean = 0.0, var = 0.0;
      for (int k = 0; k < 3; ++k) {
        mean += kXyzToSrgb[c][k] * mean_xyz[k];
        var += kXyzToSrgb[c][k] * var_xyz[k];
      }
      mean_out[c] = float(mean);
      var_out[c] = float(var);
    }
    for (size_t c = 3; c < values; ++c) {
      const double mean = mean_sums[c] / count;
      mean_out[c] = float(mean);
      var_out[c] = float(merged_variance(mean, m2_sums[c], count, out));
    }
  }
  return out;
}

}  // namespace tr
