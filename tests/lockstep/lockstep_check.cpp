#include "lockstep_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "cpu_backend/render_cpu.h"
#include "gpu_backend/render_gpu.h"
#include "validation/harness/scene_render.h"
#include "validation/image/lockstep.h"

namespace tr {

namespace {

// The rounding control's scene: the camera's origin moved up by one float ulp on each axis.
Scene camera_moved_one_ulp(const Scene& scene) {
  Scene moved = scene;
  for (vec4& row : moved.buffers.globals.camera.to_world)
    row.w = std::nextafter(row.w, std::numeric_limits<float>::infinity());
  return moved;
}

}  // namespace

void expect_lockstep(const std::string& label, const Scene& scene, uint32_t spp, uint32_t seed,
                     const LockstepOptions& lockstep) {
  RenderOptions options;
  options.spp = spp;
  options.seed = seed;
  RenderResult cpu = render_cpu(scene, options);
  RenderResult gpu = render_gpu(scene, options);
  RgbImage control = mean_image(render_cpu(camera_moved_one_ulp(scene), options));
  LockstepResult r = lockstep_compare(mean_image(gpu), mean_image(cpu), lockstep, &control);
  std::printf(
      "%s, %u spp: %.6f of pixels within tolerance, %zu systematic, %zu clustered windows "
      "(%zu rounding-sensitive pixels)\n",
      label.c_str(), spp, r.fraction_within, r.systematic_cells, r.clustered_windows,
      r.rounding_sensitive);
  for (const LockstepPixel& p : r.worst)
    if (p.excess > 1.0)
      std::printf("  (%d, %d) gpu %.7g %.7g %.7g cpu %.7g %.7g %.7g excess %.3g\n", p.x, p.y,
                  p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2], p.excess);
  EXPECT_TRUE(r.passed) << label << ", " << spp << " spp: " << r.fraction_within
                        << " within tolerance, " << r.systematic_cells << " systematic, "
                        << r.clustered_windows << " clustered windows";
}

}  // namespace tr
