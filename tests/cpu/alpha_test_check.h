// The expected image of tests/cpu/scenes/alpha_test_plate.xml, shared by the CPU and GPU tests.
// Every estimate in that scene is deterministic (a directional emitter, a black plate, box
// filter, whole pixels per check), so each pixel must be 0 or 0.5 (rho E / pi) to float
// rounding: no statistics.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/render.h"

namespace tr::test {

enum class AlphaPattern { Checkerboard, AllDark, AllLit };

inline void expect_alpha_test_image(const RenderResult& r, AlphaPattern pattern,
                                    const std::string& what) {
  ASSERT_EQ(r.width, 16u);
  ASSERT_EQ(r.height, 16u);
  const double lit = 0.5, tolerance = 1e-5;
  int lit_pixels = 0, wrong = 0;
  bool first_block_lit = false;
  for (uint32_t y = 0; y < r.height; ++y)
    for (uint32_t x = 0; x < r.width; ++x) {
      const double* p = &r.mean[3 * (size_t(y) * r.width + x)];
      const bool is_lit = std::abs(p[0] - lit) <= tolerance;
      if (x == 0 && y == 0) first_block_lit = is_lit;
      bool expect_lit = pattern == AlphaPattern::AllLit;
      if (pattern == AlphaPattern::Checkerboard)
        expect_lit = ((((x / 2) + (y / 2)) % 2) == 0) == first_block_lit;
      const double expected = expect_lit ? lit : 0.0;
      for (int c = 0; c < 3; ++c)
        if (std::abs(p[c] - expected) > tolerance) {
          if (++wrong <= 5)
            ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") channel " << c << " is "
                          << p[c] << ", expected " << expected;
        }
      lit_pixels += is_lit;
    }
  EXPECT_EQ(wrong, 0) << what << ": " << wrong << " wrong pixel channels";
  const int expected_lit = pattern == AlphaPattern::Checkerboard ? 128
                           : pattern == AlphaPattern::AllLit     ? 256
                                                                 : 0;
  EXPECT_EQ(lit_pixels, expected_lit) << what;
}

}  // namespace tr::test
