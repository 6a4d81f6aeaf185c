// `path` with the twinray extension min_depth (core/integrator.h): only paths of
// min_depth..max_depth segments count. Scene tests/cpu/scenes/path_length_window.xml: a diffuse
// floor of albedo rho_f = 0.5 under a facing diffuse ceiling of albedo rho_c = 0.8 that also
// emits radiance Le = 1, the camera between them looking at the floor. Between two infinite
// planes every direction leaving one meets the other, and a Lambertian surface under uniform
// radiance L reflects rho L (Lo = rho / pi ∫ L cos dw = rho L). The floor does not emit, so:
//   length 1 (the floor seen directly):                    0
//   length 2 (floor, then the emitting ceiling):           rho_f Le = 0.5
//   length 3 (floor, ceiling, floor: which does not emit): 0
//   length 4 (floor, ceiling, floor, ceiling):             rho_f rho_c rho_f Le = 0.2
// and a window is the sum of its lengths. The squares are 2000 x 2000 at distance 1: a
// cosine-weighted direction leaves them only if cos(theta) < ~1/1000, which has probability
// ~1e-6 at each bounce, so the finite size changes the values by ~1e-6 relative, far below the
// standard errors of the image means (~3e-5). Significance: constant_image_check.h. Checking length
// 3 alone also checks that both MIS techniques of a length are dropped together: a ceiling vertex's
// emitter sample (length 3) must score nothing, and the length-2 value must come out whole.
#include <gtest/gtest.h>

#include <string>

#include "constant_image_check.h"
#include "render_fixture.h"

namespace tr::test {
namespace {

void expect_window(int min_depth, int max_depth, double expected) {
  LoadOptions load;
  load.defines = {{"min_depth", std::to_string(min_depth)},
                  {"max_depth", std::to_string(max_depth)}};
  RenderOptions options;
  options.seed = 1;
  RenderResult r = render_file(test_scene("path_length_window.xml"), options, load);
  expect_constant_image(
      r, expected,
      "path lengths [" + std::to_string(min_depth) + ", " + std::to_string(max_depth) + "]");
}

TEST(PathLengthWindow, EmittersSeenDirectly) { expect_window(1, 1, 0.0); }
TEST(PathLengthWindow, DirectIllumination) { expect_window(2, 2, 0.5); }
TEST(PathLengthWindow, LengthThreeCarriesNothing) { expect_window(3, 3, 0.0); }
TEST(PathLengthWindow, LengthFour) { expect_window(4, 4, 0.5 * 0.8 * 0.5); }
TEST(PathLengthWindow, SumOfLengths) { expect_window(2, 4, 0.5 + 0.5 * 0.8 * 0.5); }

}  // namespace
}  // namespace tr::test
