#include "app/conformance_command.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "app/run_backend.h"
#include "validation/harness/conformance.h"

namespace tr {
namespace {

const char* kUsage =
    "usage: twinray conformance FOLDER [--spp N] [-a PATH]... [--backend cpu|gpu]\n"
    "                           [--threads N] [--previews DIR]\n"
    "  Loads every *.xml scene directly inside FOLDER (as Mitsuba's documentation script does:\n"
    "  -D spp=N where a scene uses $spp) and renders it at N samples per pixel (default 1).\n"
    "  Prints one line a scene: rendered, out-of-scope (a plugin outside twinray's scope,\n"
    "  named) or FAILED (the error), then the counts. Exit status 1 when any scene FAILED.\n"
    "  -a PATH         add a search path for the files the scenes name\n"
    "  --previews DIR  write DIR/<scene>.png (sRGB) for every rendered scene\n";

struct ConformanceArgs {
  std::string folder;
  ConformanceOptions options;
};

ConformanceArgs parse(int argc, char** argv) {
  ConformanceArgs a;
  a.options.render = run_backend;
  Arguments args(argc, argv);
  while (args.more()) {
    std::string arg = args.next();
    if (arg == "--spp") {
      a.options.spp = args.uint_value(arg, 1);
    } else if (arg == "-a") {
      a.options.search_paths.push_back(args.value(arg));
    } else if (arg == "--backend") {
      a.options.backend = args.value(arg);
      if (a.options.backend != "cpu" && a.options.backend != "gpu")
        throw UsageError("--backend must be cpu or gpu, got '" + a.options.backend + "'");
    } else if (arg == "--threads") {
      a.options.threads = args.uint_value(arg, 1);
    } else if (arg == "--previews") {
      a.options.preview_dir = args.value(arg);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.folder.empty()) {
      a.folder = arg;
    } else {
      throw UsageError("more than one folder given ('" + a.folder + "', '" + arg + "')");
    }
  }
  if (a.folder.empty()) throw UsageError("no folder given");
  if (!std::filesystem::is_directory(a.folder))
    throw UsageError("'" + a.folder + "' is not a folder");
  if (!a.options.preview_dir.empty() && !std::filesystem::is_directory(a.options.preview_dir))
    throw UsageError("--previews: '" + a.options.preview_dir + "' is not a folder");
  return a;
}

}  // namespace

int conformance_command(int argc, char** argv) {
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    }
  }
  ConformanceArgs a;
  try {
    a = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray conformance: %s\n%s", e.what(), kUsage);
    return kExitUsage;
  }
  try {
    std::vector<std::string> scenes = conformance_scenes(a.folder);
    std::map<ConformanceOutcome, int> counts;
    for (const std::string& scene : scenes) {
      ConformanceResult r = check_conformance(scene, a.options);
      ++counts[r.outcome];
      std::string name = std::filesystem::path(scene).filename().string();
      std::printf("%-12s %-44s %6.2f s%s%s\n", outcome_name(r.outcome), name.c_str(), r.seconds,
                  r.detail.empty() ? "" : "  ", r.detail.c_str());
      std::fflush(stdout);
    }
    std::printf("%zu scenes: %d rendered, %d out-of-scope, %d FAILED\n", scenes.size(),
                counts[ConformanceOutcome::Rendered], counts[ConformanceOutcome::OutOfScope],
                counts[ConformanceOutcome::Failed]);
    return counts[ConformanceOutcome::Failed] > 0 ? kExitFailed : kExitOk;
  } catch (...) {
    return report_failure("twinray conformance");
  }
}

}  // namespace tr
