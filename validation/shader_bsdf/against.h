// `twinray check-bsdf --against PLUGIN k=v ...`: a user's BSDF compared with one of twinray's
// over a grid of directions — eval and pdf at the same (wi, wo), and the directional albedo of
// each by Monte Carlo — so a user can see whether their "GGX" is Mitsuba's GGX, and where and by
// how much it is not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "twinray_validation.h"

namespace tr::shader_bsdf {

struct AgainstOptions {
  // theta_i and theta_o of the grid (degrees); every pair is compared at each azimuth below.
  std::vector<double> theta_degrees;  // default: 2.5, 7.5, ..., 87.5, 89
  double phi_i_degrees = 30.0;
  int delta_phi_steps = 8;  // phi_o = phi_i + k 360 / steps: 180 is the plane of the mirror
  // Two values agree within the tolerance of the consistency check (validation/bsdf's
  // ConsistencyOptions): |a - b| <= relative |max(a, b)| + absolute.
  float relative_tolerance = 1e-3f;
  float absolute_tolerance = 1e-6f;
  // The albedo comparison: at these incident angles, `albedo_samples` draws of each BSDF.
  std::vector<double> albedo_theta_degrees = {0.0, 30.0, 60.0, 85.0, 89.9};
  std::size_t albedo_samples = 25000;
  std::uint64_t seed = 3;
  double alpha_per_test = 0.01;  // level of each albedo test (Šidák is the caller's)
  AgainstOptions();
};

struct AgainstPair {  // one compared (wi, wo) and the two values, the user's first
  glm::vec3 wi{0.0f}, wo{0.0f};
  glm::vec3 user{0.0f}, reference{0.0f};
  double difference = 0.0;  // relative: |a - b| / max(|a|, |b|), largest channel
};

struct AgainstAlbedo {
  double theta_i = 0.0;
  glm::dvec3 user{0.0}, user_error{0.0};  // mean sample weight and its standard error
  glm::dvec3 reference{0.0}, reference_error{0.0};
  double p_value = 1.0;  // two-sided z test of equal means, Bonferroni over distinct channels
};

struct AgainstResult {
  std::string user, reference;  // names
  std::vector<double> theta;    // the grid's angles
  // Largest relative difference over the azimuths and channels, per cell [i * n + o] (i: theta_i).
  std::vector<double> eval_difference, pdf_difference;
  std::vector<unsigned char> eval_beyond_tolerance;  // per cell: some pair differs beyond it
  std::size_t pairs = 0;                             // (wi, wo) compared
  std::size_t eval_mismatches = 0, pdf_mismatches = 0;
  AgainstPair worst_eval, worst_pdf;
  std::vector<AgainstAlbedo> albedo;
  double alpha_per_test = 0.0;
  double phi_i = 0.0;  // of every incident direction (degrees)
  bool eval_equal() const { return eval_mismatches == 0; }
  bool albedo_equal() const;
  // Report lines: "vs-eval" and "vs-albedo" (failing where they differ) and "vs-pdf" (reported,
  // never failing: another sampling strategy of the same BSDF is fine).
  twinray::validation::Report report() const;
};

// Evaluates `user` inside `run` (a ShaderBsdf's run_check) and `reference` directly.
AgainstResult compare_against(const twinray::validation::BsdfUnderTest& user,
                              const twinray::validation::CheckRunner& run,
                              const twinray::validation::BsdfUnderTest& reference,
                              const AgainstOptions& options);

// The table printed by check-bsdf: eval differences per (theta_i, theta_o) and the albedos.
std::string against_table(const AgainstResult& result);

// A heat map of the eval differences over (theta_i, theta_o), log scale, as an SVG document.
std::string against_heat_map_svg(const AgainstResult& result);

}  // namespace tr::shader_bsdf
