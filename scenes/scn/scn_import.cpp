#include "scenes/scn/scn_import.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "scenes/json_node_builder.h"
#include "scenes/scn/obj_submeshes.h"

namespace tr {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The -D names a .scn scene takes (its film, sample count and path length), as XML <default>s.
const char* const kParameterNames[] = {"width", "height", "spp", "max_depth"};
// A .scn scene has no sample count; this one is documented in scenes/README.md.
const long long kDefaultSpp = 64;

// Material fields that make the material `principled` (only `color` and `emission`: `diffuse`).
const char* const kPrincipledFields[] = {"metallic",     "roughness",   "opacity", "ior",
                                         "speculartint", "anisotropic", "sheen",   "sheentint"};

class Importer : JsonNodeBuilder {
 public:
  Importer(const std::string& path, const LoadOptions& options, const fs::path& mesh_dir,
           const std::string& mesh_prefix, bool relative_names)
      : JsonNodeBuilder(path),
        options_(options),
        mesh_dir_(mesh_dir),
        mesh_prefix_(mesh_prefix),
        relative_names_(relative_names) {}

  ScnScene run() {
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec))
      throw SceneError(path_ + ":0: scene file not found or not a regular file");
    std::ifstream in(path_, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    doc_ = parse_document(s);
    if (!doc_.is_object()) bad("", "expected a JSON object, not ", doc_.type_name());

    fs::path dir = fs::path(path_).parent_path();
    for (const std::string& p : options_.search_paths) out_.parsed.resolver.dirs.push_back(p);
    out_.parsed.resolver.dirs.push_back(dir.empty() ? fs::path(".") : dir);
    root_ = std::make_shared<Node>();
    root_->tag = "scene";
    root_->loc = at("");
    out_.parsed.root = root_;

    known(doc_, "", {"resolution", "maxdepth", "camera", "materials", "entities"});
    read_parameters();
    read_materials();
    read_entities();
    add_sensor();
    add_integrator();
    for (const auto& [name, m] : materials_)
      if (!used_.count(name))
        warn(m.pointer, "material \"", name, "\" is used by no entity and no usemtl group");
    out_.warnings = take_warnings();
    return std::move(out_);
  }

 private:
  struct Material {
    std::string pointer;
    json fields;
    NodePtr bsdf;  // made when first used
  };

  // --- messages ---

  // Warns about every field of object `o` not in `names`; `what` says why it is not read.
  void known(const json& o, const std::string& pointer, std::set<std::string> names,
             const std::string& what = "unknown field") {
    for (const auto& [key, value] : o.items())
      if (!names.count(key)) warn(pointer + "/" + key, what, ", ignored");
  }

  // --- typed reads ---

  long long integer(const json& v, const std::string& pointer) const {
    if (!v.is_number_integer()) bad(pointer, "expected an integer, not ", v.type_name());
    return v.get<long long>();
  }

  glm::dvec3 vec3(const json& v, const std::string& pointer) const {
    if (!v.is_array() || v.size() != 3) bad(pointer, "expected an array of 3 numbers");
    return {number(v[0], pointer + "/0"), number(v[1], pointer + "/1"),
            number(v[2], pointer + "/2")};
  }

  // --- node tree ---

