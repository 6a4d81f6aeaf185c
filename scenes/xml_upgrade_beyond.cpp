#include "scenes/xml_upgrade_beyond.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace tr {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string value_text(const Property& p) {
  std::ostringstream out;
  switch (p.kind) {
    case PropertyKind::Boolean:
      out << (p.boolean ? "true" : "false");
      break;
    case PropertyKind::Integer:
      out << p.integer;
      break;
    case PropertyKind::Float:
      out << p.number;
      break;
    case PropertyKind::String:
      out << '"' << p.text << '"';
      break;
    default:
      out << "(" << kind_name(p.kind) << ")";
  }
  return out.str();
}

// What one file gets: its first line concerned and the notes of its warning.
struct FileNotes {
  Location first;
  std::vector<std::string> notes;
};

class Upgrade {
 public:
  std::vector<FileNotes> files;

  void note(const Location& loc, const std::string& text) {
    auto it = std::find_if(files.begin(), files.end(),
                           [&](const FileNotes& f) { return f.first.file == loc.file; });
    if (it == files.end()) it = files.insert(files.end(), FileNotes{loc, {}});
    if (loc.line < it->first.line) it->first = loc;
    it->notes.push_back(text + " (line " + std::to_string(loc.line) + ")");
  }

  // Rule 2: ldrfilm as hdrfilm; output-only parameters dropped and named.
  void film(Node& film) {
    bool ldr = film.type == "ldrfilm";
    std::vector<std::string> dropped;
    auto output_only = [&](const Property& p) {
      if (ldr) {
        static const std::set<std::string> names = {"file_format", "pixel_format", "tonemap_method",
                                                    "gamma",       "exposure",     "key",
                                                    "burn",        "banner"};
        return names.count(p.name) > 0;
      }
      std::string v = p.kind == PropertyKind::String ? lower(p.text) : "";
      return (p.name == "file_format" && v != "openexr" && v != "exr") ||
             (p.name == "pixel_format" && v != "rgb") ||
             (p.name == "component_format" && v != "float16" && v != "float32") ||
             p.name == "attach_log" || p.name == "channel_names";
    };
    for (const Property& p : film.props)
      if (output_only(p) && !(p.name == "banner" && p.kind == PropertyKind::Boolean && !p.boolean))
        dropped.push_back(p.name + " " + value_text(p));
    film.props.erase(std::remove_if(film.props.begin(), film.props.end(), output_only),
                     film.props.end());
    std::string text;
    if (ldr) {
      film.type = "hdrfilm";
      text = "<film type=\"ldrfilm\"> read as an hdrfilm";
    }
    if (!dropped.empty()) {
      std::string list;
      for (const std::string& d : dropped) list += (list.empty() ? "" : ", ") + d;
      text += std::string(text.empty() ? "" : "; ") + "not applied (they shape only the image " +
              "file; twinray writes linear EXR and an sRGB PNG preview): " + list;
    }
    if (!text.empty()) note(film.loc, text);
    // Rule 3.
    if (Property* p = find_property(film, "high_quality_edges")) {
      if (const Property* given = find_property(film, "sample_border"))
        fail(given->loc, "parameter 'sample_border' of ", describe(film),
             " is specified twice: highQualityEdges (line ", p->loc.line,
             ") is Mitsuba 3's sample_border");
      p->name = "sample_border";
    }
  }

  // Rule 5: Mitsuba 0.6's (rough)conductor divides eta and k by extEta.
  static void conductor(Node& bsdf) {
    Property* ext = find_property(bsdf, "ext_eta");
    if (!ext || ext->kind != PropertyKind::Float) return;  // an IOR name stays unread
    double ext_eta = ext->number;
    Property* eta = find_property(bsdf, "eta");
    Property* k = find_property(bsdf, "k");
    auto constant = [](const Property* p) {
      return p && (p->kind == PropertyKind::Float || p->kind == PropertyKind::Color);
    };
    if (ext_eta != 1.0) {
      if (!constant(eta) || !constant(k) || !(ext_eta > 0.0))
        fail(ext->loc, "extEta ", ext_eta, " of ", describe(bsdf),
             " is not supported: Mitsuba 0.6 divides eta and k by it, which twinray does only "
             "for a positive extEta with eta and k given as numbers or colours");
      eta->number /= ext_eta;
      eta->vec /= ext_eta;
      k->number /= ext_eta;
      k->vec /= ext_eta;
    }
    bsdf.props.erase(bsdf.props.begin() + (ext - bsdf.props.data()));
  }

