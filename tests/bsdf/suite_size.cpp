#include "suite_size.h"

namespace tr::bsdf_suite {

bool& full_size() {
#ifdef TWINRAY_FULL_TESTS
  static bool full = true;
#else
  static bool full = false;
#endif
  return full;
}

SuiteSize suite_size() {
  SuiteSize s;
  if (full_size()) {
    s.chi_square.sample_count = 2000000;
    s.chi_square.cos_theta_bins = 20;
    s.chi_square.phi_bins = 40;
    s.consistency.sample_count = 200000;
    s.consistency.random_pairs = 200000;
    s.albedo_samples = 1000000;
    s.extreme_random_draws = 1024;
  } else {
    s.chi_square.sample_count = 200000;
    s.chi_square.cos_theta_bins = 10;
    s.chi_square.phi_bins = 20;
    s.consistency.sample_count = 20000;
    s.consistency.random_pairs = 20000;
    s.albedo_samples = 50000;
    s.extreme_random_draws = 64;
  }
  // A bin's expected count is then off by at most 0.1 draws: (0.1)^2 / 5 adds < 0.002 to X^2
  // per bin even at the pooling threshold.
  s.chi_square.integration_tolerance = 0.1 / double(s.chi_square.sample_count);
  return s;
}

SuiteSize gpu_suite_size() {
  SuiteSize s = suite_size();
  if (full_size()) return s;
  s.chi_square.sample_count /= 4;
  s.chi_square.integration_tolerance = 0.1 / double(s.chi_square.sample_count);
  s.consistency.sample_count /= 4;
  s.consistency.random_pairs /= 4;
  s.albedo_samples /= 4;
  return s;
}

}  // namespace tr::bsdf_suite
