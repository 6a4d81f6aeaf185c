// core/special_functions.h against the C++ library.
#include "core/special_functions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tr {
namespace {

TEST(SpecialFunctions, ErfinvInvertsErf) {
  for (float x = -0.999f; x < 1.0f; x += 0.0123f)
    EXPECT_NEAR(erf_approx(erfinv_approx(x)), x, 2e-6f) << x;
}

TEST(PortableTrig, MatchesTheLibraryWithinFourUlpScaledError) {
  for (int i = -2000; i <= 2000; ++i) {
    float x = i * 0.0004995f;
    EXPECT_NEAR(acos_portable(x), std::acos(double(x)), 4e-7 + 2e-7 * std::acos(double(x))) << x;
    for (int j = 0; j < 8; ++j) {
      float y = std::sin(j * 0.785398f + 0.1f), z = std::cos(j * 0.785398f + 0.1f) * (i * 0.001f);
      EXPECT_NEAR(atan2_portable(y, z), std::atan2(double(y), double(z)), 5e-7) << y << " " << z;
    }
  }
}

}  // namespace
}  // namespace tr