  // An integer property that -D `name` may override; `value` is the .scn's.
  void add_parameter(Node& n, const std::string& property, const std::string& name, long long value,
                     const std::string& pointer) {
    auto d = options_.defines.find(name);
    if (d != options_.defines.end()) {
      size_t used = 0;
      try {
        value = std::stoll(d->second, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != d->second.size())
        fail(at(""), "-D ", name, "=", d->second, ": expected an integer");
    }
    add(n, property, PropertyKind::Integer, pointer).integer = value;
    out_.parameters.push_back({name, std::to_string(value), &n, property});
  }

  // --- the scene ---

  void read_parameters() {
    for (const auto& [name, value] : options_.defines) {
      bool known_name = false;
      for (const char* p : kParameterNames) known_name = known_name || name == p;
      if (!known_name && !options_.unused_defines_allowed)
        fail(at(""), "-D ", name, "=", value,
             " is not used: a .scn scene takes -D width, height, spp and max_depth");
    }
  }

  void add_sensor() {
    if (!doc_.contains("camera")) bad("", "\"camera\" is required");
    const json& c = object(doc_["camera"], "/camera");
    known(c, "/camera", {"position", "lookat", "fov", "antialiasing_radius"});
    for (const char* required : {"position", "lookat", "fov"})
      if (!c.contains(required)) bad("/camera", "\"", required, "\" is required");
    glm::dvec3 position = vec3(c["position"], "/camera/position");
    glm::dvec3 target = vec3(c["lookat"], "/camera/lookat");
    double fov = number(c["fov"], "/camera/fov");
    if (!(fov > 0.0 && fov < 180.0)) bad("/camera/fov", "must be in (0, 180) degrees");

    NodePtr sensor = make("sensor", "perspective", "/camera");
    add_float(*sensor, "fov", fov, "/camera/fov");
    add(*sensor, "fov_axis", PropertyKind::String, "/camera/fov").text = "y";  // vertical fov
    // The .scn camera has no up vector: +y, the up axis of the seed scenes' models.
    add_transform(*sensor, look_at(position, target, {0.0, 1.0, 0.0}, at("/camera")), "/camera");

    NodePtr film = make("film", "hdrfilm", "/resolution");
    long long width = 768, height = 576;  // Mitsuba's hdrfilm defaults
    if (doc_.contains("resolution")) {
      const json& r = doc_["resolution"];
      if (!r.is_array() || r.size() != 2) bad("/resolution", "expected [width, height]");
      width = integer(r[0], "/resolution/0");
      height = integer(r[1], "/resolution/1");
    }
    add_parameter(*film, "width", "width", width, "/resolution");
    add_parameter(*film, "height", "height", height, "/resolution");
    add(*film, "component_format", PropertyKind::String, "/resolution").text = "float32";
    NodePtr rfilter;
    if (c.contains("antialiasing_radius")) {
      double r = number(c["antialiasing_radius"], "/camera/antialiasing_radius");
      if (!(r > 0.0)) bad("/camera/antialiasing_radius", "must be positive");
      rfilter = make("rfilter", "tent", "/camera/antialiasing_radius");
      add_float(*rfilter, "radius", r, "/camera/antialiasing_radius");
      warn("/camera/antialiasing_radius",
           "approximate: a tent filter of this radius in pixels (the .scn renderer's sample "
           "spread over the radius is not specified)");
    } else {
      rfilter = make("rfilter", "box", "/camera");  // one uniform sample position per pixel
    }
    add_object(*film, rfilter, "/camera");
    add_object(*sensor, film, "/resolution");

    NodePtr sampler = make("sampler", "independent", "/camera");
    add_parameter(*sampler, "sample_count", "spp", kDefaultSpp, "/camera");
    add_object(*sensor, sampler, "/camera");
    add_object(*root_, sensor, "/camera");
  }

  void add_integrator() {
    NodePtr path = make("integrator", "path", "/maxdepth");
    long long depth = -1;  // Mitsuba's default: unbounded
    if (doc_.contains("maxdepth")) depth = integer(doc_["maxdepth"], "/maxdepth");
    add_parameter(*path, "max_depth", "max_depth", depth, "/maxdepth");
    add_object(*root_, path, "/maxdepth");
  }

  void read_materials() {
    if (!doc_.contains("materials")) return;
    const json& list = doc_["materials"];
    if (!list.is_array()) bad("/materials", "expected an array, not ", list.type_name());
    for (size_t i = 0; i < list.size(); ++i) {
      std::string pointer = "/materials/" + std::to_string(i);
      const json& m = object(list[i], pointer);
      if (!m.contains("name")) bad(pointer, "\"name\" is required");
      std::string name = text(m["name"], pointer + "/name");
      if (materials_.count(name))
        bad(pointer + "/name", "material \"", name, "\" is defined twice");
      check_material(m, pointer);
      materials_[name] = Material{pointer, m, nullptr};
    }
  }

  static bool is_texture_field(const std::string& key) {
    return key.size() > 7 && key.compare(key.size() - 7, 7, "texture") == 0;
  }

  // The texture map fields of material `m` whose base field has a twinray parameter.
  std::vector<std::string> texture_fields(const json& m) const {
    std::vector<std::string> out;
    for (const auto& [key, value] : m.items())
      if (is_texture_field(key) && !mitsuba_parameter(key.substr(0, key.size() - 7), m).empty())
        out.push_back(key);
    return out;
  }

  // The Mitsuba parameter that .scn field `base` of material `m` sets (empty: none).
  static std::string mitsuba_parameter(const std::string& base, const json& m) {
    if (base == "color") return is_principled(m) ? "base_color" : "reflectance";
    for (const char* scalar : {"metallic", "roughness", "anisotropic", "sheen"})
      if (base == scalar) return base;
    if (base == "speculartint") return "spec_tint";
    if (base == "sheentint") return "sheen_tint";
    return "";
  }

  static bool is_principled(const json& m) {
    for (const char* k : kPrincipledFields)
      if (m.contains(k) || m.contains(std::string(k) + "texture")) return true;
    return false;
  }

  glm::dvec2 tiling(const json& v, const std::string& pointer) const {
    glm::dvec2 t = v.is_array() && v.size() == 2
                       ? glm::dvec2(number(v[0], pointer + "/0"), number(v[1], pointer + "/1"))
                   : v.is_number() ? glm::dvec2(number(v, pointer))
                                   : (bad(pointer, "expected a number or [u, v]"), glm::dvec2());
    if (t.x == 0.0 || t.y == 0.0) bad(pointer, "must not be 0");
    return t;
  }

  // The file an image name of the .scn names (searched as mesh files are).
  fs::path image_path(const std::string& name, const std::string& pointer) const {
    fs::path fallback = fs::path(path_).parent_path();
    fs::path file = out_.parsed.resolver.resolve(name, fallback.empty() ? "." : fallback);
    if (file.empty()) bad(pointer, "image file \"", name, "\" not found");
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) bad(pointer, file.string(), ": not a regular file");
    return file;
  }

