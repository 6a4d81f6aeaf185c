#include "validation/image/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace tr {

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

constexpr double kPi = 3.14159265358979323846;

// Exponents and redistribution constants of the paper: q_c = 0.7 (colour), p_c = 0.4,
// p_t = 0.95 (error redistribution), q_f = 0.5 (features).
constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95, kQf = 0.5;

// Linear sRGB → XYZ (D65), the exact rational form of the IEC 61966-2-1 matrix used by the
// FLIP authors.
const Mat3 kRgbToXyz = {
    {{10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
     {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
     {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}}};

Vec3 mul(const Mat3& m, const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return r;
}

Mat3 inverse(const Mat3& m) {
  Mat3 r;
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // Cofactor of (j, i) divided by the determinant.
      int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      r[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
    }
  return r;
}

const Mat3 kXyzToRgb = inverse(kRgbToXyz);
const Vec3 kWhite = mul(kRgbToXyz, {1.0, 1.0, 1.0});  // D65 white of the RGB cube

// YyCxCz, the linearised CIELAB opponent space of Zhang & Wandell ("A spatial extension of
// CIELAB for digital color image reproduction", 1997), FLIP's opponent space for spatial filtering.
Vec3 xyz_to_ycxcz(const Vec3& xyz) {
  double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxcz_to_xyz(const Vec3& o) {
  double y = (o[0] + 16.0) / 116.0;
  return {(y + o[1] / 500.0) * kWhite[0], y * kWhite[1], (y - o[2] / 200.0) * kWhite[2]};
}

// CIE 1976 L*a*b* relative to the D65 white above (CIE 15:2004 §8.2.1).
Vec3 xyz_to_lab(const Vec3& xyz) {
  const double delta = 6.0 / 29.0;
  auto f = [&](double t) {
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  double fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// Hunt adjustment (FLIP, after Hunt's effect): chroma scaled by 0.01 L*, so that colours lose
// chromatic difference as they darken.
Vec3 hunt(const Vec3& lab) { return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]}; }

// HyAB distance (Abasi, Tehran & Fairchild 2020), FLIP's colour distance: |ΔL| + ||(Δa, Δb)||.
double hyab(const Vec3& p, const Vec3& q) {
  return std::fabs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
}

Vec3 hunt_lab_of_rgb(const Vec3& rgb) { return hunt(xyz_to_lab(mul(kRgbToXyz, rgb))); }

// A planar single-channel image.
struct Plane {
  int width = 0, height = 0;
  std::vector<double> v;
  double at_clamped(int x, int y) const {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return v[size_t(y) * width + x];
  }
};

// Separable correlation with kernel kx(x) ky(y) over [-r, r]^2 (kernels of odd length 2r+1);
// borders replicate the edge pixels.
Plane filter(const Plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
  const int r = int(kx.size()) / 2;
  Plane tmp = in, out = in;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) s += kx[k + r] * in.at_clamped(x + k, y);
      tmp.v[size_t(y) * in.width + x] = s;
    }
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) s += ky[k + r] * tmp.at_clamped(x, y + k);
      out.v[size_t(y) * in.width + x] = s;
    }
  return out;
}

// Contrast sensitivity functions as sums of Gaussians (the paper's CSF
// constants, after Johnson & Fairchild 2003): S(x) = Σ_i a_i sqrt(π / b_i) exp(-π² x² / b_i), x in
// degrees.
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kCsfAchromatic = {1.0, 0.0047, 0.0, 1e-5};
constexpr Csf kCsfRedGreen = {1.0, 0.0053, 0.0, 1e-5};
constexpr Csf kCsfBlueYellow = {34.1, 0.04, 13.5, 0.025};

