#include "cpu_backend/cpu_kernels.h"

#include <stdexcept>

namespace tr {

std::size_t cpu_kernel_index(const SceneFeatures& scene) {
  for (std::size_t i = 0; i < kCpuKernelCount; ++i)
    if (features_cover(kCpuKernels[i].features, scene)) return i;
  throw std::logic_error("cpu_kernels: the last kernel does not cover every feature");
}

PixelKernel cpu_kernel_entry(std::size_t index) {
  static constexpr PixelKernel entries[] = {pixel_kernel_0, pixel_kernel_1, pixel_kernel_2,
                                            pixel_kernel_3, pixel_kernel_4, pixel_kernel_5};
  static_assert(sizeof(entries) / sizeof(entries[0]) == kCpuKernelCount,
                "one pixel_kernel_K (pixel_kernel.h, cpu_backend/CMakeLists.txt) per kCpuKernels");
  return entries[index];
}

}  // namespace tr