  // The image copied once into mesh_dir (so that convert's XML finds it beside itself); returns
  // the name the bitmap texture reads.
  std::string image_file(const std::string& name, const std::string& pointer) {
    fs::path file = image_path(name, pointer);
    std::string key = fs::weakly_canonical(file).string();
    auto it = images_.find(key);
    if (it != images_.end()) return it->second;
    fs::path copy = mesh_dir_ / (mesh_prefix_ + "_image" + std::to_string(images_.size()) + "_" +
                                 file.filename().string());
    std::error_code ec;
    fs::copy_file(file, copy, fs::copy_options::overwrite_existing, ec);
    if (ec) bad(pointer, "cannot copy ", file.string(), " to ", copy.string(), ": ", ec.message());
    return images_[key] = relative_names_ ? copy.filename().string() : copy.string();
  }

  // Types and ranges of every field (also of materials nothing uses), and the warnings.
  void check_material(const json& m, const std::string& pointer) {
    for (const auto& [key, value] : m.items()) {
      std::string p = pointer + "/" + key;
      if (key == "name") continue;
      if (key == "color" || key == "emission") {
        glm::dvec3 v = vec3(value, p);
        if (glm::any(glm::lessThan(v, glm::dvec3(0.0))) ||
            (key == "color" && glm::any(glm::greaterThan(v, glm::dvec3(1.0)))))
          bad(p, key == "color" ? "components must be in [0, 1]" : "components must be >= 0");
      } else if (key == "opacity" || key == "metallic" || key == "roughness" ||
                 key == "speculartint" || key == "anisotropic" || key == "sheen" ||
                 key == "sheentint" || key == "subsurface") {
        double v = number(value, p);
        if (v < 0.0 || v > 1.0) bad(p, "must be in [0, 1]");
        if (key == "subsurface" && v != 0.0)
          warn(p, "unsupported: Mitsuba's principled has no subsurface lobe; ignored");
      } else if (key == "ior") {
        if (!(number(value, p) > 0.0)) bad(p, "must be positive");
      } else if (key == "tiling") {
        tiling(value, p);
        if (texture_fields(m).empty() && !m.contains("normaltexture"))
          warn(p, "ignored: the material has no texture map it would scale");
      } else if (is_texture_field(key)) {
        std::string base = key.substr(0, key.size() - 7);
        std::string name = text(value, p);
        if (base == "normal") {
          image_path(name, p);
          warn(p,
               "approximate: read as Mitsuba's normalmap, a tangent-space map with +y along "
               "the texture's v (OpenGL convention), in the frame of the mesh's uv");
        } else if (!mitsuba_parameter(base, m).empty()) {
          image_path(name, p);
          if (m.contains(base))
            warn(pointer + "/" + base, "ignored: ", key,
                 " gives this parameter (the value is not a factor of the map)");
        } else {
          warn(p, "unsupported: no twinray parameter takes a map of '", base, "'; ignored");
        }
      } else {
        warn(p, "unknown field, ignored");
      }
    }
  }

