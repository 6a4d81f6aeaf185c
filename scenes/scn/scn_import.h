// `.scn` scenes (the JSON format of ../shared/seed-scenes/README.md, issue 13) -> the Node tree
// that the Mitsuba XML parser builds (scenes/xml_parser.h), so that the scene builder and both
// backends treat them as XML scenes. scenes/README.md ("`.scn` scenes") gives the field table.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scenes/load_scene.h"
#include "scenes/xml_parser.h"
#include "scenes/xml_writer.h"

namespace tr {

struct ScnScene {
  ParsedScene parsed;
  // The values -D may override (width, height, spp, max_depth), as XML <default>s.
  std::vector<SceneParameter> parameters;
  // One line each: fields not mapped or mapped approximately, unused materials, usemtl groups
  // without a .scn material.
  std::vector<std::string> warnings;
};

// Reads `path`; the OBJ files' material groups are written as PLY files into `mesh_dir`,
// named `<mesh_prefix>_<entity>_<group>_<material>.ply`, and the shapes name them by file name
// only when `relative_names` (an XML written into mesh_dir), else by full path. Throws
// SceneError("file:line: what and why") on bad input.
ScnScene import_scn(const std::string& path, const LoadOptions& options,
                    const std::filesystem::path& mesh_dir, const std::string& mesh_prefix,
                    bool relative_names);

}  // namespace tr
