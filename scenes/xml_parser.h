// Mitsuba 3 XML -> Node tree: <default>, $name substitution, <include>, <path>, <ref>/id,
// typed properties (spectra converted to RGB, transforms composed), files below version 2.0.0
// upgraded as by Mitsuba 3 (xml_upgrade.h), with every error reported as "file:line: ...".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scenes/load_scene.h"
#include "scenes/properties.h"

namespace tr {

// Mitsuba's file resolver: directories searched in order for relative file names.
struct FileResolver {
  std::vector<std::filesystem::path> dirs;
  // The first existing dir/name, else `fallback_dir`/name if that exists; empty if none.
  std::filesystem::path resolve(const std::string& name,
                                const std::filesystem::path& fallback_dir) const;
};

struct ParsedScene {
  NodePtr root;  // tag "scene"
  FileResolver resolver;
  // "file:line: what" lines for the user: one per file below version 2.0.0, upgraded as
  // Mitsuba 3 upgrades it (xml_upgrade.h).
  std::vector<std::string> warnings;
};

// Mitsuba Transform4f::look_at, as <lookat>; fails at `loc` when origin = target or up is
// parallel to the view direction.
glm::dmat4 look_at(glm::dvec3 origin, glm::dvec3 target, glm::dvec3 up, const Location& loc);

ParsedScene parse_scene_xml(const std::string& path, const LoadOptions& options);

}  // namespace tr
