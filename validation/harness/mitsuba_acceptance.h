// The acceptance rule of shared/mitsuba-tests/README.md applied to one render: its two tests
// (per pixel, per 4x4 block; validation/image/variance_tests.h) decide; the gain test of
// variance_tests.h is computed alongside for information.
#pragma once

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

// One line: verdict, failing counts and the smallest p-value (and where), or for a gain test
// the estimated gain per XYZ channel.
std::string describe_test(const HypothesisTestResult& t);

}  // namespace tr
