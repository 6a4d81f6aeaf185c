#include "scenes/xml_parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <unordered_map>

#include "scenes/spectrum.h"
#include "scenes/values.h"
#include "scenes/xml_upgrade.h"
#include "scenes/xml_upgrade_beyond.h"

namespace tr {

namespace fs = std::filesystem;

fs::path FileResolver::resolve(const std::string& name, const fs::path& fallback_dir) const {
  fs::path p(name);
  std::error_code ec;
  if (p.is_absolute()) return fs::exists(p, ec) ? p : fs::path();
  for (const fs::path& dir : dirs)
    if (fs::exists(dir / p, ec)) return dir / p;
  if (fs::exists(fallback_dir / p, ec)) return fallback_dir / p;
  return fs::path();
}

glm::dmat4 look_at(glm::dvec3 origin, glm::dvec3 target, glm::dvec3 up, const Location& loc) {
  // Mitsuba Transform4f::look_at: columns (left, up', dir, origin); the camera looks along +z.
  glm::dvec3 dir = target - origin;
  if (glm::length(dir) == 0.0) fail(loc, "<lookat>: origin and target coincide");
  dir = glm::normalize(dir);
  glm::dvec3 left = glm::cross(up, dir);
  if (glm::length(left) < 1e-12) fail(loc, "<lookat>: 'up' is parallel to the view direction");
  left = glm::normalize(left);
  glm::dvec3 new_up = glm::cross(dir, left);
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(left, 0.0);
  m[1] = glm::dvec4(new_up, 0.0);
  m[2] = glm::dvec4(dir, 0.0);
  m[3] = glm::dvec4(origin, 1.0);
  return m;
}

namespace {

// Mitsuba's object tags; media, phase functions and volumes are parsed only to be refused by
// name (scenes/plugins.h).
const std::set<std::string> OBJECT_TAGS = {"shape",      "bsdf",   "texture", "emitter",
                                           "sensor",     "film",   "rfilter", "sampler",
                                           "integrator", "medium", "phase",   "volume"};
const int MAX_INCLUDE_DEPTH = 15;

// Parameters that Mitsuba's plugins read as unbounded textures or IORs, so that their colors
// may leave [0, 1]: conductor eta/k (conductor.cpp get_unbounded_texture), microfacet alphas
// (roughconductor.cpp, roughdielectric.cpp), int_ior/ext_ior (ior.h).
bool unbounded_parameter(const std::string& name) {
  return name == "eta" || name == "k" || name == "int_ior" || name == "ext_ior" ||
         name == "alpha" || name == "alpha_u" || name == "alpha_v";
}

// One XML file: its text (for offset -> line) and its directory.
struct Source {
  std::string display;  // file name used in messages
  fs::path dir;
  bool below_2_0 = false;  // version below 2.0.0: its objects are upgraded (xml_upgrade.h)
  std::vector<size_t> line_starts;

  int line_of(ptrdiff_t offset) const {
    if (offset < 0) return 1;
    return int(std::upper_bound(line_starts.begin(), line_starts.end(), size_t(offset)) -
               line_starts.begin());
  }
  Location at(const pugi::xml_node& x) const { return {display, line_of(x.offset_debug())}; }
};

// Rotation by `degrees` about `axis`, counter-clockwise looking down the axis (Rodrigues).
glm::dmat4 rotation(glm::dvec3 axis, double degrees) {
  axis = glm::normalize(axis);
  double a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  glm::dmat3 k(0.0);  // cross-product matrix [axis]_x, column-major
  k[1][0] = -axis.z;
  k[2][0] = axis.y;
  k[0][1] = axis.z;
  k[2][1] = -axis.x;
  k[0][2] = -axis.y;
  k[1][2] = axis.x;
  glm::dmat3 r = c * glm::dmat3(1.0) + s * k + (1.0 - c) * glm::outerProduct(axis, axis);
  return glm::dmat4(r);
}

class Parser {
 public:
  explicit Parser(const LoadOptions& options)
      : params_(options.defines),
        defines_(options.defines),
        unused_defines_allowed_(options.unused_defines_allowed) {
    for (const std::string& p : options.search_paths) resolver_.dirs.push_back(fs::path(p));
  }

