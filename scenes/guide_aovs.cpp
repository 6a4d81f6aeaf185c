#include "scenes/guide_aovs.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <set>
#include <stdexcept>

#include "core/scene_types.h"
#include "scenes/properties.h"

namespace tr {
namespace {

// The types parse_aovs (scenes/build_sensor.cpp) accepts; Mitsuba's dp_du, dp_dv, duv_dx and
// duv_dy are not implemented by twinray.
const std::vector<std::string> kTypes = {"albedo",     "depth",     "position",   "uv",
                                         "geo_normal", "sh_normal", "prim_index", "shape_index"};

bool valid_name(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::string joined_types() {
  std::string s;
  for (const std::string& t : kTypes) s += (s.empty() ? "" : ", ") + t;
  return s;
}

void check(const std::vector<GuideAov>& aovs) {
  if (aovs.empty()) throw std::invalid_argument("no AOV given");
  if (aovs.size() > AOV_MAX)
    throw std::invalid_argument(std::to_string(aovs.size()) + " AOVs, more than the " +
                                std::to_string(AOV_MAX) + " the aov integrator holds");
  std::set<std::string> names;
  for (const GuideAov& a : aovs) {
    if (std::find(kTypes.begin(), kTypes.end(), a.type) == kTypes.end())
      throw std::invalid_argument("unknown AOV type '" + a.type + "' (valid: " + joined_types() +
                                  ")");
    if (!valid_name(a.name))
      throw std::invalid_argument("invalid AOV name '" + a.name +
                                  "' (a letter, then letters, digits or '_')");
    if (!names.insert(a.name).second)
      throw std::invalid_argument("AOV name '" + a.name + "' given twice");
  }
}

}  // namespace

const char* guide_aov_types() {
  static const std::string types = joined_types();
  return types.c_str();
}

std::vector<GuideAov> parse_guide_aovs(const std::string& list) {
  std::vector<GuideAov> aovs;
  size_t start = 0;
  while (true) {
    size_t end = list.find(',', start);
    std::string entry =
        list.substr(start, end == std::string::npos ? std::string::npos : end - start);
    // Spaces around an entry are ignored, as Mitsuba's aovs list ignores them.
    entry.erase(0, entry.find_first_not_of(' '));
    entry.erase(entry.find_last_not_of(' ') + 1);
    if (entry.empty())
      throw std::invalid_argument("empty entry in '" + list +
                                  "' (expected TYPE or NAME:TYPE, comma-separated)");
    const size_t colon = entry.find(':');
    if (colon == std::string::npos)
      aovs.push_back({entry, entry});
    else
      aovs.push_back({entry.substr(0, colon), entry.substr(colon + 1)});
    if (end == std::string::npos) break;
    start = end + 1;
  }
  check(aovs);
  return aovs;
}

void wrap_in_guide_aovs(Node& root, const std::vector<GuideAov>& aovs) {
  check(aovs);
  auto is_integrator = [](const Property& p) {
    return p.kind == PropertyKind::Object && p.object->tag == "integrator";
  };
  auto slot = std::find_if(root.props.begin(), root.props.end(), is_integrator);
  NodePtr inner;
  if (slot == root.props.end()) {
    inner = std::make_shared<Node>();  // Mitsuba's default integrator
    inner->tag = "integrator";
    inner->type = "path";
    inner->loc = root.loc;
  } else {
    inner = slot->object;
    if (inner->type == "aov")
      fail(inner->loc,
           "--aov: the scene's integrator is already <integrator type=\"aov\">; put the guide "
           "AOVs into its aovs list or drop --aov");
    // build_sensor.cpp nests neither aov nor moment in aov (Mitsuba's aov would write the
    // moment's channels as further AOVs, which twinray's film does not hold).
    if (inner->type == "moment")
      fail(inner->loc,
           "--aov: the scene's integrator is <integrator type=\"moment\">, which twinray cannot "
           "nest in aov; use the integrator it wraps (OUT_var.exr holds the variance anyway)");
  }
  std::string list;
  for (const GuideAov& a : aovs) list += (list.empty() ? "" : ",") + a.name + ":" + a.type;
  auto aov = std::make_shared<Node>();
  aov->tag = "integrator";
  aov->type = "aov";
  aov->loc = inner->loc;
  add_property(*aov, "aovs", PropertyKind::String, inner->loc).text = list;
  // Unnamed, as a nested <integrator> in XML: its colour is the image's R, G, B.
  add_property(*aov, "_arg_0", PropertyKind::Object, inner->loc).object = inner;
  if (slot == root.props.end()) {
    add_property(root, "_guide_aovs", PropertyKind::Object, root.loc).object = aov;
  } else {
    slot->object = aov;
  }
}

}  // namespace tr
