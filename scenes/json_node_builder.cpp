#include "scenes/json_node_builder.h"

#include <cmath>
#include <map>
#include <set>

#include "scenes/scn/json_lines.h"

namespace tr {

nlohmann::json JsonNodeBuilder::parse_document(const std::string& text) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    int line = 1;
    for (size_t i = 0; i < e.byte && i < text.size(); ++i) line += text[i] == '\n';
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    size_t cut = what.find("] ");
    fail(Location{path_, line},
         "malformed JSON: ", cut == std::string::npos ? what : what.substr(cut + 2));
  }
  JsonLines lines = json_value_lines(text);
  lines_ = lines.lines;
  bytes_ = lines.bytes;
  if (lines.too_deep)
    fail(Location{path_, lines.too_deep}, "arrays and objects nested deeper than ", kJsonMaxDepth,
         " levels");
  if (!lines.repeated.empty()) {
    const auto& [pointer, line] = *lines.repeated.begin();
    fail(Location{path_, line}, field(pointer), ": given twice (first on line ", lines_[pointer],
         ")");
  }
  return doc;
}

Location JsonNodeBuilder::at(std::string pointer) const {
  for (;;) {
    auto it = lines_.find(pointer);
    if (it != lines_.end() || pointer.empty()) return {path_, it != lines_.end() ? it->second : 1};
    pointer = pointer.substr(0, pointer.rfind('/'));
  }
}

std::string JsonNodeBuilder::field(const std::string& pointer) {
  std::string out;
  size_t i = 1;
  while (i <= pointer.size() && !pointer.empty()) {
    size_t j = pointer.find('/', i);
    std::string token = pointer.substr(i, j == std::string::npos ? std::string::npos : j - i);
    bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + token + "]" : (out.empty() ? "" : ".") + token;
    if (j == std::string::npos) break;
    i = j + 1;
  }
  return out.empty() ? "the scene" : out;
}

std::string JsonNodeBuilder::byte_note(std::string pointer) const {
  if (!byte_offsets_) return "";
  for (;;) {
    auto it = bytes_.find(pointer);
    if (it != bytes_.end()) return " (JSON chunk byte " + std::to_string(it->second) + ")";
    if (pointer.empty()) return "";
    pointer = pointer.substr(0, pointer.rfind('/'));
  }
}

std::string JsonNodeBuilder::shape(const std::string& pointer) {
  std::string out = field(pointer);
  for (size_t open = out.find('['); open != std::string::npos; open = out.find('[', open + 1))
    out.replace(open + 1, out.find(']', open) - open - 1, "*");
  return out;
}

std::vector<std::string> JsonNodeBuilder::take_warnings() {
  std::map<std::string, size_t> count;
  for (const Warning& w : warnings_) ++count[w.key];
  std::vector<std::string> out;
  std::set<std::string> said;
  for (const Warning& w : warnings_) {
    if (!said.insert(w.key).second) continue;
    size_t n = count[w.key];
    out.push_back(n == 1 ? w.line
                         : w.line + " (x " + std::to_string(n) + ": " +
                               w.key.substr(0, w.key.find('\n')) + ")");
  }
  warnings_.clear();
  return out;
}

const nlohmann::json& JsonNodeBuilder::object(const json& v, const std::string& pointer) const {
  if (!v.is_object()) bad(pointer, "expected an object, not ", v.type_name());
  return v;
}

double JsonNodeBuilder::number(const json& v, const std::string& pointer) const {
  if (!v.is_number()) bad(pointer, "expected a number, not ", v.type_name());
  double d = v.get<double>();
  if (!std::isfinite(d)) bad(pointer, "expected a finite number");
  return d;
}

std::string JsonNodeBuilder::text(const json& v, const std::string& pointer) const {
  if (!v.is_string()) bad(pointer, "expected a string, not ", v.type_name());
  return v.get<std::string>();
}

NodePtr JsonNodeBuilder::make(const std::string& tag, const std::string& type,
                              const std::string& pointer) const {
  auto n = std::make_shared<Node>();
  n->tag = tag;
  n->type = type;
  n->loc = at(pointer);
  return n;
}

Property& JsonNodeBuilder::add(Node& n, const std::string& name, PropertyKind kind,
                               const std::string& pointer) const {
  Property p;
  p.name = name;
  p.kind = kind;
  p.loc = at(pointer);
  n.props.push_back(p);
  return n.props.back();
}

void JsonNodeBuilder::add_float(Node& n, const std::string& name, double v,
                                const std::string& pointer) const {
  add(n, name, PropertyKind::Float, pointer).number = v;
}

void JsonNodeBuilder::add_color(Node& n, const std::string& name, glm::dvec3 v,
                                const std::string& pointer) const {
  add(n, name, PropertyKind::Color, pointer).vec = v;
}

void JsonNodeBuilder::add_object(Node& n, NodePtr o, const std::string& pointer) {
  add(n, "_arg_" + std::to_string(unnamed_++), PropertyKind::Object, pointer).object = std::move(o);
}

void JsonNodeBuilder::add_transform(Node& n, const glm::dmat4& m,
                                    const std::string& pointer) const {
  add(n, "to_world", PropertyKind::Transform, pointer).matrix = m;
}

}  // namespace tr
