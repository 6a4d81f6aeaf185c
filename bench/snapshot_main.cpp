// bench_snapshot SCENE.xml OUT.twscene [-D NAME=VALUE]...: see scene_snapshot.h.
#include <cstdio>
#include <string>

#include "bench/scene_snapshot.h"
#include "scenes/load_scene.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_snapshot SCENE.xml OUT.twscene [-D NAME=VALUE]...\n");
    return 2;
  }
  tr::LoadOptions load;
  for (int i = 3; i + 1 < argc; i += 2) {
    std::string kv = argv[i + 1];
    size_t eq = kv.find('=');
    load.defines[kv.substr(0, eq)] = eq == std::string::npos ? "" : kv.substr(eq + 1);
  }
  try {
    tr::write_scene_snapshot(argv[2], tr::load_scene(argv[1], load));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_snapshot: %s\n", e.what());
    return 1;
  }
  return 0;
}
