#include "validation/mitsuba/pass_scene.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <pugixml.hpp>
#include <sstream>
#include <vector>

namespace tr {
namespace {

namespace fs = std::filesystem;

// Mitsuba 3.8.0 src/core/parser.cpp refuses deeper include chains (ParserConfig).
constexpr int kMaxIncludeDepth = 15;

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw PassSceneError(where + ": " + what);
}

// One XML file, kept with its text so that node offsets can be turned into line numbers.
struct XmlFile {
  fs::path path;
  std::string text;
  pugi::xml_document doc;

  std::string at(const pugi::xml_node& node) const {
    const ptrdiff_t offset = node.offset_debug();
    // Nodes copied in from an included file have no offset in this file's text.
    if (offset < 0 || size_t(offset) > text.size()) return path.string();
    const size_t line = 1 + std::count(text.begin(), text.begin() + offset, '\n');
    return path.string() + ":" + std::to_string(line);
  }
};

void load(XmlFile& file, const fs::path& path) {
  file.path = path;
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path.string(), "cannot open the file");
  file.text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  pugi::xml_parse_result parsed = file.doc.load_buffer(file.text.data(), file.text.size());
  if (!parsed) fail(path.string(), std::string("XML parse error: ") + parsed.description());
  pugi::xml_node root = file.doc.document_element();
  if (std::strcmp(root.name(), "scene") != 0)
    fail(file.at(root), "the root element is <" + std::string(root.name()) +
                            ">, only <scene> files are supported");
  // Mitsuba upgrades files older than 2.0 one file at a time (parser.cpp, transform_upgrade);
  // inlining such a file would change what is upgraded.
  const std::string version = root.attribute("version").value();
  if (version.empty() || !std::isdigit(static_cast<unsigned char>(version[0])) ||
      std::stoi(version) < 2)
    fail(file.at(root), "scene version '" + version + "' is not supported (2.0.0 or later)");
}

std::vector<pugi::xml_node> elements_named(const pugi::xml_node& parent, const char* name) {
  std::vector<pugi::xml_node> found;
  for (pugi::xml_node child : parent.children(name)) found.push_back(child);
  return found;
}

// Relative <path> folders that exist beside `file` become absolute: Mitsuba looks beside the
// XML file first (parser.cpp, TagType::Path) and the pass scene lives elsewhere.
void make_paths_absolute(XmlFile& file) {
  const fs::path dir = file.path.parent_path();
  for (pugi::xml_node p : elements_named(file.doc.document_element(), "path")) {
    fs::path value(p.attribute("value").value());
    if (!value.is_absolute() && fs::exists(dir / value))
      p.attribute("value").set_value(fs::absolute(dir / value).lexically_normal().c_str());
  }
}

fs::path resolve_include(const XmlFile& file, const pugi::xml_node& include,
                         const fs::path& scene_dir) {
  for (pugi::xml_attribute a : include.attributes())
    if (std::strcmp(a.name(), "filename") != 0)
      fail(file.at(include), std::string("<include> attribute '") + a.name() +
                                 "' is not supported (only scene includes are)");
  const fs::path name(include.attribute("filename").value());
  if (name.empty()) fail(file.at(include), "<include> without a filename");
  if (name.is_absolute()) return name;
  for (const fs::path& dir : {file.path.parent_path(), scene_dir})
    if (fs::exists(dir / name)) return fs::absolute(dir / name).lexically_normal();
  fail(file.at(include), "included file '" + name.string() + "' not found beside " +
                             file.path.parent_path().string() + " or in " + scene_dir.string());
}

// Replaces every <include> below `parent` (a node of `file`'s tree or of the tree the file's
// nodes were copied into) by the children of the included scene.
void inline_includes(pugi::xml_node parent, const XmlFile& file, const fs::path& scene_dir,
                     int depth) {
  for (pugi::xml_node node = parent.first_child(); node;) {
    pugi::xml_node next = node.next_sibling();
    if (node.type() == pugi::node_element && std::strcmp(node.name(), "include") == 0) {
      if (depth >= kMaxIncludeDepth) fail(file.at(node), "includes nest too deeply");
      XmlFile included;
      load(included, resolve_include(file, node, scene_dir));
      make_paths_absolute(included);
      pugi::xml_node root = included.doc.document_element();
      inline_includes(root, included, scene_dir, depth + 1);
      for (pugi::xml_node child : root.children()) parent.insert_copy_before(child, node);
      parent.remove_child(node);
    } else if (node.type() == pugi::node_element) {
      inline_includes(node, file, scene_dir, depth);
    }
    node = next;
  }
}

