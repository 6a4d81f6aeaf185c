// The film estimator of core/film.h against Mitsuba's splatting rule, for every tabulated
// filter, at every pixel of a small film (interior and border pixels), with and without
// sample_border and with a crop window.
//
// The radiance on the film is the fixed function mu(x, y) = 2 + g1(x) h1(y) + g2(x) h2(y)
// (a sum of separable terms with closed-form integrals). Three values per pixel:
//  - brute: Mitsuba's rule simulated literally (scalar ImageBlock::put, put_block clipping to
//    the crop window, division by the weight channel) for samples on a regular grid in every
//    pixel of the sampled rectangle S: a quadrature of what Mitsuba converges to.
//  - exact: integral_S f_d(c - x) mu(x) dx / integral_S f_d(c - x) dx, per-bin closed form.
//  - ours: the estimator's expectation E[s mu] / E[s], by quadrature over the random number of
//    each axis (axis_expectation).
// brute and exact must agree within the grid's quadrature error, ours and exact within float
// rounding. The test is able to fail: the same comparison rejects the continuous filter in
// place of the table and the sampled rectangle of the other sample_border setting (without
// sample_border: a footprint not truncated to the film), checked below by a margin.
#include "core/film.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "core/rng.h"
#include "film_test_camera.h"
#include "render/film_moments.h"