  // Rule 4: strictNormals false dropped; true dropped and returned for the whole-scene check.
  const Property* integrator(Node& integrator, Property& kept) {
    Property* p = find_property(integrator, "strict_normals");
    if (!p) return nullptr;
    if (p->kind != PropertyKind::Boolean)
      fail(p->loc, "parameter 'strictNormals' of ", describe(integrator), " must be a boolean");
    bool strict = p->boolean;
    kept = *p;
    integrator.props.erase(integrator.props.begin() + (p - integrator.props.data()));
    return strict ? &kept : nullptr;
  }
};

// The first object of the scene whose shading normals may differ from its geometric normals:
// a mesh without face_normals = true (Mitsuba 3 interpolates the file's or computed vertex
// normals), a bumpmap or normalmap, or a shape that twinray does not know to be flat-shaded.
const Node* shading_normals(const Node& node, std::set<const Node*>& seen) {
  if (!seen.insert(&node).second) return nullptr;
  static const std::set<std::string> flat = {"rectangle", "cube",       "sphere",  "disk",
                                             "cylinder",  "shapegroup", "instance"};
  static const std::set<std::string> meshes = {"obj", "ply", "serialized"};
  if (node.tag == "bsdf" && (node.type == "bumpmap" || node.type == "normalmap")) return &node;
  if (node.tag == "shape" && !flat.count(node.type)) {
    if (!meshes.count(node.type)) return &node;
    const Property* fn = nullptr;
    for (const Property& p : node.props)
      if (p.name == "face_normals") fn = &p;
    if (!fn || fn->kind != PropertyKind::Boolean || !fn->boolean) return &node;
  }
  for (const Property& p : node.props)
    if (p.kind == PropertyKind::Object && p.object)
      if (const Node* n = shading_normals(*p.object, seen)) return n;
  return nullptr;
}

}  // namespace

bool is_lookat_operation(const std::string& tag, bool below_2_0) {
  return tag == "lookat" || (below_2_0 && tag == "lookAt");
}

std::vector<std::string> upgrade_beyond_mitsuba_3_8(const std::vector<Node*>& upgraded,
                                                    const Node& root) {
  Upgrade u;
  std::vector<Property> strict(upgraded.size());
  const Property* first_strict = nullptr;
  for (size_t i = 0; i < upgraded.size(); ++i) {
    Node& node = *upgraded[i];
    if (node.tag == "film") u.film(node);
    if (node.tag == "bsdf" && (node.type == "conductor" || node.type == "roughconductor"))
      Upgrade::conductor(node);
    if (node.tag == "integrator") {
      const Property* s = u.integrator(node, strict[i]);
      if (s && !first_strict) first_strict = s;
      if (s)
        u.note(s->loc,
               "strictNormals true not applied: every shape's shading normal is its "
               "geometric normal, so it changes only paths of measure zero");
    }
  }
  if (first_strict) {
    std::set<const Node*> seen;
    if (const Node* n = shading_normals(root, seen))
      fail(first_strict->loc,
           "strictNormals true is not supported: Mitsuba 0.6 then drops the paths on which a "
           "shading normal and the geometric normal put a direction on different sides, which "
           "twinray's integrators do not do, and ",
           describe(*n), " at ", to_string(n->loc),
           n->tag == "bsdf" ? " perturbs" : " has (or may have) interpolated", " shading normals");
  }
  std::vector<std::string> warnings;
  for (const FileNotes& f : u.files) {
    std::string w = to_string(f.first) + ": beyond Mitsuba 3.8's upgrade of this 0.x file: ";
    for (size_t i = 0; i < f.notes.size(); ++i) w += (i ? "; " : "") + f.notes[i];
    warnings.push_back(w);
  }
  return warnings;
}

}  // namespace tr
