#pragma once

#include <memory>
#include <string>

#include "render/render.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace tr {

// Renders with the named backend ("cpu" or "gpu"); throws BackendUnavailable when it cannot.
RenderResult run_backend(const std::string& backend, const Scene& scene,
                         const RenderOptions& options);

// The named backend bound to `scene`, for progressive rendering; throws BackendUnavailable.
std::unique_ptr<Renderer> make_renderer(const std::string& backend, const Scene& scene,
                                        const RenderOptions& options);

}  // namespace tr