// `value` with each $name replaced as Mitsuba does: -D values first, then <default>s.
std::string substitute(const std::string& where, const std::string& value,
                       const std::map<std::string, std::string>& params) {
  std::string out;
  for (size_t i = 0; i < value.size();) {
    if (value[i] != '$') {
      out += value[i++];
      continue;
    }
    size_t end = i + 1;
    while (end < value.size() &&
           (std::isalnum(static_cast<unsigned char>(value[end])) || value[end] == '_'))
      ++end;
    const std::string name = value.substr(i + 1, end - i - 1);
    auto it = params.find(name);
    if (it == params.end()) fail(where, "'$" + name + "' has no -D value and no <default>");
    out += it->second;
    i = end;
  }
  return out;
}

// Removes every parameter called `name` from `node` and adds <tag name=name value=value/>.
void set_parameter(pugi::xml_node node, const char* tag, const char* name,
                   const std::string& value) {
  for (pugi::xml_node child = node.first_child(); child;) {
    pugi::xml_node next = child.next_sibling();
    if (child.type() == pugi::node_element &&
        std::strcmp(child.attribute("name").value(), name) == 0)
      node.remove_child(child);
    child = next;
  }
  pugi::xml_node p = node.append_child(tag);
  p.append_attribute("name") = name;
  p.append_attribute("value") = value.c_str();
}

pugi::xml_node only_child(const XmlFile& file, const pugi::xml_node& parent, const char* name) {
  std::vector<pugi::xml_node> found = elements_named(parent, name);
  if (found.size() != 1)
    fail(file.at(parent), "expected exactly one <" + std::string(name) + ">, found " +
                              std::to_string(found.size()) + " (after inlining includes)");
  return found.front();
}

void wrap_integrator_in_moment(const XmlFile& file, pugi::xml_node root,
                               const std::map<std::string, std::string>& params) {
  std::vector<pugi::xml_node> integrators = elements_named(root, "integrator");
  if (integrators.size() > 1)
    fail(file.at(root),
         std::to_string(integrators.size()) + " top-level <integrator>s (after inlining includes)");
  if (integrators.empty()) {
    pugi::xml_node moment = root.append_child("integrator");
    moment.append_attribute("type") = "moment";
    moment.append_child("integrator").append_attribute("type") = "path";
    return;
  }
  pugi::xml_node integrator = integrators.front();
  const std::string type =
      substitute(file.at(integrator), integrator.attribute("type").value(), params);
  if (type == "moment") return;
  pugi::xml_node moment = root.insert_child_before("integrator", integrator);
  moment.append_attribute("type") = "moment";
  moment.append_move(integrator);
}

}  // namespace

std::string pass_scene_xml(const std::string& scene_path, const PassSettings& settings) {
  XmlFile scene;
  load(scene, fs::absolute(scene_path).lexically_normal());
  make_paths_absolute(scene);
  pugi::xml_node root = scene.doc.document_element();
  inline_includes(root, scene, scene.path.parent_path(), 0);

  std::map<std::string, std::string> params = settings.defines;
  for (pugi::xml_node d : elements_named(root, "default"))
    params.emplace(d.attribute("name").value(), d.attribute("value").value());

  wrap_integrator_in_moment(scene, root, params);

  pugi::xml_node sensor = only_child(scene, root, "sensor");
  pugi::xml_node film = only_child(scene, sensor, "film");
  const std::string film_type = substitute(scene.at(film), film.attribute("type").value(), params);
  if (film_type != "hdrfilm")
    fail(scene.at(film), "film type '" + film_type + "' is not supported (hdrfilm)");
  for (pugi::xml_node p : film.children())
    if (std::strcmp(p.attribute("name").value(), "file_format") == 0) {
      const std::string format = substitute(scene.at(p), p.attribute("value").value(), params);
      if (format != "openexr" && format != "exr")
        fail(scene.at(p), "file_format '" + format + "': the passes must be OpenEXR files");
    }
  set_parameter(film, "string", "component_format", "float32");

  pugi::xml_node sampler = only_child(scene, sensor, "sampler");
  set_parameter(sampler, "integer", "seed", std::to_string(settings.seed));
  set_parameter(sampler, "integer", "sample_count", std::to_string(settings.spp));

  std::ostringstream out;
  scene.doc.save(out, "    ");
  return out.str();
}

}  // namespace tr