  ParsedScene parse(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
      throw SceneError(path + ":0: scene file not found or not a regular file");
    fs::path main_dir = fs::path(path).parent_path();
    resolver_.dirs.push_back(main_dir.empty() ? fs::path(".") : main_dir);
    auto root = std::make_shared<Node>();
    root->tag = "scene";
    parse_file(path, path, *root, 0, true);
    resolve_references();
    for (Node* node : upgraded_) upgrade_from_v1(*node);
    // What Mitsuba 3.8 refuses in those files but keeps Mitsuba 0.6's radiance (beyond 3.8).
    for (std::string& w : upgrade_beyond_mitsuba_3_8(upgraded_))
      warnings_.push_back(std::move(w));
    check_cycles(*root);
    // As Mitsuba: a -D value that no $name uses is an error (probably a typo).
    for (const auto& [name, value] : defines_)
      if (!used_.count(name) && !unused_defines_allowed_)
        fail(root->loc, "-D ", name, "=", value, " is not used: the scene has no $", name);
    return {root, resolver_, warnings_};
  }

 private:
  std::map<std::string, std::string> params_;
  std::map<std::string, std::string> defines_;
  bool unused_defines_allowed_;
  std::set<std::string> used_;  // names substituted at least once
  FileResolver resolver_;
  std::map<std::string, NodePtr> ids_;
  // Per node, the line of each parameter name given so far: a scene of 1e5 shapes would make a
  // scan of the scene's parameters quadratic.
  std::unordered_map<const Node*, std::unordered_map<std::string, int>> property_lines_;
  int unnamed_ = 0;
  // <ref> elements, resolved once every file is read: Mitsuba resolves references to objects
  // declared anywhere in the scene, before or after the reference (src/core/parser.cpp).
  struct PendingReference {
    Node* owner;  // kept alive by the tree
    size_t property;
    std::string id;
  };
  std::vector<PendingReference> references_;
  // The objects of files below version 2.0.0, upgraded once every file is read, as Mitsuba's
  // transform_upgrade does.
  std::vector<Node*> upgraded_;
  std::vector<std::string> warnings_;

  void resolve_references() {
    for (const PendingReference& r : references_) {
      Property& p = r.owner->props[r.property];
      auto it = ids_.find(r.id);
      if (it == ids_.end())
        fail(p.loc, "<ref id=\"", r.id, "\">: no object in the scene has this id");
      p.object = it->second;
    }
  }

  // Mitsuba refuses circular references (an object that contains itself through <ref>s).
  void check_cycles(const Node& node) {
    std::set<const Node*> done, path;
    visit_for_cycles(node, done, path);
  }
  void visit_for_cycles(const Node& node, std::set<const Node*>& done,
                        std::set<const Node*>& path) {
    if (done.count(&node)) return;
    path.insert(&node);
    for (const Property& p : node.props) {
      if (p.kind != PropertyKind::Object) continue;
      if (path.count(p.object.get()))
        fail(p.loc, describe(*p.object), " (id \"", p.object->id,
             "\") contains itself through this reference");
      visit_for_cycles(*p.object, done, path);
    }
    path.erase(&node);
    done.insert(&node);
  }

  void parse_file(const fs::path& file, const std::string& display, Node& parent, int depth,
                  bool is_main) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(display + ":0: cannot read file");
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();

    Source src;
    src.display = display;
    src.dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    src.line_starts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') src.line_starts.push_back(i + 1);

    pugi::xml_document doc;
    pugi::xml_parse_result result = doc.load_buffer(text.data(), text.size());
    if (!result)
      fail(Location{display, src.line_of(result.offset)}, "malformed XML: ", result.description());

