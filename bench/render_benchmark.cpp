// Google Benchmark of whole renders: samples/s and rays/s of a backend on a scene.
//   bench_render --scene=FILE [--spp=N] [--backend=cpu|gpu] [-D NAME=VALUE]... [benchmark flags]
// Each iteration renders the full image; counters report Msamples/s and Mrays/s of the render
// itself (scene loading and acceleration-structure builds are outside the timed region's
// counters but inside the iteration time).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

#include "app/run_backend.h"
#include "scenes/load_scene.h"

namespace {

struct Config {
  std::string scene;
  std::string backend = "cpu";
  unsigned spp = 0;
  tr::LoadOptions load;
};

Config g_config;

void BM_Render(benchmark::State& state) {
  tr::Scene scene = tr::load_scene(g_config.scene, g_config.load);
  tr::RenderOptions options;
  options.spp = g_config.spp;
  double samples = 0.0, rays = 0.0, seconds = 0.0;
  for (auto _ : state) {
    tr::RenderResult r = tr::run_backend(g_config.backend, scene, options);
    samples += double(r.stats.samples);
    rays += double(r.stats.rays);
    seconds += r.stats.seconds;
    state.SetIterationTime(r.stats.seconds);
  }
  state.counters["Msamples/s"] = samples / seconds * 1e-6;
  state.counters["Mrays/s"] = rays / seconds * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a.rfind("--scene=", 0) == 0) {
      g_config.scene = a.substr(8);
    } else if (a.rfind("--spp=", 0) == 0) {
      g_config.spp = unsigned(std::stoul(a.substr(6)));
    } else if (a.rfind("--backend=", 0) == 0) {
      g_config.backend = a.substr(10);
    } else if (a == "-D" && i + 1 < argc) {
      std::string kv = argv[++i];
      size_t eq = kv.find('=');
      g_config.load.defines[kv.substr(0, eq)] = eq == std::string::npos ? "" : kv.substr(eq + 1);
    } else {
      rest.push_back(argv[i]);
    }
  }
  if (g_config.scene.empty()) {
    std::fprintf(stderr, "bench_render: --scene=FILE is required\n");
    return 2;
  }
  benchmark::RegisterBenchmark("render", BM_Render)
      ->UseManualTime()
      ->Unit(benchmark::kSecond)
      ->Iterations(3);
  int rest_argc = int(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
