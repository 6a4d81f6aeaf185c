// The reference backend: Embree 3 for rays, TBB over image tiles, core/integrator.h for
// everything else.
#pragma once

#include <memory>

#include "render/render.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace tr {

// Binds `scene` for the CPU (one bound scene per process at a time) and builds its Embree
// scene; the build time counts in the first render's stats.seconds.
std::unique_ptr<Renderer> make_cpu_renderer(const Scene& scene, const RenderOptions& options);

RenderResult render_cpu(const Scene& scene, const RenderOptions& options);

}  // namespace tr