  // A bitmap texture of map field `key` of material `m`: `raw` (linear) unless a colour map,
  // which is sRGB-encoded; scaled by the material's tiling.
  NodePtr bitmap(const Material& m, const std::string& key, bool raw) {
    std::string p = m.pointer + "/";
    NodePtr t = make("texture", "bitmap", p + key);
    add(*t, "filename", PropertyKind::String, p + key).text =
        image_file(m.fields[key].get<std::string>(), p + key);
    if (raw) add(*t, "raw", PropertyKind::Boolean, p + key).boolean = true;
    if (m.fields.contains("tiling")) {
      glm::dvec2 k = tiling(m.fields["tiling"], p + "tiling");
      add(*t, "to_uv", PropertyKind::Transform, p + "tiling").matrix =
          glm::scale(glm::dmat4(1.0), glm::dvec3(k, 1.0));
    }
    return t;
  }

  NodePtr bsdf(Material& m) {
    if (m.bsdf) return m.bsdf;
    const json& f = m.fields;
    bool principled = is_principled(f);
    m.bsdf = make("bsdf", principled ? "principled" : "diffuse", m.pointer);
    m.bsdf->id = f["name"].get<std::string>();
    Node& n = *m.bsdf;
    std::string p = m.pointer + "/";
    std::vector<std::string> maps = texture_fields(f);
    auto mapped = [&](const std::string& base) {
      return std::find(maps.begin(), maps.end(), base + "texture") != maps.end();
    };
    if (f.contains("color") && !mapped("color"))
      add_color(n, mitsuba_parameter("color", f), vec3(f["color"], p + "color"), p + "color");
    if (principled) {
      for (const char* scn :
           {"metallic", "roughness", "speculartint", "anisotropic", "sheen", "sheentint"})
        if (f.contains(scn) && !mapped(scn))
          add_float(n, mitsuba_parameter(scn, f), f[scn].get<double>(), p + scn);
      if (f.contains("opacity"))
        add_float(n, "spec_trans", 1.0 - f["opacity"].get<double>(), p + "opacity");
      if (f.contains("ior")) add_float(n, "eta", f["ior"].get<double>(), p + "ior");
    }
    for (const std::string& key : maps) {
      std::string base = key.substr(0, key.size() - 7);
      add(n, mitsuba_parameter(base, f), PropertyKind::Object, p + key).object =
          bitmap(m, key, base != "color");
    }
    if (f.contains("normaltexture")) {  // Mitsuba's normalmap BSDF around the material
      NodePtr outer = make("bsdf", "normalmap", m.pointer);
      std::swap(outer->id, m.bsdf->id);
      add(*outer, "normalmap", PropertyKind::Object, p + "normaltexture").object =
          bitmap(m, "normaltexture", true);
      add_object(*outer, m.bsdf, m.pointer);
      m.bsdf = outer;
    }
    add_object(*root_, m.bsdf, m.pointer);
    return m.bsdf;
  }

