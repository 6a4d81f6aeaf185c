// bench_gpu_replay SNAPSHOT.twscene [--spp N] [--frames K] [--device D] [--pfm OUT.pfm]:
// renders a scene snapshot K times on the GPU backend and prints, per render, time,
// Msamples/s, Mrays/s and frames/s (1 spp = one frame); --pfm writes the last render's mean
// (Portable Float Map, bottom row first) to compare with a CPU render. Depends only on
// Vulkan, so it runs where the loader's libraries are absent.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "bench/scene_snapshot.h"
#include "gpu_backend/render_gpu.h"

namespace {

void write_pfm(const std::string& path, const tr::RenderResult& r) {
  std::ofstream out(path, std::ios::binary);
  out << "PF\n" << r.width << " " << r.height << "\n-1.0\n";
  for (uint32_t y = r.height; y-- > 0;)
    for (uint32_t x = 0; x < r.width * 3; ++x) {
      float v = float(r.mean[size_t(y) * r.width * 3 + x]);
      out.write(reinterpret_cast<const char*>(&v), sizeof v);
    }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_gpu_replay SNAPSHOT.twscene [--spp N] [--frames K] [--device D]\n");
    return 2;
  }
  tr::RenderOptions options;
  int frames = 3;
  std::string pfm;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--spp")) options.spp = unsigned(std::stoul(argv[i + 1]));
    if (!std::strcmp(argv[i], "--frames")) frames = std::stoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--device")) options.device = argv[i + 1];
    if (!std::strcmp(argv[i], "--pfm")) pfm = argv[i + 1];
  }
  try {
    tr::Scene scene = tr::read_scene_snapshot(argv[1]);
    for (int f = 0; f < frames; ++f) {
      tr::RenderResult r = tr::render_gpu(scene, options);
      if (!pfm.empty() && f + 1 == frames) write_pfm(pfm, r);
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
