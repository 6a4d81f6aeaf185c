#include "app/run_backend.h"

#include "cpu_backend/render_cpu.h"
#ifdef TWINRAY_HAS_GPU
#include "gpu_backend/render_gpu.h"
#endif

namespace tr {

RenderResult run_backend(const std::string& backend, const Scene& scene,
                         const RenderOptions& options) {
  if (backend == "cpu") return render_cpu(scene, options);
#ifdef TWINRAY_HAS_GPU
  return render_gpu(scene, options);
#else
  throw BackendUnavailable(
      "this twinray was built without the GPU backend (TWINRAY_BUILD_GPU=OFF); use --backend cpu");
#endif
}

}  // namespace tr
