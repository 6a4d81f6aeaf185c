// The closed-form guide buffers (albedo, sh_normal, depth) of tests/cpu/scenes/guide_sphere.xml
// at one sample per pixel, as tests/cpu/aov_sphere_check.h checks all AOVs of aov_sphere.xml:
// each pixel's camera ray is the core's own (integrator_begin with the render's seed), its hit
// on the sphere is solved in double (|o + t d - c| = r, smaller root), and the values must
// match to float rounding. Pixels whose ray passes within 5% of the radius of the silhouette
// are left out (there a ray that differs by rounding may hit on one side and miss on the other).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "core/integrator.h"
#include "cpu_backend/bound_scene.h"
#include "render/render.h"
#include "scenes/load_scene.h"

namespace tr::test {

// The guides in this order; channel c of guide g.
inline const char* const kGuideNames[3] = {"albedo", "sh_normal", "depth"};
inline const char* const kGuideChannels[3][3] = {{"albedo.R", "albedo.G", "albedo.B"},
                                                 {"sh_normal.X", "sh_normal.Y", "sh_normal.Z"},
                                                 {"depth.T"}};
inline const int kGuideChannelCount[3] = {3, 3, 1};

// `value(x, y, g, c)`: the render's value of channel c of guide g at pixel (x, y).
inline void expect_guide_sphere(const Scene& scene, std::uint32_t seed,
                                const std::function<double(uint, uint, int, int)>& value,
                                double tolerance) {
  const glm::dvec3 center(0.2, -0.1, 0.3), reflectance(0.2, 0.4, 0.6);
  const double radius = 1.1;
  const Camera& camera = scene.buffers.globals.camera;
  ScopedSceneBinding binding(scene.buffers);
  int hits = 0, misses = 0;
  for (uint y = 0; y < camera.height; ++y)
    for (uint x = 0; x < camera.width; ++x) {
      PathState s = integrator_begin(uvec2(x, y), 0u, seed);
      const glm::dvec3 o(s.ray.o), d(s.ray.d);
      const glm::dvec3 oc = o - center;
      const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - radius * radius);
      if (std::abs(disc) < 0.05 * radius * radius) continue;
      glm::dvec3 expected[3] = {};  // zero where the ray misses (Mitsuba's invalid interaction)
      if (disc > 0.0) {
        const double t = -b - std::sqrt(disc);
        expected[0] = reflectance;
        expected[1] = (o + t * d - center) / radius;
        expected[2] = glm::dvec3(t, 0.0, 0.0);
        hits++;
      } else {
        misses++;
      }
      for (int g = 0; g < 3; ++g)
        for (int c = 0; c < kGuideChannelCount[g]; ++c)
          EXPECT_NEAR(value(x, y, g, c), expected[g][c],
                      tolerance * std::max(1.0, std::abs(expected[g][c])))
              << kGuideChannels[g][c] << " at pixel (" << x << ", " << y << ")";
    }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
}

// The same for a 1-spp render of the scene (aov_mean: 3 values per guide per pixel).
inline void expect_guide_sphere_render(const Scene& scene, const RenderResult& r) {
  ASSERT_EQ(r.aov_count, 3u);
  ASSERT_EQ(r.spp, 1u);
  expect_guide_sphere(
      scene, r.seed,
      [&](uint x, uint y, int g, int c) {
        return r.aov_mean[3 * ((size_t(y) * r.width + x) * 3 + g) + c];
      },
      1e-5);
}

}  // namespace tr::test