// Filters one opponent channel with its CSF, sampled on the pixel grid over the radius
// r = ceil(3 sqrt(b_max / (2π²)) ppd) of the widest Gaussian of all three channels and
// normalised to unit sum. Each Gaussian term is separable, so the 2D filter is applied as a
// weighted sum of two separable passes.
Plane csf_filter(const Plane& in, const Csf& csf, double ppd) {
  const double b_max = 0.04;
  const int r = int(std::ceil(3.0 * std::sqrt(b_max / (2.0 * kPi * kPi)) * ppd));
  const double dx = 1.0 / ppd;
  const double a[2] = {csf.a1, csf.a2}, b[2] = {csf.b1, csf.b2};
  std::vector<double> g[2];
  double weight[2], total = 0.0;
  for (int i = 0; i < 2; ++i) {
    g[i].resize(2 * r + 1);
    double sum = 0.0;
    for (int k = -r; k <= r; ++k) {
      double x = k * dx;
      sum += g[i][k + r] = std::exp(-kPi * kPi * x * x / b[i]);
    }
    // The 2D term's sum over the grid is a_i sqrt(π / b_i) (Σ_k g_i(k))^2.
    weight[i] = a[i] * std::sqrt(kPi / b[i]);
    total += weight[i] * sum * sum;
  }
  Plane out = in;
  std::fill(out.v.begin(), out.v.end(), 0.0);
  for (int i = 0; i < 2; ++i) {
    if (weight[i] == 0.0) continue;
    Plane term = filter(in, g[i], g[i]);
    for (size_t j = 0; j < out.v.size(); ++j) out.v[j] += weight[i] / total * term.v[j];
  }
  return out;
}

// Edge and point detectors (feature pipeline): first and second derivatives of a Gaussian with
// sigma = 0.5 w ppd, w = 0.082 degrees (peak-to-trough width of human edge detection), radius
// ceil(3 sigma). The 2D kernels d(x) g(y) are normalised so their positive weights sum to 1 and
// their negative weights to -1; since g(y) does not change sign, this normalises d and g
// separately.
struct FeatureKernels {
  std::vector<double> edge, point, smooth;
};

FeatureKernels feature_kernels(double ppd) {
  const double w = 0.082, sigma = 0.5 * w * ppd;
  const int r = int(std::ceil(3.0 * sigma));
  FeatureKernels k;
  k.edge.resize(2 * r + 1);
  k.point.resize(2 * r + 1);
  k.smooth.resize(2 * r + 1);
  double smooth_sum = 0.0, edge_pos = 0.0, edge_neg = 0.0, point_pos = 0.0, point_neg = 0.0;
  for (int i = -r; i <= r; ++i) {
    double g = std::exp(-double(i) * i / (2.0 * sigma * sigma));
    double e = -i * g, p = (double(i) * i / (sigma * sigma) - 1.0) * g;
    k.smooth[i + r] = g;
    k.edge[i + r] = e;
    k.point[i + r] = p;
    smooth_sum += g;
    (e > 0 ? edge_pos : edge_neg) += std::fabs(e);
    (p > 0 ? point_pos : point_neg) += std::fabs(p);
  }
  for (int i = 0; i <= 2 * r; ++i) {
    k.smooth[i] /= smooth_sum;
    k.edge[i] /= k.edge[i] > 0 ? edge_pos : edge_neg;
    k.point[i] /= k.point[i] > 0 ? point_pos : point_neg;
  }
  return k;
}

// Magnitudes of the edge and point responses, ||(f_x, f_y)||.
void feature_magnitudes(const Plane& y, const FeatureKernels& k, Plane* edges, Plane* points) {
  Plane ex = filter(y, k.edge, k.smooth), ey = filter(y, k.smooth, k.edge);
  Plane px = filter(y, k.point, k.smooth), py = filter(y, k.smooth, k.point);
  *edges = ex;
  *points = px;
  for (size_t i = 0; i < y.v.size(); ++i) {
    edges->v[i] = std::hypot(ex.v[i], ey.v[i]);
    points->v[i] = std::hypot(px.v[i], py.v[i]);
  }
}

