// Traversal and intersection: closest hits of primary rays (tests/gpu/hit_probe.rgen) against
// an analytic double-precision reference, through both BLAS kinds, two TLAS instances and
// the geometry -> shape table, with the validation layer on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "core/camera.h"
#include "gpu_backend/render_gpu.h"
#include "spirv/probe_raygen.h"
#include "test_scene.h"

namespace tr {
namespace {

struct Expected {
  int shape = -1;
  double t = 0.0;
  int primitive = 0;
  bool ambiguous = false;  // too close to a silhouette or the quad's diagonal to decide
};

Expected reference_hit(const Ray& r) {
  const double ox = r.o.x, oy = r.o.y, oz = r.o.z, dx = r.d.x, dy = r.d.y, dz = r.d.z;
  const double margin = 1e-3;
  Expected e;
  e.t = INFINITY;
  // Unit sphere at (0, 0, 5).
  double b = dx * ox + dy * oy + dz * (oz - 5.0);
  double c = ox * ox + oy * oy + (oz - 5.0) * (oz - 5.0) - 1.0;
  double disc = b * b - c;
  if (std::abs(disc) < margin) e.ambiguous = true;
  if (disc > 0.0) {
    e.shape = 0;
    e.t = -b - std::sqrt(disc);
  }
  // Disk of radius 0.5 centred at (1.5, 0, 4.5), facing z.
  double td = (4.5 - oz) / dz;
  double rx = ox + td * dx - 1.5, ry = oy + td * dy;
  double rd = std::sqrt(rx * rx + ry * ry);
  if (std::abs(rd - 0.5) < margin) e.ambiguous = true;
  if (rd < 0.5 && td < e.t) {
    e.shape = 2;
    e.t = td;
  }
  if (e.shape < 0) {
    // Quad at z = 8; triangle 0 is (-20,-20), (20,20), (20,-20): below the diagonal y = x.
    double tq = (8.0 - oz) / dz;
    double qx = ox + tq * dx, qy = oy + tq * dy;
    if (std::abs(qx - qy) < margin) e.ambiguous = true;
    e.shape = 1;
    e.t = tq;
    e.primitive = qy < qx ? 0 : 1;
  }
  return e;
}

TEST(GpuHitProbe, ClosestHitsMatchAnalyticReference) {
  const uint width = 64, height = 48;
  Scene scene = test::probe_scene(width, height);
  RenderOptions options;
  options.spp = 1;
  RenderResult result =
      render_with_raygen(scene, options, one_raygen(spirv_hit_probe, sizeof(spirv_hit_probe)));
  ASSERT_EQ(result.width, width);
  ASSERT_EQ(result.mean.size(), size_t(3) * width * height);

  int seen[4] = {0, 0, 0, 0};  // sphere, quad triangle 0, quad triangle 1, disk
  int checked = 0;
  const Camera& camera = scene.buffers.globals.camera;
  ASSERT_EQ(camera.rfilter, RFILTER_BOX);  // the probe's ray of u = 0.5: through pixel centres
  for (uint y = 0; y < height; ++y)
    for (uint x = 0; x < width; ++x) {
      vec2 film = camera.crop_offset + vec2(x, y) + vec2(0.5f);
      Expected e = reference_hit(camera_ray(camera, film, vec2(0.5f)));
      if (e.ambiguous) continue;
      const double* got = &result.mean[3 * (size_t(y) * width + x)];
      ASSERT_EQ(int(got[0]), e.shape) << "pixel (" << x << ", " << y << ")";
      EXPECT_NEAR(got[1], e.t, 1e-5 * e.t) << "pixel (" << x << ", " << y << ")";
      if (e.shape == 1) {
        EXPECT_EQ(int(got[2]), e.primitive) << "pixel (" << x << ", " << y << ")";
      }
      seen[e.shape == 0 ? 0 : e.shape == 2 ? 3 : 1 + e.primitive]++;
      ++checked;
    }
  EXPECT_GT(checked, int(width * height * 9 / 10));
  for (int k = 0; k < 4; ++k) EXPECT_GT(seen[k], 10) << "case " << k;
}

}  // namespace
}  // namespace tr

namespace tr {
namespace {

// More samples than one dispatch may take (256) force several overlapped dispatches; the
// probe writes the same value for every sample, so the merge must reproduce it exactly.
TEST(GpuHitProbe, OverlappedBatchesMergeExactly) {
  const uint width = 16, height = 12, spp = 300;
  Scene scene = test::probe_scene(width, height);
  RenderOptions options;
  options.spp = 1;
  RenderResult one =
      render_with_raygen(scene, options, one_raygen(spirv_hit_probe, sizeof(spirv_hit_probe)));
  options.spp = spp;
  uint64_t progress_calls = 0;
  options.progress = [&](uint64_t, uint64_t) { ++progress_calls; };
  RenderResult many =
      render_with_raygen(scene, options, one_raygen(spirv_hit_probe, sizeof(spirv_hit_probe)));
  EXPECT_GE(progress_calls, 2u);
  EXPECT_EQ(many.stats.rays, uint64_t(spp) * width * height);
  ASSERT_EQ(one.mean.size(), many.mean.size());
  for (size_t i = 0; i < one.mean.size(); ++i) {
    ASSERT_EQ(one.mean[i], many.mean[i]) << i;
    ASSERT_EQ(many.variance[i], 0.0) << i;
  }
}

}  // namespace
}  // namespace tr
