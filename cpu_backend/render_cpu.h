// The reference backend: Embree 3 for rays, TBB over image tiles, core/integrator.h for
// everything else.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>

#include "render/render.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace tr {

// Knobs of the CPU backend beyond RenderOptions, for tests and measurements.
struct CpuTuning {
  // The kernel to render with (an index of cpu_backend/cpu_kernels.h's kCpuKernels, which must
  // cover the scene's features); by default the first that covers them.
  std::optional<std::size_t> kernel;
};

// Binds `scene` for the CPU (one bound scene per process at a time) and builds its Embree
// scene; the build time counts in the first render's stats.seconds. The device names the
// kernel that renders it. Throws std::invalid_argument for a tuning.kernel that does not cover
// the scene.
std::unique_ptr<Renderer> make_cpu_renderer(const Scene& scene, const RenderOptions& options,
                                            const CpuTuning& tuning = CpuTuning());

RenderResult render_cpu(const Scene& scene, const RenderOptions& options,
                        const CpuTuning& tuning = CpuTuning());

}  // namespace tr
