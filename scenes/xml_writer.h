// A Node tree (scenes/properties.h) -> Mitsuba 3 XML that scenes/xml_parser.cpp reads back into
// the same tree: floats with 17 significant digits (exact round trip of doubles), objects held
// by several parents written once with their id and then as <ref>.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scenes/properties.h"

namespace tr {

// A <default name value>, and the property of `node` that reads it as $name.
struct SceneParameter {
  std::string name, value;
  const Node* node;
  std::string property;
};

void write_scene_xml(std::ostream& out, const Node& root,
                     const std::vector<SceneParameter>& parameters, const std::string& comment);

}  // namespace tr
