// Chi-square goodness-of-fit tests of sampling routines. Design after Wenzel Jakob's chi-square
// test in Mitsuba and pbrt-v3's src/tests/bsdfs.cpp: histogram the draws on a grid, integrate
// the claimed density over every cell for the expected counts, pool cells expecting fewer than
// `min_expected` draws, and compare with Pearson's X² = Σ (O - E)² / E, which is asymptotically
// chi-square distributed with (cells - 1) degrees of freedom (Pearson 1900).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "quadrature.h"
#include "random.h"
#include "twinray_validation.h"

namespace twinray::validation {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

struct Cell {
  double observed = 0.0;
  double expected = 0.0;
};

// Where the draws of each cell fell, to seed the quadrature's panels.
struct Draws {
  std::vector<std::vector<float>> x, y;
  explicit Draws(std::size_t cells) : x(cells), y(cells) {}
  void add(int cell, double xv, double yv) {
    x[cell].push_back(float(xv));
    y[cell].push_back(float(yv));
  }
};

// The cell's edges and the 1%, 10%, 50%, 90% and 99% quantiles of its draws.
std::vector<double> breakpoints(double lower, double upper, std::vector<float>& draws) {
  std::vector<double> breaks = {lower, upper};
  if (!draws.empty()) {
    std::sort(draws.begin(), draws.end());
    for (double q : {0.01, 0.1, 0.5, 0.9, 0.99}) {
      double v = draws[std::size_t(q * double(draws.size() - 1))];
      if (v > lower && v < upper) breaks.push_back(v);
    }
  }
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

// A rectangular grid over (x, y) whose density has Jacobian 1 with respect to the measure the
// pdf is stated in: (cos θ, φ) for solid angle (dω = d(cos θ) dφ), (x, y) for area.
struct Grid {
  double x0, x1, y0, y1;
  int nx, ny;

  int cell(double x, double y) const {
    int i = std::clamp(int(std::floor((x - x0) / (x1 - x0) * nx)), 0, nx - 1);
    int j = std::clamp(int(std::floor((y - y0) / (y1 - y0) * ny)), 0, ny - 1);
    return i * ny + j;
  }
};

void check_options(const ChiSquareOptions& o) {
  if (o.sample_count == 0 || o.cos_theta_bins < 1 || o.phi_bins < 1 || o.min_expected <= 0.0 ||
      o.integration_tolerance <= 0.0 || o.integration_max_panels < 1) {
    throw std::invalid_argument("ChiSquareOptions out of range");
  }
}

glm::dvec3 spherical_direction(double cos_theta, double phi) {
  double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// (cos θ, φ ∈ [0, 2π)) of a direction.
glm::dvec2 spherical_coordinates(const glm::vec3& w) {
  double phi = std::atan2(double(w.y), double(w.x));
  if (phi < 0.0) phi += kTwoPi;
  return {std::clamp(double(w.z), -1.0, 1.0), phi};
}

Grid spherical_grid(const ChiSquareOptions& o) {
  return {-1.0, 1.0, 0.0, kTwoPi, o.cos_theta_bins, o.phi_bins};
}

// Expected counts of every cell: sample_count · ∫_cell density.
void integrate_expected(const std::function<double(double, double)>& density, const Grid& g,
                        const ChiSquareOptions& o, Draws& draws, std::vector<Cell>& cells,
                        ChiSquareResult& result) {
  detail::QuadratureSettings settings{o.integration_tolerance, o.integration_max_panels};
  double dx = (g.x1 - g.x0) / g.nx, dy = (g.y1 - g.y0) / g.ny;
  for (int i = 0; i < g.nx; ++i) {
    for (int j = 0; j < g.ny; ++j) {
      int c = i * g.ny + j;
      detail::Quadrature q = detail::adaptive_gauss_kronrod_2d(
          density, breakpoints(g.x0 + i * dx, g.x0 + (i + 1) * dx, draws.x[c]),
          breakpoints(g.y0 + j * dy, g.y0 + (j + 1) * dy, draws.y[c]), settings);
      if (!std::isfinite(q.value) || q.value < 0.0) {
        std::ostringstream m;
        m << "density integrates to " << q.value << " over cell (" << i << ", " << j << ")";
        result.failure = m.str();
        return;
      }
      cells[c].expected = q.value * double(o.sample_count);
      result.pdf_integral += q.value;
      result.integration_error += q.error;
    }
  }
}

// Pools sparse cells and computes X² and its p-value; hard failures (draws where the density is
// zero, ∫ pdf > 1, non-finite densities) then set `failure` and p = 0.
void finish(std::vector<Cell> cells, const ChiSquareOptions& o, ChiSquareResult& result) {
  double stray = 0.0;
  for (const Cell& c : cells) {
    if (c.expected == 0.0) stray += c.observed;
  }
  cells.erase(
      std::remove_if(cells.begin(), cells.end(), [](const Cell& c) { return c.expected == 0.0; }),
      cells.end());
  std::sort(cells.begin(), cells.end(),
            [](const Cell& a, const Cell& b) { return a.expected < b.expected; });
  // Sparse cells (ascending) merge into one pool until it expects at least min_expected.
  Cell pool;
  int pooled_cells = 0;
  std::vector<Cell> merged;
  for (const Cell& c : cells) {
    if (c.expected < o.min_expected || (pooled_cells > 0 && pool.expected < o.min_expected)) {
      pool.observed += c.observed;
      pool.expected += c.expected;
      ++pooled_cells;
    } else {
      merged.push_back(c);
    }
  }
  if (pooled_cells > 0) merged.push_back(pool);
  for (const Cell& c : merged) {
    result.statistic += (c.observed - c.expected) * (c.observed - c.expected) / c.expected;
  }
  result.dof = int(merged.size()) - 1;
  result.p_value = result.dof >= 1 ? chi_square_p_value(result.statistic, result.dof) : 1.0;

  if (result.failure.empty() && result.outside_support > 0) {
    std::ostringstream m;
    m << result.outside_support << " draws where pdf() is 0 (outside the support)";
    result.failure = m.str();
  }
  if (result.failure.empty() && stray > 0.0) {
    std::ostringstream m;
    m << stray << " draws in cells where the integrated density is 0";
    result.failure = m.str();
  }
  // ∫ pdf ≤ 1: beyond the quadrature's error bound and 1e-5 for the float rounding of the
  // density values (a few ulps each), a larger integral is the density's fault.
  const double bound = 1.0 + result.integration_error + 1e-5;
  if (result.failure.empty() && result.pdf_integral > bound) {
    std::ostringstream m;
    m.precision(7);
    m << "pdf integrates to " << result.pdf_integral << " > 1 + error bound (" << bound << ")";
    result.failure = m.str();
  }
  if (!result.failure.empty()) result.p_value = 0.0;
}

// Key of a delta atom: its lobe, and its direction to 1e-4 per component.
std::tuple<unsigned, long, long, long> atom_key(const BsdfSample& s) {
  return {s.lobe, std::lround(s.wo.x * 1e4), std::lround(s.wo.y * 1e4), std::lround(s.wo.z * 1e4)};
}

}  // namespace

ChiSquareResult chi_square_bsdf(const BsdfUnderTest& bsdf, const glm::vec3& wi,
                                const ChiSquareOptions& o) {
  check_options(o);
  if (!bsdf.sample || !bsdf.pdf)
    throw std::invalid_argument(bsdf.name + ": sample and pdf required");
  ChiSquareResult result;
  Grid grid = spherical_grid(o);
  std::vector<Cell> cells(std::size_t(grid.nx) * grid.ny);
  Draws draws(cells.size());
  struct Atom {
    double probability;
    double observed;
  };
  std::map<std::tuple<unsigned, long, long, long>, Atom> atoms;
  detail::Random random(o.seed);
  for (std::size_t n = 0; n < o.sample_count; ++n) {
    float u1 = random.uniform();
    glm::vec2 u2 = random.uniform2();
    BsdfSample s = bsdf.sample(wi, u1, u2);
    ++result.samples;
    if (!(s.pdf > 0.0f)) {
      ++result.failed_samples;
      continue;
    }
    if (s.delta) {
      ++result.delta_samples;
      auto [it, inserted] = atoms.try_emplace(atom_key(s), Atom{double(s.pdf), 0.0});
      it->second.observed += 1.0;
      continue;
    }
    if (!(bsdf.pdf(wi, s.wo) > 0.0f)) ++result.outside_support;
    glm::dvec2 p = spherical_coordinates(s.wo);
    int c = grid.cell(p.x, p.y);
    cells[c].observed += 1.0;
    draws.add(c, p.x, p.y);
  }
  integrate_expected(
      [&](double cos_theta, double phi) {
        return double(bsdf.pdf(wi, glm::vec3(spherical_direction(cos_theta, phi))));
      },
      grid, o, draws, cells, result);
  result.delta_atoms = atoms.size();
  for (const auto& [key, atom] : atoms) {
    cells.push_back({atom.observed, atom.probability * double(o.sample_count)});
    result.pdf_integral += atom.probability;
  }
  finish(std::move(cells), o, result);
  return result;
}

ChiSquareResult chi_square_directions(const DirectionSampler& sampler, const ChiSquareOptions& o) {
  check_options(o);
  if (!sampler.sample || !sampler.pdf) {
    throw std::invalid_argument(sampler.name + ": sample and pdf required");
  }
  ChiSquareResult result;
  Grid grid = spherical_grid(o);
  std::vector<Cell> cells(std::size_t(grid.nx) * grid.ny);
  Draws draws(cells.size());
  detail::Random random(o.seed);
  for (std::size_t n = 0; n < o.sample_count; ++n) {
    DirectionSample s = sampler.sample(random.uniform2());
    ++result.samples;
    if (!(s.pdf > 0.0f)) {
      ++result.failed_samples;
      continue;
    }
    if (!(sampler.pdf(s.w) > 0.0f)) ++result.outside_support;
    glm::dvec2 p = spherical_coordinates(s.w);
    int c = grid.cell(p.x, p.y);
    cells[c].observed += 1.0;
    draws.add(c, p.x, p.y);
  }
  integrate_expected(
      [&](double cos_theta, double phi) {
        return double(sampler.pdf(glm::vec3(spherical_direction(cos_theta, phi))));
      },
      grid, o, draws, cells, result);
  finish(std::move(cells), o, result);
  return result;
}

ChiSquareResult chi_square_planar(const PlanarSampler& sampler, const ChiSquareOptions& o) {
  check_options(o);
  if (!sampler.sample || !sampler.pdf) {
    throw std::invalid_argument(sampler.name + ": sample and pdf required");
  }
  ChiSquareResult result;
  Grid grid{sampler.lower.x, sampler.upper.x,  sampler.lower.y,
            sampler.upper.y, o.cos_theta_bins, o.phi_bins};
  std::vector<Cell> cells(std::size_t(grid.nx) * grid.ny);
  Draws draws(cells.size());
  std::size_t outside_rectangle = 0;
  detail::Random random(o.seed);
  for (std::size_t n = 0; n < o.sample_count; ++n) {
    glm::vec2 p = sampler.sample(random.uniform2());
    ++result.samples;
    if (!(p.x >= grid.x0 && p.x <= grid.x1 && p.y >= grid.y0 && p.y <= grid.y1)) {
      ++outside_rectangle;
      continue;
    }
    if (!(sampler.pdf(p) > 0.0f)) ++result.outside_support;
    int c = grid.cell(p.x, p.y);
    cells[c].observed += 1.0;
    draws.add(c, p.x, p.y);
  }
  if (outside_rectangle > 0) {
    result.failure = std::to_string(outside_rectangle) + " draws outside the test rectangle";
  }
  integrate_expected(
      [&](double x, double y) { return double(sampler.pdf(glm::vec2(float(x), float(y)))); }, grid,
      o, draws, cells, result);
  finish(std::move(cells), o, result);
  return result;
}

}  // namespace twinray::validation