    pugi::xml_node root = doc.document_element();
    if (std::string(root.name()) != "scene")
      fail(src.at(root), "the root element must be <scene>, not <", root.name(), ">");
    check_attributes(root, src, {"version"});
    if (root.attribute("version").empty())
      fail(src.at(root), "<scene> is missing its 'version' attribute");
    std::string version = root.attribute("version").value();
    src.below_2_0 = check_version(version, src.at(root));
    if (src.below_2_0) {
      std::string warning = to_string(src.at(root)) + ": scene version " + version +
                            " upgraded on load as Mitsuba 3 upgrades Mitsuba 0.x scenes "
                            "(camelCase parameter names to snake_case, diffuse_reflectance to "
                            "reflectance, uoffset/voffset/uscale/vscale to to_uv)";
      if (std::find(warnings_.begin(), warnings_.end(), warning) == warnings_.end())
        warnings_.push_back(warning);
      if (is_main) upgraded_.push_back(&parent);
    }
    if (is_main) parent.loc = src.at(root);
    for (pugi::xml_node child : root.children()) parse_element(child, parent, src, depth, false, 1);
  }

  // The attribute's value with every $name replaced by its -D / <default> value.
  std::string attr(const pugi::xml_node& x, const char* name, const Source& src) {
    std::string raw = x.attribute(name).value();
    std::string out;
    for (size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '$') {
        out += raw[i];
        continue;
      }
      size_t j = i + 1;
      while (j < raw.size() && (std::isalnum(static_cast<unsigned char>(raw[j])) || raw[j] == '_'))
        ++j;
      std::string key = raw.substr(i + 1, j - i - 1);
      if (key.empty()) fail(src.at(x), "stray '$' in attribute ", name, "=\"", raw, "\"");
      auto it = params_.find(key);
      if (it == params_.end())
        fail(src.at(x), "undefined parameter $", key, " (give it with -D ", key,
             "=... or a <default name=\"", key, "\" .../>)");
      out += it->second;
      used_.insert(key);
      i = j - 1;
    }
    return out;
  }

  bool has_attr(const pugi::xml_node& x, const char* name) { return !x.attribute(name).empty(); }

  std::string required_attr(const pugi::xml_node& x, const char* name, const Source& src) {
    if (!has_attr(x, name)) fail(src.at(x), "<", x.name(), "> requires the attribute '", name, "'");
    return attr(x, name, src);
  }

  // Mitsuba's util::Version: three period-separated numbers (digits only, stricter than its
  // tokenizer). True below 2.0.0: a Mitsuba 0.x file, upgraded as Mitsuba 3 upgrades it
  // (xml_upgrade.h). From 4.0.0 on, a format after Mitsuba 3's that twinray cannot know: refused,
  // where Mitsuba 3.8 reads any version from 2.0.0 on as its own.
  bool check_version(const std::string& v, const Location& loc) {
    int parts = 0;
    bool digits = false, ok = true;
    unsigned long major = 0;
    for (char c : v) {
      if (std::isdigit(static_cast<unsigned char>(c))) {
        digits = true;
        if (parts == 0) major = std::min(major * 10 + unsigned(c - '0'), 10ul);
      } else if (c == '.' && digits) {
        ++parts;
        digits = false;
      } else {
        ok = false;
      }
    }
    if (!ok || !digits || parts != 2)
      fail(loc, "<scene version=\"", v, "\">: a version is three period-separated numbers");
    if (major > 3)
      fail(loc, "<scene version=\"", v,
           "\">: a version after Mitsuba 3's (3.x.x), whose scene format twinray does not know");
    return major < 2;
  }

  // The name the plugin reads the parameter under, where the upgrade's renaming of camelCase
  // names decides which colors may leave [0, 1].
  static std::string read_name(const std::string& name, const Source& src) {
    return src.below_2_0 ? camel_to_underscore_case(name) : name;
  }