  // A material that only emits (fields name and emission) gets no BSDF: the shape keeps
  // Mitsuba's luminaire default, diffuse of reflectance 0 (Mitsuba 3.8 shape.cpp).
  static bool only_emits(const json& f) {
    for (const auto& [key, value] : f.items())
      if (key != "name" && key != "emission") return false;
    return f.contains("emission");
  }

  // Gives shape `s` the material `name` (its BSDF and, when it emits, an area emitter).
  void attach(Node& s, const std::string& name, const std::string& pointer) {
    Material& m = materials_.at(name);
    used_.insert(name);
    if (!only_emits(m.fields)) add_object(s, bsdf(m), pointer);
    if (m.fields.contains("emission")) {
      glm::dvec3 e = vec3(m.fields["emission"], m.pointer + "/emission");
      if (e == glm::dvec3(0.0)) return;
      NodePtr area = make("emitter", "area", m.pointer + "/emission");
      add_color(*area, "radiance", e, m.pointer + "/emission");
      add_object(s, area, pointer);
    }
  }

  // to_world = T(position) Rx Ry Rz S(scale): scale, then rotate about z, y and x (degrees, the
  // order of the glm::rotate chain x, y, z on a model matrix), then translate.
  glm::dmat4 entity_transform(const json& e, const std::string& pointer) {
    glm::dmat4 m(1.0);
    if (e.contains("position")) m = glm::translate(m, vec3(e["position"], pointer + "/position"));
    if (e.contains("rotation")) {
      glm::dvec3 r = vec3(e["rotation"], pointer + "/rotation");
      if ((r.x != 0.0) + (r.y != 0.0) + (r.z != 0.0) > 1)
        warn(pointer + "/rotation",
             "approximate: rotations about several axes are applied z, then y, then x "
             "(to_world = T Rx Ry Rz S); the .scn format does not specify the order");
      m = glm::rotate(m, glm::radians(r.x), glm::dvec3(1, 0, 0));
      m = glm::rotate(m, glm::radians(r.y), glm::dvec3(0, 1, 0));
      m = glm::rotate(m, glm::radians(r.z), glm::dvec3(0, 0, 1));
    }
    if (e.contains("scale")) {
      const json& s = e["scale"];
      glm::dvec3 v =
          s.is_array() ? vec3(s, pointer + "/scale") : glm::dvec3(number(s, pointer + "/scale"));
      if (v.x == 0.0 || v.y == 0.0 || v.z == 0.0) bad(pointer + "/scale", "must not be 0");
      m = glm::scale(m, v);
    }
    return m;
  }

