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

// What one file gets: its first line concerned and the notes of its warning, each with the
// lines it is about (a note repeated on several lines is said once).
struct FileNotes {
  Location first;
  std::vector<std::pair<std::string, std::vector<int>>> notes;
};

class Upgrade {
 public:
  std::vector<FileNotes> files;

  void note(const Location& loc, const std::string& text) {
    auto it = std::find_if(files.begin(), files.end(),
                           [&](const FileNotes& f) { return f.first.file == loc.file; });
    if (it == files.end()) it = files.insert(files.end(), FileNotes{loc, {}});
    if (loc.line < it->first.line) it->first = loc;
    auto same = std::find_if(it->notes.begin(), it->notes.end(),
                             [&](const auto& n) { return n.first == text; });
    if (same == it->notes.end()) same = it->notes.insert(it->notes.end(), {text, {}});
    same->second.push_back(loc.line);
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

  // Rule 6: a bitmap's filter names in any case; its MIP-map filters, trilinear and ewa (0.6's
  // default), sampled bilinearly, and ewa's max_anisotropy dropped.
  void bitmap(Node& texture) {
    if (Property* f = find_property(texture, "filter_type"); f && f->kind == PropertyKind::String) {
      std::string v = lower(f->text);
      if (v == "trilinear" || v == "ewa") {
        note(f->loc, "filter_type \"" + f->text + "\" read as \"bilinear\"");
        v = "bilinear";
      }
      f->text = v;
    }
    Property* a = find_property(texture, "max_anisotropy");
    if (a && (a->kind == PropertyKind::Float || a->kind == PropertyKind::Integer)) {
      note(a->loc, "max_anisotropy " + value_text(*a) + " dropped (only ewa reads it)");
      texture.props.erase(texture.props.begin() + (a - texture.props.data()));
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
};

}  // namespace

bool is_lookat_operation(const std::string& tag, bool below_2_0) {
  return tag == "lookat" || (below_2_0 && tag == "lookAt");
}

std::vector<std::string> upgrade_beyond_mitsuba_3_8(const std::vector<Node*>& upgraded) {
  Upgrade u;
  // Rule 4 needs nothing here: Mitsuba 3.8's upgrade has renamed strictNormals strict_normals.
  for (Node* n : upgraded) {
    Node& node = *n;
    if (node.tag == "film") u.film(node);
    if (node.tag == "texture" && node.type == "bitmap") u.bitmap(node);
    if (node.tag == "bsdf" && (node.type == "conductor" || node.type == "roughconductor"))
      Upgrade::conductor(node);
  }
  std::vector<std::string> warnings;
  for (const FileNotes& f : u.files) {
    std::string w = to_string(f.first) + ": beyond Mitsuba 3.8's upgrade of this 0.x file: ";
    for (size_t i = 0; i < f.notes.size(); ++i) {
      const std::vector<int>& lines = f.notes[i].second;
      w += (i ? "; " : "") + f.notes[i].first + (lines.size() == 1 ? " (line " : " (lines ");
      for (size_t k = 0; k < lines.size(); ++k) w += (k ? ", " : "") + std::to_string(lines[k]);
      w += ")";
    }
    warnings.push_back(w);
  }
  return warnings;
}

}  // namespace tr
