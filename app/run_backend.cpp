#include "app/run_backend.h"

#include "cpu_backend/render_cpu.h"
#ifdef TWINRAY_HAS_GPU
#include "gpu_backend/render_gpu.h"
#endif

namespace tr {
namespace {

#ifndef TWINRAY_HAS_GPU
[[noreturn]] void no_gpu() {
  throw BackendUnavailable(
      "this twinray was built without the GPU backend (TWINRAY_BUILD_GPU=OFF); use --backend cpu");
}
#endif

}  // namespace

RenderResult run_backend(const std::string& backend, const Scene& scene,
                         const RenderOptions& options) {
  if (backend == "cpu") return render_cpu(scene, options);
#ifdef TWINRAY_HAS_GPU
  return render_gpu(scene, options);
#else
  no_gpu();
#endif
}

std::unique_ptr<Renderer> make_renderer(const std::string& backend, const Scene& scene,
                                        const RenderOptions& options) {
  if (backend == "cpu") return make_cpu_renderer(scene, options);
#ifdef TWINRAY_HAS_GPU
  return make_gpu_renderer(scene, options);
#else
  no_gpu();
#endif
}

}  // namespace tr
