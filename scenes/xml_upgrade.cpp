#include "scenes/xml_upgrade.h"

#include <algorithm>
#include <cctype>
#include <unordered_set>

namespace tr {

namespace {

bool is_lower(char c) { return std::islower(static_cast<unsigned char>(c)) != 0; }
bool is_upper(char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; }
char to_lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

// Properties::rename_property: nothing happens when another parameter has the new name.
void rename(Property& p, const std::string& new_name, std::unordered_set<std::string>& names) {
  if (new_name == p.name || names.count(new_name)) return;
  names.erase(p.name);
  names.insert(new_name);
  p.name = new_name;
}

void upgrade_uv_parameters(Node& node) {
  const char* const names[4] = {"uoffset", "voffset", "uscale", "vscale"};
  auto is_uv = [&](const Property& p) {
    return std::any_of(std::begin(names), std::end(names),
                       [&](const char* n) { return p.name == n; });
  };
  auto first = std::find_if(node.props.begin(), node.props.end(), is_uv);
  if (first == node.props.end()) return;
  Location loc = first->loc;
  double values[4] = {0.0, 0.0, 1.0, 1.0};
  for (int i = 0; i < 4; ++i) values[i] = take_float(node, names[i], values[i]);
  node.props.erase(std::remove_if(node.props.begin(), node.props.end(), is_uv), node.props.end());
  if (const Property* given = find_property(node, "to_uv"))
    fail(given->loc, "parameter 'to_uv' of ", describe(node), " is specified twice: the uoffset, ",
         "voffset, uscale and vscale of line ", loc.line,
         " become 'to_uv' when a scene below version 2.0.0 is upgraded (as in Mitsuba 3)");
  glm::dmat4 translate(1.0), scale(1.0);
  translate[3] = glm::dvec4(values[0], values[1], 0.0, 1.0);
  scale[0][0] = values[2];
  scale[1][1] = values[3];
  Property to_uv;
  to_uv.name = "to_uv";
  to_uv.kind = PropertyKind::Transform;
  to_uv.loc = loc;
  to_uv.matrix = scale * translate;
  node.props.push_back(std::move(to_uv));
}

}  // namespace

std::string camel_to_underscore_case(const std::string& name) {
  std::string result;
  for (size_t i = 0; i < name.size(); ++i) {
    if (i > 0 && is_lower(name[i - 1]) && is_upper(name[i])) {
      result += '_';
      result += to_lower(name[i]);
      while (i + 1 < name.size() && is_upper(name[i + 1])) result += to_lower(name[++i]);
    } else {
      result += name[i];
    }
  }
  return result;
}

void upgrade_from_v1(Node& node) {
  std::unordered_set<std::string> names;
  for (const Property& p : node.props) names.insert(p.name);
  for (Property& p : node.props) rename(p, camel_to_underscore_case(p.name), names);
  if (node.type == "diffuse")
    if (Property* p = find_property(node, "diffuse_reflectance")) rename(*p, "reflectance", names);
  upgrade_uv_parameters(node);
}

}  // namespace tr