// Both images after the colour pipeline's spatial filtering: clamp to [0, 1], to
// YyCxCz, CSF-filter each channel, back to linear RGB, clamp to the RGB cube, to Hunt-adjusted
// L*a*b*. Also returns the unfiltered normalised luminance used by the feature pipeline,
// (Yy + 16) / 116 = Y / Y_white.
void prepare(const RgbImage& img, double ppd, std::vector<Vec3>* lab, Plane* luminance) {
  Plane opponent[3];
  for (Plane& p : opponent) {
    p.width = img.width;
    p.height = img.height;
    p.v.resize(img.pixel_count());
  }
  *luminance = opponent[0];
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    Vec3 rgb;
    for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(img.rgb[3 * i + c], 0.0, 1.0);
    Vec3 o = xyz_to_ycxcz(mul(kRgbToXyz, rgb));
    for (int c = 0; c < 3; ++c) opponent[c].v[i] = o[c];
    luminance->v[i] = (o[0] + 16.0) / 116.0;
  }
  Plane filtered[3] = {csf_filter(opponent[0], kCsfAchromatic, ppd),
                       csf_filter(opponent[1], kCsfRedGreen, ppd),
                       csf_filter(opponent[2], kCsfBlueYellow, ppd)};
  lab->resize(img.pixel_count());
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    Vec3 rgb = mul(kXyzToRgb, ycxcz_to_xyz({filtered[0].v[i], filtered[1].v[i], filtered[2].v[i]}));
    for (double& c : rgb) c = std::clamp(c, 0.0, 1.0);
    (*lab)[i] = hunt_lab_of_rgb(rgb);
  }
}

// Error at cumulative-error fraction p of the total: the weighted percentile of RTG II ch. 19.
double weighted_percentile(const std::vector<float>& sorted, double total, double p) {
  double target = p * total, running = 0.0;
  for (float e : sorted) {
    running += e;
    if (running >= target) return e;
  }
  return sorted.empty() ? 0.0 : sorted.back();
}

}  // namespace

double flip_default_pixels_per_degree() { return 0.7 * (3840.0 / 0.7) * kPi / 180.0; }

FlipResult ldr_flip(const RgbImage& test, const RgbImage& reference, double pixels_per_degree) {
  check_same_size(reference, "reference", test, "test image");
  if (!(pixels_per_degree > 0.0)) throw std::invalid_argument("pixels per degree must be positive");
  std::vector<Vec3> lab_ref, lab_test;
  Plane y_ref, y_test;
  prepare(reference, pixels_per_degree, &lab_ref, &y_ref);
  prepare(test, pixels_per_degree, &lab_test, &y_test);

  // Colour difference: HyAB^q_c, redistributed so that errors up to p_c c_max map
  // linearly to [0, p_t] and the rest to (p_t, 1]; c_max is the exponentiated HyAB distance
  // between Hunt-adjusted green and blue, the largest in the RGB cube.
  const double cmax =
      std::pow(hyab(hunt_lab_of_rgb({0.0, 1.0, 0.0}), hunt_lab_of_rgb({0.0, 0.0, 1.0})), kQc);
  const double pccmax = kPc * cmax;

  FeatureKernels kernels = feature_kernels(pixels_per_degree);
  Plane edges_ref, points_ref, edges_test, points_test;
  feature_magnitudes(y_ref, kernels, &edges_ref, &points_ref);
  feature_magnitudes(y_test, kernels, &edges_test, &points_test);

  FlipResult r;
  r.map.resize(test.pixel_count());
  for (size_t i = 0; i < r.map.size(); ++i) {
    double e = std::pow(hyab(lab_ref[i], lab_test[i]), kQc);
    double color =
        e < pccmax ? kPt / pccmax * e : kPt + (e - pccmax) / (cmax - pccmax) * (1.0 - kPt);
    // Feature difference: the larger of the edge and point magnitude differences,
    // scaled by 1/sqrt(2) and raised to q_f.
    double f = std::max(std::fabs(edges_ref.v[i] - edges_test.v[i]),
                        std::fabs(points_ref.v[i] - points_test.v[i]));
    double feature = std::pow(f / std::sqrt(2.0), kQf);
    r.map[i] = float(std::pow(color, 1.0 - feature));  // FLIP = ΔE_c^(1 - ΔE_f)
  }

  std::vector<float> sorted = r.map;
  std::sort(sorted.begin(), sorted.end());
  double total = 0.0;
  for (float e : sorted) total += e;
  r.mean = total / double(sorted.size());
  r.min = sorted.front();
  r.max = sorted.back();
  r.weighted_median = weighted_percentile(sorted, total, 0.5);
  r.weighted_quartile1 = weighted_percentile(sorted, total, 0.25);
  r.weighted_quartile3 = weighted_percentile(sorted, total, 0.75);
  return r;
}

}  // namespace tr
