// Sample counts of the suite: a fast CI size by default, the full size when built with
// TWINRAY_FULL_TESTS=ON, when TWINRAY_FULL_TESTS=1 is in the environment, or with --full.
#ifndef TWINRAY_TESTS_BSDF_SUITE_SIZE_H
#define TWINRAY_TESTS_BSDF_SUITE_SIZE_H

#include <cstddef>

#include "twinray_validation.h"

namespace tr::bsdf_suite {

bool& full_size();  // set by main() from --full / the environment / the build option

struct SuiteSize {
  twinray::validation::ChiSquareOptions chi_square;
  twinray::validation::ConsistencyOptions consistency;
  std::size_t albedo_samples;
  std::size_t extreme_random_draws;
};

SuiteSize suite_size();

// The size of the same suite on the GLSL build of core/ (tests/bsdf_gpu): the full size is
// suite_size()'s, the fast size draws a quarter of its samples, since every value comes from
// lavapipe and each check runs about three times (tests/bsdf_gpu/gpu_core_calls.h).
SuiteSize gpu_suite_size();

// Overall significance of the suite: a correct implementation fails any statistical test with
// probability 1%; every test runs at the Šidák level over all of them.
constexpr double kSignificance = 0.01;

}  // namespace tr::bsdf_suite

#endif