  void read_entities() {
    if (!doc_.contains("entities")) return;
    const json& list = doc_["entities"];
    if (!list.is_array()) bad("/entities", "expected an array, not ", list.type_name());
    for (size_t i = 0; i < list.size(); ++i) {
      std::string pointer = "/entities/" + std::to_string(i);
      const json& e = object(list[i], pointer);
      if (!e.contains("type")) bad(pointer, "\"type\" is required (mesh or sphere)");
      std::string type = text(e["type"], pointer + "/type");
      std::string material;
      if (e.contains("material")) {
        material = text(e["material"], pointer + "/material");
        if (!materials_.count(material))
          bad(pointer + "/material", "no material named \"", material, "\"");
      }
      glm::dmat4 to_world = entity_transform(e, pointer);
      if (type == "sphere") {
        known(e, pointer, {"type", "position", "rotation", "scale", "radius", "material"},
              "not a field of a sphere entity");
        NodePtr s = make("shape", "sphere", pointer);
        if (e.contains("radius")) {
          double r = number(e["radius"], pointer + "/radius");
          if (!(r > 0.0)) bad(pointer + "/radius", "must be positive");
          add_float(*s, "radius", r, pointer + "/radius");
        }
        if (to_world != glm::dmat4(1.0)) add_transform(*s, to_world, pointer);
        if (!material.empty()) attach(*s, material, pointer + "/material");
        add_object(*root_, s, pointer);
      } else if (type == "mesh") {
        known(e, pointer, {"type", "file", "position", "rotation", "scale", "material"},
              "not a field of a mesh entity");
        add_mesh(e, i, pointer, material, to_world);
      } else {
        bad(pointer + "/type", "unknown entity type \"", type, "\" (mesh or sphere)");
      }
    }
  }

  void add_mesh(const json& e, size_t index, const std::string& pointer,
                const std::string& material, const glm::dmat4& to_world) {
    if (!e.contains("file")) bad(pointer, "\"file\" is required for a mesh");
    std::string file_pointer = pointer + "/file";
    std::string name = text(e["file"], file_pointer);
    fs::path fallback = fs::path(path_).parent_path();
    fs::path file = out_.parsed.resolver.resolve(name, fallback.empty() ? "." : fallback);
    if (file.empty()) bad(file_pointer, "mesh file \"", name, "\" not found");
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) bad(file_pointer, file.string(), ": not a regular file");
    std::vector<ObjSubmesh> groups;
    try {
      groups =
          write_obj_submeshes(file.string(), mesh_dir_, mesh_prefix_ + "_" + std::to_string(index));
    } catch (const std::exception& x) {
      bad(file_pointer, file.string(), ": ", x.what());
    }
    std::set<std::string> reported;
    for (const ObjSubmesh& g : groups) {
      NodePtr s = make("shape", "ply", pointer);
      add(*s, "filename", PropertyKind::String, file_pointer).text =
          relative_names_ ? g.ply_file.filename().string() : g.ply_file.string();
      // OBJ faces without `vn` are flat: Mitsuba would smooth them across shared vertices.
      if (!g.has_normals)
        add(*s, "face_normals", PropertyKind::Boolean, file_pointer).boolean = true;
      // OBJ's v runs up the image; flipped as Mitsuba's obj plugin flips it by default.
      if (g.has_uv) add(*s, "flip_tex_coords", PropertyKind::Boolean, file_pointer).boolean = true;
      if (to_world != glm::dmat4(1.0)) add_transform(*s, to_world, pointer);
      std::string m = material.empty() ? g.material : material;
      if (materials_.count(m)) {
        attach(*s, m, material.empty() ? file_pointer : pointer + "/material");
      } else if (reported.insert(m).second) {
        warn(file_pointer, "usemtl \"", m, "\" of ", name,
             " has no .scn material: twinray's default (diffuse 0.5; MTL values are not read)");
      }
      add_object(*root_, s, pointer);
    }
  }

  const LoadOptions& options_;
  fs::path mesh_dir_;
  std::string mesh_prefix_;
  bool relative_names_;
  json doc_;
  ScnScene out_;
  NodePtr root_;
  std::map<std::string, Material> materials_;
  std::set<std::string> used_;
  std::map<std::string, std::string> images_;  // canonical path -> the name bitmaps read
};

}  // namespace

ScnScene import_scn(const std::string& path, const LoadOptions& options, const fs::path& mesh_dir,
                    const std::string& mesh_prefix, bool relative_names) {
  return Importer(path, options, mesh_dir, mesh_prefix, relative_names).run();
}

}  // namespace tr
