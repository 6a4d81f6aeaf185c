// The cases of the suite, grouped in families (one gtest per family): chi-square of every warp
// of core/warp.h and of the microfacet normal samplers, every BSDF of core/bsdf.h over its
// parameter grid at several incident directions, and the extremes grid of every BSDF.
#ifndef TWINRAY_TESTS_BSDF_CASES_H
#define TWINRAY_TESTS_BSDF_CASES_H

#include <functional>
#include <string>
#include <vector>

#include "core/scene_types.h"
#include "core_calls.h"
#include "suite_size.h"
#include "twinray_validation.h"

namespace tr::bsdf_suite {

// A case is a recipe over CoreCalls, so the same case validates either build of core/.
struct StatisticalCase {
  std::string family;
  std::function<twinray::validation::DirectionSampler(CoreCalls&)> directions;
  std::function<twinray::validation::PlanarSampler(CoreCalls&)> planar;
  // A core BSDF, validated at `incident`; built when run (roughplastic's tables are costly).
  std::string bsdf_name;
  std::function<Material()> material;
  std::vector<glm::vec3> incident;
  // Transmissive BSDFs carry 1/eta^2 in their radiance weights: their albedo is tested on
  // energy weights instead.
  bool transmissive = false;
  // The Disney/principled model (Burley 2012) is not energy conserving: its diffuse and sheen
  // lobes are added to the specular lobe without a 1 - F weight, so at grazing angles, where F
  // tends to 1, the albedo exceeds 1 (measured: 1.07 with sheen = 1 and 1.25 with specular = 1,
  // roughness = 0.1 at 85°). The albedo test is therefore not applied to it.
  bool energy_conserving = true;
  // false for Mitsuba's normalmap: its flipping (by wi) and shadowing term (by wo) break
  // Helmholtz reciprocity.
  bool reciprocal = true;
};

struct ExtremesCase {
  std::string family;
  std::string name;
  std::function<Material()> material;
};

const std::vector<StatisticalCase>& statistical_cases();
const std::vector<ExtremesCase>& extremes_cases();

// Statistical tests (p-values) of one case, over all statistical cases, and the Šidák level of
// each test over all cases.
std::size_t statistical_test_count(const StatisticalCase& c);
std::size_t statistical_test_count();
double alpha_per_test();

std::vector<std::string> statistical_families();
std::vector<std::string> extremes_families();

// The options of validate_bsdf at `size`, each statistical test at level `alpha`.
twinray::validation::ValidationOptions validation_options(const SuiteSize& size, double alpha);

// Runs one case with core/ reached through `calls`, each statistical test at level `alpha`.
// `number` is the case's position in its list, from 1: it seeds the case.
twinray::validation::Report run_statistical_case(const StatisticalCase& c, std::size_t number,
                                                 double alpha, const SuiteSize& size,
                                                 CoreCalls& calls);
twinray::validation::Report run_extremes_case(const ExtremesCase& c, std::size_t number,
                                              const SuiteSize& size, CoreCalls& calls);

// Runs every case of a family on the C++ build of core/ and returns its report.
twinray::validation::Report run_statistical_family(const std::string& family);
twinray::validation::Report run_extremes_family(const std::string& family);

}  // namespace tr::bsdf_suite

#endif