  void check_attributes(const pugi::xml_node& x, const Source& src,
                        std::initializer_list<const char*> allowed) {
    for (pugi::xml_attribute a : x.attributes()) {
      bool ok = false;
      for (const char* name : allowed) ok = ok || std::string(a.name()) == name;
      if (!ok) fail(src.at(x), "unexpected attribute '", a.name(), "' in <", x.name(), ">");
    }
  }

  void add_property(Node& parent, Property p) {
    auto [first, added] = property_lines_[&parent].emplace(p.name, p.loc.line);
    if (!added)
      fail(p.loc, "parameter '", p.name, "' of ", describe(parent),
           " is specified twice (first at line ", first->second, ")");
    parent.props.push_back(std::move(p));
  }

  void no_children(const pugi::xml_node& x, const Source& src) {
    for (pugi::xml_node c : x.children())
      if (c.type() == pugi::node_element)
        fail(src.at(c), "<", x.name(), "> cannot contain <", c.name(), ">");
  }

  void parse_element(const pugi::xml_node& x, Node& parent, const Source& src, int depth,
                     bool within_emitter, int level) {
    if (x.type() != pugi::node_element) {
      if (x.type() == pugi::node_pcdata) {
        std::string t = x.value();
        if (std::any_of(t.begin(), t.end(), [](char c) { return !std::isspace((unsigned char)c); }))
          fail(src.at(x), "unexpected text \"", t, "\"");
      }
      return;
    }
    std::string tag = x.name();
    Location loc = src.at(x);

    if (OBJECT_TAGS.count(tag)) {
      check_attributes(x, src, {"type", "id", "name"});
      auto node = std::make_shared<Node>();
      node->tag = tag;
      node->type = required_attr(x, "type", src);
      node->loc = loc;
      if (has_attr(x, "id")) {
        node->id = attr(x, "id", src);
        if (ids_.count(node->id))
          fail(loc, "duplicate id \"", node->id, "\" (first used at ",
               to_string(ids_[node->id]->loc), ")");
      }
      bool in_emitter = within_emitter || tag == "emitter";
      for (pugi::xml_node c : x.children())
        parse_element(c, *node, src, depth, in_emitter, level + 1);
      if (!node->id.empty()) ids_[node->id] = node;
      if (src.below_2_0) upgraded_.push_back(node.get());
      Property p;
      p.name = has_attr(x, "name") ? attr(x, "name", src) : "_arg_" + std::to_string(unnamed_++);
      p.kind = PropertyKind::Object;
      p.loc = loc;
      p.object = node;
      add_property(parent, std::move(p));
      return;
    }

    if (tag == "ref") {
      check_attributes(x, src, {"id", "name"});
      no_children(x, src);
      std::string id = required_attr(x, "id", src);
      Property p;
      p.name = has_attr(x, "name") ? attr(x, "name", src) : "_arg_" + std::to_string(unnamed_++);
      p.kind = PropertyKind::Object;
      p.loc = loc;
      add_property(parent, std::move(p));
      references_.push_back({&parent, parent.props.size() - 1, id});
      return;
    }

    if (tag == "default") {
      check_attributes(x, src, {"name", "value"});
      no_children(x, src);
      std::string name = required_attr(x, "name", src);
      std::string value = required_attr(x, "value", src);
      if (name.empty()) fail(loc, "<default> with an empty name");
      params_.emplace(name, value);  // -D values and earlier defaults win
      return;
    }

    if (tag == "path") {
      check_attributes(x, src, {"value"});
      no_children(x, src);
      if (level != 1) fail(loc, "<path> may only appear directly inside <scene>");
      fs::path value(required_attr(x, "value", src));
      fs::path dir = value.is_absolute() ? value : src.dir / value;
      std::error_code ec;
      if (!fs::is_directory(dir, ec)) {
        fs::path alt = resolver_.resolve(value.string(), src.dir);
        if (alt.empty() || !fs::is_directory(alt, ec))
          fail(loc, "<path>: folder \"", value.string(), "\" not found (relative to ",
               src.dir.string(), ")");
        dir = alt;
      }
      resolver_.dirs.insert(resolver_.dirs.begin(), dir);
      return;
    }

    if (tag == "include") {
      check_attributes(x, src, {"filename"});
      no_children(x, src);
      std::string name = required_attr(x, "filename", src);
      fs::path file = src.dir / name;
      std::error_code ec;
      if (fs::path(name).is_absolute()) file = name;
      if (!fs::is_regular_file(file, ec)) file = resolver_.resolve(name, src.dir);
      if (file.empty() || !fs::is_regular_file(file, ec))
        fail(loc, "<include>: file \"", name, "\" not found");
      if (depth + 1 > MAX_INCLUDE_DEPTH)
        fail(loc, "<include>: nesting deeper than ", MAX_INCLUDE_DEPTH, " (recursive include?)");
      parse_file(file, file.lexically_normal().string(), parent, depth + 1, false);
      return;
    }

    if (tag == "alias") {
      check_attributes(x, src, {"id", "as"});
      no_children(x, src);
      std::string id = required_attr(x, "id", src), as = required_attr(x, "as", src);
      auto it = ids_.find(id);
      if (it == ids_.end()) fail(loc, "<alias>: unknown id \"", id, "\"");
      if (ids_.count(as)) fail(loc, "<alias>: id \"", as, "\" is already in use");
      ids_[as] = it->second;
      return;
    }

    // Typed properties.
    Property p;
    p.loc = loc;
    if (tag == "boolean" || tag == "integer" || tag == "float" || tag == "string") {
      check_attributes(x, src, {"name", "value"});
      no_children(x, src);
      p.name = required_attr(x, "name", src);
      std::string value = required_attr(x, "value", src);
      std::string what = tag + " '" + p.name + "'";
      if (tag == "boolean") {
        p.kind = PropertyKind::Boolean;
        p.boolean = parse_boolean(value, loc, what);
      } else if (tag == "integer") {
        p.kind = PropertyKind::Integer;
        p.integer = parse_integer(value, loc, what);
      } else if (tag == "float") {
        p.kind = PropertyKind::Float;
        p.number = parse_double(value, loc, what);
      } else {
        p.kind = PropertyKind::String;
        p.text = value;
      }
    } else if (tag == "rgb") {
      check_attributes(x, src, {"name", "value"});
      no_children(x, src);
      p.name = required_attr(x, "name", src);
      std::vector<double> v =
          parse_doubles(required_attr(x, "value", src), 3, true, loc, "rgb '" + p.name + "'");
      p.kind = PropertyKind::Color;
      p.vec = glm::dvec3(v[0], v[1], v[2]);
      // Mitsuba's srgb texture rejects reflectance-like colors outside [0, 1].
      if (!within_emitter && !unbounded_parameter(read_name(p.name, src)) &&
          (glm::any(glm::lessThan(p.vec, glm::dvec3(0.0))) ||
           glm::any(glm::greaterThan(p.vec, glm::dvec3(1.0)))))
        fail(loc, "rgb '", p.name, "' = (", v[0], ", ", v[1], ", ", v[2],
             ") must lie in [0, 1]: it is a reflectance-like value (Mitsuba rejects it too)");
    } else if (tag == "spectrum") {
      check_attributes(x, src, {"name", "value", "filename"});
      no_children(x, src);
      p.name = required_attr(x, "name", src);
      p.kind = PropertyKind::Color;
      p.vec = parse_spectrum(x, src, p.name, within_emitter);
    } else if (tag == "point" || tag == "vector") {
      check_attributes(x, src, {"name", "value", "x", "y", "z"});
      no_children(x, src);
      p.name = required_attr(x, "name", src);
      p.kind = tag == "point" ? PropertyKind::Point : PropertyKind::Vector;
      p.vec = parse_xyz(x, src, 0.0, true, tag + " '" + p.name + "'");
    } else if (tag == "transform") {
      check_attributes(x, src, {"name"});
      p.name = required_attr(x, "name", src);
      p.kind = PropertyKind::Transform;
      p.matrix = parse_transform(x, src);
    } else {
      fail(loc, "unknown or unsupported element <", tag, ">");
    }
    add_property(parent, std::move(p));
  }

