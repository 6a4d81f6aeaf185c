// The reference backend: Embree 3 for rays, TBB over image tiles, core/integrator.h for
// everything else.
#pragma once

#include "render/render.h"
#include "scenes/scene.h"

namespace tr {

RenderResult render_cpu(const Scene& scene, const RenderOptions& options);

}  // namespace tr
