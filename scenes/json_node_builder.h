// What the JSON scene importers (scenes/scn, scenes/gltf) share: the file:line of a JSON pointer
// (scenes/scn/json_lines.h), one-line errors and warnings that name the field as a reader
// writes it ("/entities/1/radius" -> entities[1].radius), typed reads, and the XML parser's
// node tree (scenes/xml_parser.h) they build, so that everything after them is the XML path.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/properties.h"
#include "scenes/scene_error.h"

namespace tr {

class JsonNodeBuilder {
 protected:
  using json = nlohmann::json;

  explicit JsonNodeBuilder(std::string path) : path_(std::move(path)) {}

  // Parses `text` (the document of path_) and records the line of each value in lines_; a
  // malformed document, one nested deeper than kJsonMaxDepth or a key given twice in one object
  // (RFC 8259 section 4 leaves its meaning to the reader) is a one-line error.
  json parse_document(const std::string& text);

  // --- locations and messages ---

  // The line of `pointer`, else of its nearest ancestor with a known line.
  Location at(std::string pointer) const;
  static std::string field(const std::string& pointer);
  // " (JSON chunk byte N)" where the value of `pointer` (or its nearest ancestor) starts, when
  // byte_offsets_ is set (a GLB's JSON chunk, whose lines say little); else "".
  std::string byte_note(std::string pointer) const;
  // field() with every array index written as "*".
  static std::string shape(const std::string& pointer);

  template <typename... Parts>
  [[noreturn]] void bad(const std::string& pointer, const Parts&... parts) const {
    fail(at(pointer), field(pointer), byte_note(pointer), ": ", parts...);
  }

  // A field that does not map exactly: one "file:line: field: what" warning, each distinct line
  // once; with strict_, an error.
  template <typename... Parts>
  void warn(const std::string& pointer, const Parts&... parts) {
    if (strict_) bad(pointer, parts..., " (refused: --strict-gltf)");
    note(pointer, parts...);
  }

  // A warning that strict_ does not refuse: what the scene does not use, with no effect on the
  // quantity rendered, or what twinray chose where the file states nothing.
  template <typename... Parts>
  void note(const std::string& pointer, const Parts&... parts) {
    std::ostringstream what;
    (what << ... << parts);
    std::string line =
        to_string(at(pointer)) + ": " + field(pointer) + byte_note(pointer) + ": " + what.str();
    if (warned_.insert(line).second)
      warnings_.push_back({line, shape(pointer) + "\n" + what.str()});
  }

  // The warnings, those that differ only in their fields' array indices collapsed into their
  // first, which says how many there are and the fields' shape ("(x 20: meshes[*].primitives[*]
  // .attributes.TANGENT)").
  std::vector<std::string> take_warnings();

  // --- typed reads (each failure names the field) ---

  const json& object(const json& v, const std::string& pointer) const;
  double number(const json& v, const std::string& pointer) const;
  std::string text(const json& v, const std::string& pointer) const;

  // --- node tree ---

  NodePtr make(const std::string& tag, const std::string& type, const std::string& pointer) const;
  Property& add(Node& n, const std::string& name, PropertyKind kind,
                const std::string& pointer) const;
  void add_float(Node& n, const std::string& name, double v, const std::string& pointer) const;
  void add_color(Node& n, const std::string& name, glm::dvec3 v, const std::string& pointer) const;
  void add_object(Node& n, NodePtr o, const std::string& pointer);
  void add_transform(Node& n, const glm::dmat4& m, const std::string& pointer) const;

  std::string path_;
  std::map<std::string, int> lines_;     // JSON pointer -> line
  std::map<std::string, size_t> bytes_;  // JSON pointer -> byte offset
  bool byte_offsets_ = false;
  bool strict_ = false;
  struct Warning {
    std::string line;
    std::string key;  // the field's shape and the message
  };
  std::vector<Warning> warnings_;

 private:
  std::set<std::string> warned_;
  int unnamed_ = 0;
};

}  // namespace tr
