// The CPU renderer's per-pixel routine as each of its kernels (cpu_backend/cpu_kernels.h) runs
// it, and the film and counters it writes to.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>

#include "cpu_backend/embree_scene.h"
#include "render/film_state.h"

namespace tr {

struct ThreadCounts {
  std::uint64_t rays = 0;
  std::uint64_t rejected = 0;
};

// One render() call's film: accumulator i of `pixels` or `aovs` gets its samples, and the
// negative groups are allocated when the first negative sample arrives (a filter with negative
// lobes, core/film.h), by one thread while the others wait (std::call_once), so that a film
// without negative samples holds none. Threads adding positive samples meanwhile do not read
// the negative groups: each counts its pixel's negative samples itself (negatives_before), and
// a pixel's AOV accumulators get the pixel's samples with the same signs.
struct FilmTarget {
  FilmMomentArray& pixels;
  FilmMomentArray& aovs;
  std::uint32_t pass_size;
  bool had_negative;  // pixels.has_negative() before the render() call's threads started
  std::once_flag negative_once;

  // The negative samples that pixel `index` held when the render() call began.
  double negatives_before(std::size_t index) {
    return had_negative ? pixels.negative(index).n : 0.0;
  }

  // Adds sample L to accumulator i, which holds `positives` positive samples before it.
  void add(FilmMomentArray& a, std::size_t i, double positives, bool negative, const glm::vec3& L) {
    if (negative) {
      std::call_once(negative_once, [this] {
        pixels.keep_negative();
        aovs.keep_negative();
      });
      add_sample(a.negative(i), L);
    } else {
      SampleGroup g = a.positive_counted(i, positives);
      add_sample(g, L);
      a.set_positive(i, g);
    }
    if (pass_size > 0u) add_to_pass(a.passes(i), negative ? -1.0 : 1.0, 1.0, L);
  }
};

// Samples [first, first + count) of pixel `pixel` (film index `index`), in order, added to its
// moments in double (render/film_moments.h); sample i ends a pass when (i + 1) % pass_size == 0.
using PixelKernelFn = void(const EmbreeScene& accel, glm::uvec2 pixel, std::size_t index,
                           std::uint32_t first, std::uint32_t count, std::uint32_t seed,
                           FilmTarget& film, ThreadCounts& counts);
using PixelKernel = PixelKernelFn*;

// pixel_kernel.cpp as compiled for kernel K of cpu_backend/cpu_kernels.h is pixel_kernel_K.
PixelKernelFn pixel_kernel_0, pixel_kernel_1, pixel_kernel_2, pixel_kernel_3, pixel_kernel_4,
    pixel_kernel_5;

}  // namespace tr