  // value="x, y, z" (or one broadcast value when allowed) or x=/y=/z= attributes.
  glm::dvec3 parse_xyz(const pugi::xml_node& x, const Source& src, double default_value,
                       bool allow_broadcast, const std::string& what) {
    Location loc = src.at(x);
    if (has_attr(x, "value")) {
      if (has_attr(x, "x") || has_attr(x, "y") || has_attr(x, "z"))
        fail(loc, what, ": give either 'value' or x/y/z, not both");
      std::vector<double> v = parse_doubles(attr(x, "value", src), 3, allow_broadcast, loc, what);
      return glm::dvec3(v[0], v[1], v[2]);
    }
    glm::dvec3 r(default_value);
    if (has_attr(x, "x")) r.x = parse_double(attr(x, "x", src), loc, what + " x");
    if (has_attr(x, "y")) r.y = parse_double(attr(x, "y", src), loc, what + " y");
    if (has_attr(x, "z")) r.z = parse_double(attr(x, "z", src), loc, what + " z");
    return r;
  }

  glm::dvec3 parse_vec3_attr(const pugi::xml_node& x, const char* name, const Source& src) {
    std::vector<double> v = parse_doubles(required_attr(x, name, src), 3, false, src.at(x),
                                          std::string("<lookat> ") + name);
    return glm::dvec3(v[0], v[1], v[2]);
  }

