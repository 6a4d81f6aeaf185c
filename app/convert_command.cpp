#include "app/convert_command.h"

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "io/temp_file.h"
#include "scenes/load_scene.h"
#include "scenes/scn/scn_import.h"
#include "scenes/xml_writer.h"

namespace tr {

namespace {

namespace fs = std::filesystem;

const char* kUsage =
    "usage: twinray convert SCENE.scn -o OUT.xml [-D NAME=VALUE]... [-a PATH]...\n"
    "  Writes the .scn scene as Mitsuba 3 XML, and each material group of its OBJ meshes as\n"
    "  OUT_<entity>_<group>_<material>.ply beside it. -D width, height, spp and max_depth set\n"
    "  the XML's <default> values; -a adds folders searched for the OBJ files. The mapping\n"
    "  warnings are printed as `twinray render` prints them (scenes/README.md).\n";

struct ConvertArgs {
  std::string scene, output;
  LoadOptions load;
};

ConvertArgs parse(int argc, char** argv) {
  Arguments args(argc, argv);
  ConvertArgs a;
  while (args.more()) {
    std::string arg = args.next();
    if (arg == "-o") {
      a.output = args.value("-o");
    } else if (arg == "-D") {
      auto [name, value] = args.name_value("-D");
      a.load.defines[name] = value;
    } else if (arg == "-a") {
      a.load.search_paths.push_back(args.value("-a"));
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.scene.empty()) {
      a.scene = arg;
    } else {
      throw UsageError("more than one scene given");
    }
  }
  if (a.scene.empty()) throw UsageError("no scene given");
  if (fs::path(a.scene).extension() != ".scn")
    throw UsageError("'" + a.scene + "' is not a .scn scene");
  if (a.output.empty()) throw UsageError("-o OUT.xml is required");
  return a;
}

}  // namespace

int convert_command(int argc, char** argv) {
  for (int i = 0; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    }
  ConvertArgs a;
  try {
    a = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray convert: %s\n%s", e.what(), kUsage);
    return kExitUsage;
  }
  try {
    // Building the scene checks everything the XML loader will check, and prints the warnings.
    load_scene(a.scene, a.load);
    TemporaryDirectory meshes;
    fs::path out(a.output);
    ScnScene scn = import_scn(a.scene, a.load, meshes.path(), out.stem().string(), true);
    std::ostringstream xml;
    write_scene_xml(xml, *scn.parsed.root, scn.parameters,
                    "Written by twinray convert from " + fs::path(a.scene).filename().string() +
                        " (scenes/README.md: .scn scenes)");
    fs::path dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    for (const fs::directory_entry& e : fs::directory_iterator(meshes.path())) {
      std::error_code ec;
      fs::copy_file(e.path(), dir / e.path().filename(), fs::copy_options::overwrite_existing, ec);
      if (ec)
        throw FileError((dir / e.path().filename()).string() + ": cannot write: " + ec.message());
    }
    write_text_file(a.output, xml.str());
    return kExitOk;
  } catch (...) {
    return report_failure("twinray convert");
  }
}

}  // namespace tr
