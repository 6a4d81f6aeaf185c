// bench_gpu_replay SNAPSHOT.twscene [--spp N] [--frames K] [--device D]: renders a scene
// snapshot K times on the GPU backend and prints, per render, time, Msamples/s, Mrays/s and
// frames/s (1 spp = one frame). Depends only on Vulkan, so it runs where the loader's
// libraries are absent.
#include <cstdio>
#include <cstring>
#include <string>

#include "bench/scene_snapshot.h"
#include "gpu_backend/render_gpu.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_gpu_replay SNAPSHOT.twscene [--spp N] [--frames K] [--device D]\n");
    return 2;
  }
  tr::RenderOptions options;
  int frames = 3;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--spp")) options.spp = unsigned(std::stoul(argv[i + 1]));
    if (!std::strcmp(argv[i], "--frames")) frames = std::stoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--device")) options.device = argv[i + 1];
  }
  try {
    tr::Scene scene = tr::read_scene_snapshot(argv[1]);
    for (int f = 0; f < frames; ++f) {
      tr::RenderResult r = tr::render_gpu(scene, options);
      const tr::RenderStats& s = r.stats;
      std::printf("%s: %ux%u %u spp %.4f s  %.1f Msamples/s  %.1f Mrays/s  %.1f spp-frames/s  rejected %llu\n",
                  r.device.c_str(), r.width, r.height, r.spp, s.seconds, s.samples / s.seconds * 1e-6,
                  s.rays / s.seconds * 1e-6, r.spp / s.seconds, static_cast<unsigned long long>(s.rejected_nonfinite));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_gpu_replay: %s\n", e.what());
    return 1;
  }
  return 0;
}