  // Mitsuba composes the operations in document order: each one is applied after the
  // previous ones, M = op_n * ... * op_1.
  glm::dmat4 parse_transform(const pugi::xml_node& x, const Source& src) {
    glm::dmat4 m(1.0);
    for (pugi::xml_node op : x.children()) {
      if (op.type() != pugi::node_element) continue;
      std::string tag = op.name();
      Location loc = src.at(op);
      no_children(op, src);
      glm::dmat4 t(1.0);
      if (tag == "translate") {
        check_attributes(op, src, {"value", "x", "y", "z"});
        t[3] = glm::dvec4(parse_xyz(op, src, 0.0, false, "<translate>"), 1.0);
      } else if (tag == "scale") {
        check_attributes(op, src, {"value", "x", "y", "z"});
        glm::dvec3 s = parse_xyz(op, src, 1.0, true, "<scale>");
        t[0][0] = s.x;
        t[1][1] = s.y;
        t[2][2] = s.z;
      } else if (tag == "rotate") {
        check_attributes(op, src, {"value", "x", "y", "z", "angle"});
        glm::dvec3 axis = parse_xyz(op, src, 0.0, false, "<rotate> axis");
        if (glm::length(axis) == 0.0) fail(loc, "<rotate>: the axis is zero");
        double angle = parse_double(required_attr(op, "angle", src), loc, "<rotate> angle");
        t = rotation(axis, angle);
      } else if (is_lookat_operation(tag, src.below_2_0)) {  // <lookAt> below 2.0.0
        check_attributes(op, src, {"origin", "target", "up"});
        glm::dvec3 origin = parse_vec3_attr(op, "origin", src);
        glm::dvec3 target = parse_vec3_attr(op, "target", src);
        glm::dvec3 up;
        if (has_attr(op, "up")) {
          up = parse_vec3_attr(op, "up", src);
        } else {  // Mitsuba: any vector perpendicular to the view direction
          glm::dvec3 d = glm::normalize(target - origin);
          up = std::abs(d.x) > std::abs(d.z) ? glm::dvec3(-d.y, d.x, 0.0)
                                             : glm::dvec3(0.0, -d.z, d.y);
        }
        t = look_at(origin, target, up, loc);
      } else if (tag == "matrix") {
        check_attributes(op, src, {"value"});
        std::vector<std::string> tokens = split_list(required_attr(op, "value", src));
        std::vector<double> v;
        for (const std::string& s : tokens) v.push_back(parse_double(s, loc, "<matrix>"));
        if (v.size() == 16) {
          for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) t[c][r] = v[r * 4 + c];  // row-major in the file
        } else if (v.size() == 9) {
          // A 3x3 (2D homogeneous) matrix, e.g. for to_uv: rows/columns 0, 1 and 3 of 4x4.
          const int idx[3] = {0, 1, 3};
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) t[idx[c]][idx[r]] = v[r * 3 + c];
        } else {
          fail(loc, "<matrix>: expected 16 (or 9) values, got ", v.size());
        }
      } else {
        fail(loc, "unknown transform operation <", tag, ">");
      }
      m = t * m;
    }
    return m;
  }

  glm::dvec3 parse_spectrum(const pugi::xml_node& x, const Source& src, const std::string& name,
                            bool within_emitter) {
    Location loc = src.at(x);
    SpectrumUse use = unbounded_parameter(read_name(name, src)) ? SpectrumUse::Unbounded
                      : within_emitter                          ? SpectrumUse::Emission
                                                                : SpectrumUse::Reflectance;
    bool has_value = has_attr(x, "value"), has_file = has_attr(x, "filename");
    if (has_value == has_file)
      fail(loc, "<spectrum> requires exactly one of 'value' and 'filename'");
    std::string what = "spectrum '" + name + "'";
    std::vector<double> wavelengths, values;
    if (has_value) {
      std::vector<std::string> tokens = split_list(attr(x, "value", src));
      if (tokens.size() == 1 && tokens[0].find(':') == std::string::npos)
        return constant_spectrum_to_rgb(parse_double(tokens[0], loc, what), use);
      for (const std::string& token : tokens) {
        size_t colon = token.find(':');
        if (colon == std::string::npos || token.find(':', colon + 1) != std::string::npos)
          fail(loc, what, ": expected wavelength:value pairs, got \"", token, "\"");
        wavelengths.push_back(parse_double(token.substr(0, colon), loc, what + " wavelength"));
        values.push_back(parse_double(token.substr(colon + 1), loc, what + " value"));
      }
    } else {
      std::string file_name = attr(x, "filename", src);
      fs::path file = resolver_.resolve(file_name, src.dir);
      if (file.empty()) fail(loc, what, ": spectrum file \"", file_name, "\" not found");
      read_spd(file, loc, wavelengths, values);
    }
    if (wavelengths.size() < 2) fail(loc, what, ": needs at least two wavelength:value pairs");
    for (size_t i = 1; i < wavelengths.size(); ++i)
      if (!(wavelengths[i] > wavelengths[i - 1]))
        fail(loc, what, ": wavelengths must be strictly increasing");
    return spectrum_to_rgb(wavelengths, values, use);
  }

  // Mitsuba's .spd format: one "wavelength value" pair per line, '#' starts a comment.
  static void read_spd(const fs::path& file, const Location& loc, std::vector<double>& wavelengths,
                       std::vector<double>& values) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
      line = line.substr(0, line.find('#'));
      std::vector<std::string> t = split_list(line);
      if (t.empty()) continue;
      if (t.size() != 2) fail(loc, file.string(), ": expected two numbers per line");
      wavelengths.push_back(parse_double(t[0], loc, file.string()));
      values.push_back(parse_double(t[1], loc, file.string()));
    }
  }
};

}  // namespace

ParsedScene parse_scene_xml(const std::string& path, const LoadOptions& options) {
  Parser parser(options);
  return parser.parse(path);
}

}  // namespace tr
