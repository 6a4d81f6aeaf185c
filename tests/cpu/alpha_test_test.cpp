// twinray's `alphatest` (core/alpha_test.h) on the CPU: a checkerboard-cut plate over a floor
// lit by a directional emitter (tests/cpu/scenes/alpha_test_plate.xml), seen from above (camera
// rays through the holes, shadow rays through the same holes) and from below the plate (shadow
// rays alone), and the cutoff against opacities 0.3 / 0.7.
#include <gtest/gtest.h>

#include <string>

#include "alpha_test_check.h"
#include "render_fixture.h"

namespace tr::test {
namespace {

RenderResult render_plate(const std::string& camera_y, const std::string& c0, const std::string& c1,
                          const std::string& cutoff) {
  LoadOptions load;
  load.defines = {{"camera_y", camera_y}, {"c0", c0}, {"c1", c1}, {"cutoff", cutoff}};
  RenderOptions options;
  options.seed = 7;
  return render_file(test_scene("alpha_test_plate.xml"), options, load);
}

TEST(AlphaTest, CameraAndShadowRaysPassTheHoles) {
  expect_alpha_test_image(render_plate("5", "0", "1", "0.5"), AlphaPattern::Checkerboard,
                          "camera above the plate");
}

TEST(AlphaTest, ShadowRaysAlonePassTheHoles) {
  expect_alpha_test_image(render_plate("0.5", "0", "1", "0.5"), AlphaPattern::Checkerboard,
                          "camera below the plate");
}

TEST(AlphaTest, CutoffDecidesWhereTheSurfaceIs) {
  expect_alpha_test_image(render_plate("5", "0.3", "0.7", "0.5"), AlphaPattern::Checkerboard,
                          "opacities 0.3 / 0.7, cutoff 0.5");
  expect_alpha_test_image(render_plate("5", "0.3", "0.7", "0.2"), AlphaPattern::AllDark,
                          "cutoff 0.2: no hole");
  expect_alpha_test_image(render_plate("0.5", "0.3", "0.7", "0.8"), AlphaPattern::AllLit,
                          "cutoff 0.8: the plate is absent");
}

}  // namespace
}  // namespace tr::test
