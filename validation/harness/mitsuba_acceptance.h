// The acceptance rule of shared/mitsuba-tests/README.md applied to one render: its two tests
// (per pixel, per 4x4 block; validation/image/variance_tests.h) decide; the gain test of
// variance_tests.h is computed alongside for information.
#pragma once

#include <cstdint>
#include <string>

#include "validation/image/rgb_image.h"
#include "validation/image/variance_tests.h"

namespace tr {

struct AcceptanceResult {
  HypothesisTestResult pixel_z, block_z, gain_z;
  bool passed = false;  // pixel_z and block_z
};

// README defaults: family alpha 0.01, pass fraction 0.9975, XYZ variance clamp 1e-4, 4x4 blocks.
AcceptanceResult mitsuba_acceptance(const RgbImage& img, double spp, const RgbImage& ref,
                                    const RgbImage& ref_variance, double ref_spp);

// shared/mitsuba-tests/README.md: a right renderer fails about 1% of runs by chance, and "a
// failure that repeats across seeds is a bug". A render that fails the rule is judged again by a
// confirmation render, an independent seed (confirmation_seed) at kConfirmationSppFactor times
// the samples, where a bias stands twice as many standard errors out; the scene fails only when
// that render fails too. A right renderer then fails a scene about once in 10^4 runs (0.01 x
// 0.01, more where the shared reference's own noise decides both) rather than once in 100, so that
// a suite of some 60 scenes does not fail half the changes of its random numbers; a bias the rule
// catches at the first render's spp is caught again, more surely, at four times it.
constexpr std::uint32_t kConfirmationSppFactor = 4;
std::uint32_t confirmation_seed(std::uint32_t seed);

// One line: verdict, failing counts and the smallest p-value (and where), or for a gain test
// the estimated gain per XYZ channel.
std::string describe_test(const HypothesisTestResult& t);

}  // namespace tr