namespace tr {
namespace {

struct Term {  // g(x) h(y) with antiderivatives G, H
  std::function<double(double)> g, G, h, H;
};

std::vector<Term> radiance_terms() {
  auto one = [](double) { return 1.0; };
  auto id = [](double t) { return t; };
  return {
      {one, id, [](double) { return 2.0; }, [](double t) { return 2.0 * t; }},
      {[](double x) { return std::exp(0.25 * x); },
       [](double x) { return 4.0 * std::exp(0.25 * x); },
       [](double y) { return std::cos(0.8 * y); },
       [](double y) { return std::sin(0.8 * y) / 0.8; }},
      {[](double x) { return std::sin(1.3 * x + 0.4); },
       [](double x) { return -std::cos(1.3 * x + 0.4) / 1.3; },
       [](double y) { return std::exp(-0.2 * y); },
       [](double y) { return -5.0 * std::exp(-0.2 * y); }},
  };
}

double mu(const std::vector<Term>& terms, double x, double y) {
  double v = 0.0;
  for (const Term& t : terms) v += t.g(x) * t.h(y);
  return v;
}

struct FilmSetup {
  uint type;
  vec4 params;
  float radius;
  bool sample_border;
  uvec2 film, crop_offset, crop;
  int grid;  // brute force: grid x grid samples per pixel (see brute_force)
};

Camera make_camera(const FilmSetup& f) {
  Camera c{};
  c.rfilter = f.type;
  c.width = f.crop.x;
  c.height = f.crop.y;
  c.film_size = vec2(f.film);
  c.crop_offset = vec2(f.crop_offset);
  c.filter_radius = f.radius;
  c.filter_scale = float(FILTER_RESOLUTION) / f.radius;
  for (uint i = 0; i <= FILTER_RESOLUTION; ++i)
    c.filter_table[i / 4][i % 4] = rfilter_table_entry(f.type, f.params, f.radius, i);
  for (uint k = 0; k <= 2 * FILTER_RESOLUTION; ++k)
    c.filter_cdf[k / 4][k % 4] = filter_cdf_entry(c.filter_table, f.radius, k);
  // Mitsuba's border_size (src/core/rfilter.cpp).
  float border = f.sample_border ? std::ceil(f.radius - 0.5f - 2.0f * 1500.0f * 0x1p-24f) : 0.0f;
  c.sample_min = c.crop_offset - vec2(border);
  c.sample_max = c.crop_offset + vec2(f.crop) + vec2(border);
  bind_film_test_camera(c);
  return c;
}

float table_value(const Camera& c, uint i) { return c.filter_table[i / 4][i % 4]; }

// eval_discretized (include/mitsuba/core/rfilter.h), in float like Mitsuba.
float mitsuba_discretized(const Camera& c, float x) {
  uint index = std::min(uint(std::abs(x * c.filter_scale)), FILTER_RESOLUTION);
  return table_value(c, index);
}

// Mitsuba's splatting rule for samples at the centres of an m x m grid of cells in each pixel
// of S. m is even and a multiple of 31 / radius, so that every cell lies within one step of f_d
// (the steps' edges sit at multiples of radius / 31 from the half-integer pixel centres): the
// rule is then a midpoint quadrature of smooth integrands, accurate to O(m^-2).
std::vector<double> brute_force(const Camera& c, const std::vector<Term>& terms, int m) {
  const int w = int(c.width), h = int(c.height);
  const int ox = int(c.crop_offset.x), oy = int(c.crop_offset.y);
  std::vector<double> value(size_t(w) * h, 0.0), weight(size_t(w) * h, 0.0);
  const float r = c.filter_radius;
  for (int py = int(c.sample_min.y); py < int(c.sample_max.y); ++py)
    for (int px = int(c.sample_min.x); px < int(c.sample_max.x); ++px)
      for (int b = 0; b < m; ++b)
        for (int a = 0; a < m; ++a) {
          // ImageBlock::put: pixels i with ceil(p - 0.5 - r) <= i <= floor(p - 0.5 + r),
          // weight f_d(i - (p - 0.5)); put_block keeps those inside the crop window.
          float pos_x = float(px) + (a + 0.5f) / float(m) - float(ox);
          float pos_y = float(py) + (b + 0.5f) / float(m) - float(oy);
          float fx = pos_x - 0.5f, fy = pos_y - 0.5f;
          int x0 = std::max(int(std::ceil(fx - r)), 0),
              x1 = std::min(int(std::floor(fx + r)), w - 1);
          int y0 = std::max(int(std::ceil(fy - r)), 0),
              y1 = std::min(int(std::floor(fy + r)), h - 1);
          double L = mu(terms, pos_x + ox, pos_y + oy);
          for (int y = y0; y <= y1; ++y) {
            float wy = mitsuba_discretized(c, float(y) - fy);
            for (int x = x0; x <= x1; ++x) {
              float wxy = mitsuba_discretized(c, float(x) - fx) * wy;
              value[size_t(y) * w + x] += double(wxy) * L;
              weight[size_t(y) * w + x] += double(wxy);
            }
          }
        }
  for (size_t i = 0; i < value.size(); ++i) value[i] /= weight[i];
  return value;
}

// integral over [lo, hi) of f(t) G'(center + t), f piecewise constant on the table's bins
// (table = true) or the continuous filter (midpoint rule, 64 steps per bin).
double axis_integral(const Camera& c, const FilmSetup& f, double center, double lo, double hi,
                     const std::function<double(double)>& g, const std::function<double(double)>& G,
                     bool table) {
  double h = double(c.filter_radius) / FILTER_RESOLUTION, sum = 0.0;
  for (uint k = 0; k < 2 * FILTER_RESOLUTION; ++k) {
    double a = std::max((-double(c.filter_radius) + k * h), lo);
    double b = std::min((-double(c.filter_radius) + k * h) + h, hi);
    if (b <= a) continue;
    if (table) {
      sum += table_value(c, filter_bin_entry(k)) * (G(center + b) - G(center + a));
    } else {
      const int steps = 64;
      for (int i = 0; i < steps; ++i) {
        double t = a + (i + 0.5) * (b - a) / steps;
        sum += rfilter_eval(f.type, f.params, float(t)) * g(center + t) * (b - a) / steps;
      }
    }
  }
  return sum;
}

// The ratio of integrals over S at every pixel.
std::vector<double> exact(const Camera& c, const FilmSetup& f, const std::vector<Term>& terms,
                          bool table) {
  std::vector<double> out;
  auto one = [](double) { return 1.0; };
  auto id = [](double t) { return t; };
  for (uint y = 0; y < c.height; ++y)
    for (uint x = 0; x < c.width; ++x) {
      double cx = c.crop_offset.x + x + 0.5, cy = c.crop_offset.y + y + 0.5;
      double lx = c.sample_min.x - cx, hx = c.sample_max.x - cx;
      double ly = c.sample_min.y - cy, hy = c.sample_max.y - cy;
      double num = 0.0;
      for (const Term& t : terms)
        num += axis_integral(c, f, cx, lx, hx, t.g, t.G, table) *
               axis_integral(c, f, cy, ly, hy, t.h, t.H, table);
      out.push_back(num / (axis_integral(c, f, cx, lx, hx, one, id, table) *
                           axis_integral(c, f, cy, ly, hy, one, id, table)));
    }
  return out;
}

// sum over the estimator's samples of s g(x) and of s, for one axis, each divided by the number
// of samples: integral_0^1 s(u) g(x(u)) du. u -> (x, s) is piecewise linear in x with constant
// s on the segments [U_k, U_k+1) of the cumulative bin masses (computed here independently);
// a 4-point Gauss-Legendre rule per segment, at nodes that sample_filter_axis maps, makes the
// integral exact up to rounding for these smooth g.
void axis_expectation(const Camera& c, float lo, float hi, float center,
                      const std::vector<std::function<double(double)>>& g, std::vector<double>& sg,
                      double& s) {
  const double node[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                          0.8611363115940526};
  const double weight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                            0.3478548451374538};
  const double h = double(c.filter_radius) / FILTER_RESOLUTION;
  std::vector<double> mass(2 * FILTER_RESOLUTION);
  double total = 0.0;
  for (uint k = 0; k < mass.size(); ++k) {
    double a = std::max((-double(c.filter_radius) + k * h), double(lo));
    double b = std::min((-double(c.filter_radius) + k * h) + h, double(hi));
    mass[k] = std::max(b - a, 0.0) * std::abs(table_value(c, filter_bin_entry(k)));
    total += mass[k];
  }
  sg.assign(g.size(), 0.0);
  s = 0.0;
  double start = 0.0;
  for (uint k = 0; k < mass.size(); ++k) {
    const double width = mass[k] / total;
    for (int i = 0; i < 4 && width > 0.0; ++i) {
      float sign;
      const float u = float(start + 0.5 * width * (1.0 + node[i]));
      const float x = sample_filter_axis(c.filter_radius, u, lo, hi, sign);
      s += 0.5 * width * weight[i] * sign;
      for (size_t j = 0; j < g.size(); ++j)
        sg[j] += 0.5 * width * weight[i] * sign * g[j](center + x);
    }
    start += width;
  }
}

// E[s mu] / E[s] of the estimator at every pixel (the axes are sampled independently,
// FilmEstimator.PositionComposesTheTwoAxes, and mu is a sum of separable terms).
std::vector<double> estimator_expectation(const Camera& c, const std::vector<Term>& terms) {
  std::vector<std::function<double(double)>> gs, hs;
  for (const Term& t : terms) {
    gs.push_back(t.g);
    hs.push_back(t.h);
  }
  std::vector<double> out;
  for (uint y = 0; y < c.height; ++y)
    for (uint x = 0; x < c.width; ++x) {
      const vec2 center = c.crop_offset + vec2(float(x), float(y)) + vec2(0.5f);
      const vec2 lo = c.sample_min - center, hi = c.sample_max - center;
      std::vector<double> gx, hy;
      double sx, sy;
      axis_expectation(c, lo.x, hi.x, center.x, gs, gx, sx);
      axis_expectation(c, lo.y, hi.y, center.y, hs, hy, sy);
      double num = 0.0;
      for (size_t k = 0; k < terms.size(); ++k) num += gx[k] * hy[k];
      out.push_back(num / (sx * sy));
    }
  return out;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// Radii 1, 2, 3 (grid 62) and 1.55 = 31 / 20 (grid 60), see brute_force.
std::vector<FilmSetup> setups() {
  const uvec2 film(12, 9), origin(0, 0), big(16, 14);
  return {
      {RFILTER_GAUSSIAN, vec4(0.5f), 2.0f, false, film, origin, film, 62},
      {RFILTER_GAUSSIAN, vec4(0.3875f), 1.55f, true, film, origin, film, 60},
      {RFILTER_TENT, vec4(1.0f), 1.0f, false, film, origin, film, 62},
      {RFILTER_TENT, vec4(1.55f), 1.55f, true, film, origin, film, 60},
      {RFILTER_MITCHELL, vec4(1.0f / 3, 1.0f / 3, 0, 0), 2.0f, false, film, origin, film, 62},
      {RFILTER_MITCHELL, vec4(0.2f, 0.4f, 0, 0), 2.0f, true, film, origin, film, 62},
      {RFILTER_CATMULLROM, vec4(0.0f), 2.0f, false, film, origin, film, 62},
      {RFILTER_LANCZOS, vec4(2.0f), 2.0f, false, film, origin, film, 62},
      {RFILTER_LANCZOS, vec4(3.0f), 3.0f, false, film, origin, film, 62},
      {RFILTER_LANCZOS, vec4(3.0f), 3.0f, true, big, uvec2(3, 2), uvec2(10, 9), 62},
      {RFILTER_CATMULLROM, vec4(0.0f), 2.0f, false, big, uvec2(5, 4), uvec2(8, 7), 62},
  };
}

class FilmEstimator : public testing::TestWithParam<FilmSetup> {};

TEST_P(FilmEstimator, ConvergesToMitsubasSplattedImage) {
  const FilmSetup& f = GetParam();
  const Camera c = make_camera(f);
  const std::vector<Term> terms = radiance_terms();
  const std::vector<double> truth = exact(c, f, terms, true);
  const double brute_error = max_difference(brute_force(c, terms, f.grid), truth);
  const double ours_error = max_difference(estimator_expectation(c, terms), truth);
  const double continuous_error = max_difference(exact(c, f, terms, false), truth);
  FilmSetup toggled = f;
  toggled.sample_border = !f.sample_border;
  const double region_error =
      max_difference(exact(make_camera(toggled), toggled, terms, true), truth);
  std::printf(
      "max |difference| from the exact ratio: brute force %.2e, estimator %.2e; "
      "continuous filter %.2e, other sample_border %.2e\n",
      brute_error, ours_error, continuous_error, region_error);
  // |mu| <= 25 here; tolerances are absolute. Measured: brute force <= 1.5e-4, estimator
  // <= 3e-6, the alternatives >= 4e-2.
  const double tolerance = 5e-4;
  EXPECT_LT(brute_error, tolerance);
  EXPECT_LT(ours_error, 5e-5);
  EXPECT_GT(continuous_error, 5 * tolerance);
  EXPECT_GT(region_error, 5 * tolerance);
}

INSTANTIATE_TEST_SUITE_P(Filters, FilmEstimator, testing::ValuesIn(setups()));

TEST(FilmEstimator, PositionComposesTheTwoAxes) {
  const Camera c = make_camera(setups()[9]);
  for (uint i = 0; i < 1000; ++i) {
    Rng rng = rng_init(i, 0u, 3u);
    const vec2 u = rng_next_2d(rng);
    const uvec2 pixel(i % c.width, (i / c.width) % c.height);
    const vec2 center = c.crop_offset + vec2(pixel) + vec2(0.5f);
    float sign, sign_x, sign_y;
    const vec2 p = sample_film_position(c, pixel, u, sign);
    const float tx = sample_filter_axis(c.filter_radius, u.x, c.sample_min.x - center.x,
                                        c.sample_max.x - center.x, sign_x);
    const float ty = sample_filter_axis(c.filter_radius, u.y, c.sample_min.y - center.y,
                                        c.sample_max.y - center.y, sign_y);
    EXPECT_EQ(p, center + vec2(tx, ty));
    EXPECT_EQ(sign, sign_x * sign_y);
    EXPECT_TRUE(p.x >= c.sample_min.x && p.x <= c.sample_max.x && p.y >= c.sample_min.y &&
                p.y <= c.sample_max.y);
  }
}

// The box filter: every sample uniform in its own pixel, positive.
TEST(FilmEstimator, BoxKeepsEachSampleInItsPixel) {
  Camera c{};
  c.rfilter = RFILTER_BOX;
  c.crop_offset = vec2(3.0f, 1.0f);
  float sign;
  EXPECT_EQ(sample_film_position(c, uvec2(2, 5), vec2(0.25f, 0.75f), sign), vec2(5.25f, 6.75f));
  EXPECT_EQ(sign, 1.0f);
}

// The estimator run as the backends run it: random samples, positive and negative apart,
// developed by render/film_moments.h. At a corner and an interior pixel of the 3-lobe
// Lanczos (the strongest negative lobes), within 5 standard errors (two-sided false-failure
// probability 6e-7 each).
TEST(FilmEstimator, SignedSamplesDevelopToTheFilteredValue) {
  const FilmSetup f{RFILTER_LANCZOS, vec4(3.0f), 3.0f,         false,
                    uvec2(12, 9),    uvec2(0),   uvec2(12, 9), 0};
  const Camera c = make_camera(f);
  const std::vector<Term> terms = radiance_terms();
  const std::vector<double> truth = exact(c, f, terms, true);
  for (uvec2 pixel : {uvec2(0, 0), uvec2(6, 4)}) {
    FilmMoments m;
    const uint n = 1u << 18;
    uint negative = 0;
    for (uint i = 0; i < n; ++i) {
      Rng rng = rng_init(pixel.y * c.width + pixel.x, i, 5u);
      float sign;
      vec2 p = sample_film_position(c, pixel, rng_next_2d(rng), sign);
      double L = mu(terms, p.x, p.y);
      add_sample(sign < 0.0f ? m.negative : m.positive, glm::dvec3(L));
      negative += sign < 0.0f;
    }
    double mean[3], variance[3];
    develop(m, mean, variance);
    const double expected = truth[pixel.y * c.width + pixel.x];
    EXPECT_GT(negative, n / 10);
    EXPECT_NEAR(mean[0], expected, 5.0 * std::sqrt(variance[0] / n)) << pixel.x << " " << pixel.y;
  }
}

}  // namespace
}  // namespace tr
