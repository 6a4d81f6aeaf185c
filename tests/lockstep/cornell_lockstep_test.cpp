// CPU <-> GPU lockstep on the default scene (issue 4): the Cornell box at 1 and 64 spp, same
// seed on both backends; at least 99% of the pixels agree within 1e-4 relative (+1e-6
// absolute) and no 4x4 block shows a systematic difference (validation/image/lockstep.h).
// The worst pixels are printed with their coordinates.
#include <gtest/gtest.h>

#include <cstdio>

#include "cpu_backend/render_cpu.h"
#include "gpu_backend/render_gpu.h"
#include "scenes/load_scene.h"
#include "validation/image/lockstep.h"

namespace tr {
namespace {

RgbImage mean_image(const RenderResult& r) {
  RgbImage img;
  img.width = int(r.width);
  img.height = int(r.height);
  img.rgb = r.mean;
  return img;
}

void expect_cornell_lockstep(uint32_t spp, uint32_t seed) {
  LoadOptions load;
  load.defines["width"] = "96";
  load.defines["height"] = "96";
  Scene scene = load_scene(TWINRAY_CORNELL_BOX, load);
  RenderOptions options;
  options.spp = spp;
  options.seed = seed;
  RenderResult cpu = render_cpu(scene, options);
  RenderResult gpu = render_gpu(scene, options);
  LockstepOptions lo;
  lo.required_fraction = 0.99;
  LockstepResult r = lockstep_compare(mean_image(gpu), mean_image(cpu), lo);
  std::printf("Cornell box %u spp: %.6f of pixels within tolerance, %zu systematic cells\n", spp,
              r.fraction_within, r.systematic_cells);
  for (const LockstepPixel& p : r.worst)
    std::printf("  (%d, %d) gpu %.7g %.7g %.7g cpu %.7g %.7g %.7g excess %.3g\n", p.x, p.y, p.a[0],
                p.a[1], p.a[2], p.b[0], p.b[1], p.b[2], p.excess);
  EXPECT_TRUE(r.passed) << r.fraction_within << " within tolerance, " << r.systematic_cells
                        << " systematic cells";
}

TEST(CornellLockstep, OneSamplePerPixel) { expect_cornell_lockstep(1, 21); }
TEST(CornellLockstep, SixtyFourSamplesPerPixel) { expect_cornell_lockstep(64, 22); }

}  // namespace
}  // namespace tr
