#include "app/convert_command.h"

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "io/temp_file.h"
#include "scenes/gltf/gltf_import.h"
#include "scenes/load_scene.h"
#include "scenes/scn/scn_import.h"
#include "scenes/xml_writer.h"

namespace tr {

namespace {

namespace fs = std::filesystem;

const char* kUsage =
    "usage: twinray convert SCENE.scn|SCENE.gltf|SCENE.glb -o OUT.xml [-D NAME=VALUE]...\n"
    "                       [-a PATH]... [--camera C] [--strict-gltf]\n"
    "  Writes the scene as Mitsuba 3 XML: a .scn scene with each material group of its OBJ\n"
    "  meshes as OUT_<entity>_<group>_<material>.ply beside it; a glTF scene with its\n"
    "  primitives as OUT_gltf_mesh_<n>.ply and its textures, factors applied, as\n"
    "  OUT_gltf_texture_<n>.pfm. -D width, height, spp and max_depth set the XML's <default>\n"
    "  values; -a adds folders searched for the files the scene names; --camera and\n"
    "  --strict-gltf as for `twinray render`. The mapping warnings are printed as `twinray\n"
    "  render` prints them (scenes/README.md).\n";

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
    } else if (arg == "--camera") {
      a.load.camera = args.value("--camera");
    } else if (arg == "--strict-gltf") {
      a.load.strict_gltf = true;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.scene.empty()) {
      a.scene = arg;
    } else {
      throw UsageError("more than one scene given");
    }
  }
  if (a.scene.empty()) throw UsageError("no scene given");
  const bool gltf = is_gltf(a.scene);
  if (fs::path(a.scene).extension() != ".scn" && !gltf)
    throw UsageError("'" + a.scene + "' is not a .scn or glTF scene");
  if ((!a.load.camera.empty() || a.load.strict_gltf) && !gltf)
    throw UsageError("--camera and --strict-gltf are for glTF scenes");
  if (!a.load.camera.empty() && a.load.camera != "auto" &&
      a.load.camera.find_first_not_of("0123456789") != std::string::npos)
    throw UsageError("--camera expects auto or a camera index, got '" + a.load.camera + "'");
  if (a.output.empty()) throw UsageError("-o OUT.xml is required");
  return a;
}

// Renames each file of `dir` that a `filename` property of the tree names to `prefix` + its
// name, and makes the property name it relative to the XML (which is written beside it).
void name_after_output(Node& node, const fs::path& dir, const std::string& prefix) {
  for (Property& p : node.props) {
    if (p.kind == PropertyKind::Object) name_after_output(*p.object, dir, prefix);
    if (p.kind != PropertyKind::String || p.name != "filename") continue;
    fs::path file(p.text);
    if (file.parent_path() != dir) continue;
    std::string name = file.filename().string();
    if (name.rfind(prefix, 0) != 0) {
      name = prefix + name;
      fs::rename(file, dir / name);
    }
    p.text = name;
  }
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
    const bool gltf = is_gltf(a.scene);
    TemporaryDirectory files;
    fs::path out(a.output);
    std::ostringstream xml;
    std::string comment = "Written by twinray convert from " +
                          fs::path(a.scene).filename().string() +
                          " (scenes/README.md: " + (gltf ? "glTF 2.0" : ".scn") + " scenes)";
    if (gltf) {
      GltfScene scene = import_gltf(a.scene, a.load, files.path());
      name_after_output(*scene.parsed.root, files.path(), out.stem().string() + "_");
      write_scene_xml(xml, *scene.parsed.root, scene.parameters, comment);
    } else {
      ScnScene scn = import_scn(a.scene, a.load, files.path(), out.stem().string(), true);
      write_scene_xml(xml, *scn.parsed.root, scn.parameters, comment);
    }
    fs::path dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    for (const fs::directory_entry& e : fs::directory_iterator(files.path())) {
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
