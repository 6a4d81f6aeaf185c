// The closed-form AOVs of tests/cpu/scenes/aov_sphere.xml (one sample per pixel), checked
// against a backend's render: each pixel's camera ray is the core's own (integrator_begin with
// the render's seed), its hit on the sphere is solved in double, and every AOV must match to
// float rounding. Pixels whose ray passes within 5% of the radius of the silhouette are left
// out (there a ray that differs by rounding may hit on one side and miss on the other).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/integrator.h"
#include "cpu_backend/bound_scene.h"
#include "render/render.h"
#include "scenes/load_scene.h"

namespace tr::test {

inline void expect_aov_sphere(const Scene& scene, const RenderResult& r, double tolerance) {
  const glm::dvec3 center(0.2, -0.1, 0.3), reflectance(0.2, 0.4, 0.6);
  const double radius = 1.1;
  ASSERT_EQ(r.aov_count, 8u);
  ASSERT_EQ(r.spp, 1u);
  ScopedSceneBinding binding(scene.buffers);
  int hits = 0, misses = 0;
  for (uint y = 0; y < r.height; ++y)
    for (uint x = 0; x < r.width; ++x) {
      PathState s = integrator_begin(uvec2(x, y), 0u, r.seed);
      const glm::dvec3 o(s.ray.o), d(s.ray.d);
      const glm::dvec3 oc = o - center;
      const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - radius * radius);
      if (std::abs(disc) < 0.05 * radius * radius) continue;
      double expected[8][3] = {};
      const bool hit = disc > 0.0;
      if (hit) {
        const double t = -b - std::sqrt(disc);
        const glm::dvec3 p = o + t * d, n = (p - center) / radius;
        double phi = std::atan2(n.y, n.x);
        if (phi < 0.0) phi += 2.0 * M_PI;
        const double u = phi / (2.0 * M_PI), v = std::acos(n.z) / M_PI;
        if (u < 1e-3 || u > 1.0 - 1e-3) continue;  // the uv seam
        const glm::dvec3 values[8] = {reflectance, {t, 0, 0}, p,         n,
                                      n,           {u, v, 0}, {0, 0, 0}, {1, 0, 0}};
        for (int a = 0; a < 8; ++a)
          for (int c = 0; c < 3; ++c) expected[a][c] = values[a][c];
      }
      (hit ? hits : misses)++;
      const char* names[8] = {"albedo",    "depth", "position",   "geo_normal",
                              "sh_normal", "uv",    "prim_index", "shape_index"};
      for (int a = 0; a < 8; ++a)
        for (int c = 0; c < 3; ++c) {
          const double got = r.aov_mean[3 * ((size_t(y) * r.width + x) * 8 + a) + c];
          EXPECT_NEAR(got, expected[a][c], tolerance * std::max(1.0, std::abs(expected[a][c])))
              << names[a] << "[" << c << "] at pixel (" << x << ", " << y << ")";
        }
    }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
}

}  // namespace tr::test
