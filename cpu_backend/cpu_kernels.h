// The CPU renderer's kernels: cpu_backend/pixel_kernel.cpp compiled once for each feature set of
// kCpuKernels (its index is the unit's TR_CPU_KERNEL), with the core's TR_HAS_* guards
// (core/prelude.h) set to that set, as the GPU backend specializes its pipeline to a scene
// (shaders/features.glsl). A scene renders with the first kernel whose features cover its own
// (scenes/scene_features.h); the last has every feature. One source, so every kernel that
// covers a scene computes the same values bit for bit: the guards only drop the code of features
// the scene lacks, and GCC inlines more of what is left into one routine (BENCHMARKS.md, "CPU
// kernels").
#pragma once

#include <cstddef>
#include <cstdint>

#include "cpu_backend/pixel_kernel.h"
#include "scenes/scene_features.h"

namespace tr {

// Mitsuba's BSDFs but the principled ones and the wrappers around other materials.
constexpr std::uint32_t kBasicBsdfs = (1u << BSDF_DIFFUSE) | (1u << BSDF_CONDUCTOR) |
                                      (1u << BSDF_ROUGHCONDUCTOR) | (1u << BSDF_DIELECTRIC) |
                                      (1u << BSDF_ROUGHDIELECTRIC) | (1u << BSDF_THINDIELECTRIC) |
                                      (1u << BSDF_PLASTIC) | (1u << BSDF_ROUGHPLASTIC);

// `bsdfs` and, if `lean`, only the `path` and `direct` integrators, the `independent` sampler,
// uniform or power emitter selection, no AOVs and no textures; every shape, emitter and material
// flag.
constexpr SceneFeatures kernel_features(std::uint32_t bsdfs, bool lean) {
  SceneFeatures f{~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u};
  f.bsdf_types = bsdfs;
  if (lean) {
    f.texture_types = 0u;
    f.textured_slots = 0u;
    f.aov_types = 0u;
    f.integrator_types = (1u << INTEGRATOR_PATH) | (1u << INTEGRATOR_DIRECT);
    f.sampler_types = 1u << SAMPLER_INDEPENDENT;
    f.emitter_selections = (1u << EMITTER_SELECTION_UNIFORM) | (1u << EMITTER_SELECTION_POWER);
  }
  return f;
}

struct CpuKernelFeatures {
  const char* name;
  SceneFeatures features;
};

constexpr CpuKernelFeatures kCpuKernels[] = {
    {"diffuse, lean", kernel_features(1u << BSDF_DIFFUSE, true)},
    {"basic BSDFs, lean", kernel_features(kBasicBsdfs, true)},
    {"lean", kernel_features(~0u, true)},
    {"diffuse", kernel_features(1u << BSDF_DIFFUSE, false)},
    {"basic BSDFs", kernel_features(kBasicBsdfs, false)},
    {"all features", kernel_features(~0u, false)},
};
constexpr std::size_t kCpuKernelCount = sizeof(kCpuKernels) / sizeof(kCpuKernels[0]);

// The kernel that renders a scene of these features: the first of kCpuKernels that covers them.
std::size_t cpu_kernel_index(const SceneFeatures& scene);

// Kernel `index`'s entry.
PixelKernel cpu_kernel_entry(std::size_t index);

}  // namespace tr
