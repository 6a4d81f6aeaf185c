// The cases of the suite, grouped in families (one gtest per family): chi-square of every warp
// of core/warp.h and of the microfacet normal samplers, every BSDF of core/bsdf.h over its
// parameter grid at several incident directions, and the extremes grid of every BSDF.
#ifndef TWINRAY_TESTS_BSDF_CASES_H
#define TWINRAY_TESTS_BSDF_CASES_H

#include <optional>
#include <string>
#include <vector>

#include "twinray_validation.h"

namespace tr::bsdf_suite {

struct StatisticalCase {
  std::string family;
  std::optional<twinray::validation::DirectionSampler> directions;
  std::optional<twinray::validation::PlanarSampler> planar;
  std::optional<twinray::validation::BsdfUnderTest> bsdf;  // validate_bsdf at `incident`
  std::vector<glm::vec3> incident;
  // Albedo test on energy weights, for BSDFs whose radiance weights carry 1/eta^2 on
  // transmission (bsdf->energy_conserving is then false).
  std::optional<twinray::validation::BsdfUnderTest> energy;
};

struct ExtremesCase {
  std::string family;
  twinray::validation::BsdfUnderTest bsdf;
};

const std::vector<StatisticalCase>& statistical_cases();
const std::vector<ExtremesCase>& extremes_cases();

// Statistical tests (p-values) over all statistical cases, and the Šidák level of each.
std::size_t statistical_test_count();
double alpha_per_test();

std::vector<std::string> statistical_families();
std::vector<std::string> extremes_families();

// Runs every case of a family and returns its report.
twinray::validation::Report run_statistical_family(const std::string& family);
twinray::validation::Report run_extremes_family(const std::string& family);

}  // namespace tr::bsdf_suite

#endif
