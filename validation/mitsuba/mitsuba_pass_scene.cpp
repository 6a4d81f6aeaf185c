// Writes the scene of one pass of a Mitsuba 3 reference (validation/mitsuba/pass_scene.h).
// usage: mitsuba_pass_scene SCENE.xml OUT.xml --seed N --spp N [-D name=value]...
// Exit status: 0 written, 2 bad arguments or a scene it cannot derive a pass from.
#include <cstdio>
#include <exception>
#include <string>

#include "io/temp_file.h"
#include "validation/mitsuba/pass_scene.h"

namespace {

std::uint32_t parse_count(const char* flag, const std::string& value) {
  size_t used = 0;
  unsigned long v = std::stoul(value, &used);
  if (used != value.size() || value[0] == '-' || v > 0xffffffffUL)
    throw std::invalid_argument(std::string(flag) + " expects a non-negative integer");
  return std::uint32_t(v);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage =
      "usage: mitsuba_pass_scene SCENE.xml OUT.xml --seed N --spp N [-D name=value]...\n";
  try {
    std::string scene, out;
    tr::PassSettings settings;
    bool have_seed = false, have_spp = false;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if ((arg == "--seed" || arg == "--spp" || arg == "-D") && i + 1 >= argc)
        throw std::invalid_argument(arg + " needs a value");
      if (arg == "--seed") {
        settings.seed = parse_count("--seed", argv[++i]);
        have_seed = true;
      } else if (arg == "--spp") {
        settings.spp = parse_count("--spp", argv[++i]);
        have_spp = settings.spp > 0;
      } else if (arg == "-D") {
        const std::string define = argv[++i];
        const size_t eq = define.find('=');
        if (eq == std::string::npos || eq == 0)
          throw std::invalid_argument("-D expects name=value, got '" + define + "'");
        settings.defines[define.substr(0, eq)] = define.substr(eq + 1);
      } else if (scene.empty()) {
        scene = arg;
      } else if (out.empty()) {
        out = arg;
      } else {
        throw std::invalid_argument("unexpected argument '" + arg + "'");
      }
    }
    if (scene.empty() || out.empty() || !have_seed || !have_spp)
      throw std::invalid_argument("SCENE.xml, OUT.xml, --seed and a positive --spp are required");
    tr::write_text_file(out, tr::pass_scene_xml(scene, settings));
    return 0;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "mitsuba_pass_scene: %s\n%s", e.what(), usage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mitsuba_pass_scene: %s\n", e.what());
    return 2;
  }
}
