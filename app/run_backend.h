#pragma once

#include <string>

#include "render/render.h"
#include "scenes/scene.h"

namespace tr {

// Renders with the named backend ("cpu" or "gpu"); throws BackendUnavailable when it cannot.
RenderResult run_backend(const std::string& backend, const Scene& scene,
                         const RenderOptions& options);

}  // namespace tr
