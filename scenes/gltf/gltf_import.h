// glTF 2.0 scenes (.gltf, .glb; Khronos glTF 2.0 specification, issue 13) -> the Node tree that
// the Mitsuba XML parser builds (scenes/xml_parser.h), as scenes/scn/ does for .scn scenes, so
// that the scene builder and both backends treat them as XML scenes. Assimp reads the geometry
// (buffers, accessors, primitives); the glTF JSON itself gives materials, cameras, lights and
// the fields that are reported as not mapped. scenes/README.md ("glTF 2.0 scenes") gives the
// field table.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scenes/load_scene.h"
#include "scenes/xml_parser.h"
#include "scenes/xml_writer.h"

namespace tr {

struct GltfScene {
  ParsedScene parsed;
  // One line each, "file:line: field: what": fields not mapped or mapped approximately.
  std::vector<std::string> warnings;
  // -D width, height, spp and max_depth: the values used and the properties that hold them, for
  // `twinray convert` to write as <default>s.
  std::vector<SceneParameter> parameters;
};

bool is_gltf(const std::string& path);

// Reads `path` (.gltf or .glb). The primitives are written as PLY files and the textures as
// PFM images (factors and channel selections applied) into `work_dir`, which must outlive the
// scene's build. Throws SceneError("file:line: what and why") on bad input; for a .glb the
// line is that of its JSON chunk.
GltfScene import_gltf(const std::string& path, const LoadOptions& options,
                      const std::filesystem::path& work_dir);

}  // namespace tr
