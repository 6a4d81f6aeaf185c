#include "validation/image/ssim.h"

#include <cmath>
#include <stdexcept>

#include "io/srgb.h"

namespace tr {

namespace {

std::vector<double> display_luma(const RgbImage& img) {
  std::vector<double> luma(img.pixel_count());
  for (size_t i = 0; i < luma.size(); ++i) {
    const double* p = &img.rgb[3 * i];
    luma[i] = 0.2126 * srgb_encode(float(p[0])) + 0.7152 * srgb_encode(float(p[1])) +
              0.0722 * srgb_encode(float(p[2]));
  }
  return luma;
}

// Separable Gaussian-weighted mean over every window that fits inside the image ('valid').
std::vector<double> window_mean(const std::vector<double>& v, int width, int height,
                                const std::vector<double>& w) {
  const int n = int(w.size()), out_w = width - n + 1, out_h = height - n + 1;
  std::vector<double> rows(size_t(out_w) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < out_w; ++x) {
      double s = 0.0;
      for (int k = 0; k < n; ++k) s += w[k] * v[size_t(y) * width + x + k];
      rows[size_t(y) * out_w + x] = s;
    }
  std::vector<double> out(size_t(out_w) * out_h);
  for (int y = 0; y < out_h; ++y)
    for (int x = 0; x < out_w; ++x) {
      double s = 0.0;
      for (int k = 0; k < n; ++k) s += w[k] * rows[size_t(y + k) * out_w + x];
      out[size_t(y) * out_w + x] = s;
    }
  return out;
}

}  // namespace

SsimResult ssim(const RgbImage& test, const RgbImage& reference) {
  check_same_size(reference, "reference", test, "test image");
  if (test.width < kSsimWindow || test.height < kSsimWindow)
    throw std::invalid_argument("SSIM needs images of at least 11x11 pixels");
  const double sigma = 1.5, L = 1.0, C1 = (0.01 * L) * (0.01 * L), C2 = (0.03 * L) * (0.03 * L);
  // The 2D window is the outer product of this 1D Gaussian with itself.
  std::vector<double> w(kSsimWindow);
  double sum = 0.0;
  for (int k = 0; k < kSsimWindow; ++k) {
    double d = k - kSsimWindow / 2;
    sum += w[k] = std::exp(-d * d / (2.0 * sigma * sigma));
  }
  for (double& v : w) v /= sum;

  const int W = test.width, H = test.height;
  std::vector<double> x = display_luma(test), y = display_luma(reference);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  std::vector<double> mx = window_mean(x, W, H, w), my = window_mean(y, W, H, w);
  std::vector<double> mxx = window_mean(xx, W, H, w), myy = window_mean(yy, W, H, w);
  std::vector<double> mxy = window_mean(xy, W, H, w);

  SsimResult r;
  r.map_width = W - kSsimWindow + 1;
  r.map_height = H - kSsimWindow + 1;
  r.map.resize(mx.size());
  double total = 0.0;
  for (size_t i = 0; i < mx.size(); ++i) {
    // Weighted local statistics (eqs. 14-16) and SSIM (eq. 13).
    double sxx = mxx[i] - mx[i] * mx[i], syy = myy[i] - my[i] * my[i];
    double sxy = mxy[i] - mx[i] * my[i];
    double s = (2.0 * mx[i] * my[i] + C1) * (2.0 * sxy + C2) /
               ((mx[i] * mx[i] + my[i] * my[i] + C1) * (sxx + syy + C2));
    r.map[i] = float(s);
    total += s;
  }
  r.mean = total / double(mx.size());
  return r;
}

}  // namespace tr
