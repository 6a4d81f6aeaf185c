#include "scenes/gltf/gltf_import.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include "scenes/assimp/imported_ply.h"
#include "scenes/bitmap.h"
#include "scenes/gltf/gltf_accessors.h"
#include "scenes/gltf/gltf_buffers.h"
#include "scenes/gltf/gltf_field_error.h"
#include "scenes/gltf/gltf_tangents.h"
#include "scenes/json_node_builder.h"

namespace tr {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const char* const kParameterNames[] = {"width", "height", "spp", "max_depth"};
const long long kDefaultSpp = 64;
const long long kDefaultHeight = 576;  // Mitsuba's hdrfilm default height
const long long kDefaultWidth = 768;   // ... and width, when the camera gives no aspect ratio
const double kAutoYfov = 45.0;         // degrees: --camera auto's vertical field of view

// Extensions whose fields are read (the others are reported).
const std::set<std::string> kSupportedExtensions = {
    "KHR_lights_punctual",   "KHR_materials_transmission",
    "KHR_materials_ior",     "KHR_materials_emissive_strength",
    "KHR_texture_transform", "KHR_mesh_quantization"};

// glTF 2.0 spec, mesh.primitive.mode: the topology of a primitive.
const int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

// What a baked texture holds (glTF 2.0 spec, "Materials": the channels each material map uses).
enum class Bake { Color, Red, Green, Blue, Alpha, Normal };

class Importer : JsonNodeBuilder {
 public:
  Importer(const std::string& path, const LoadOptions& options, const fs::path& work_dir)
      : JsonNodeBuilder(path), options_(options), work_(work_dir) {
    strict_ = options.strict_gltf;
  }

  GltfScene run() {
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec))
      throw SceneError(path_ + ":0: scene file not found or not a regular file");
    dir_ = fs::path(path_).parent_path();
    if (dir_.empty()) dir_ = ".";
    std::string text = read_document();
    doc_ = parse_document(text);
    if (!doc_.is_object()) bad("", "expected a JSON object, not ", doc_.type_name());
    for (const std::string& p : options_.search_paths) out_.parsed.resolver.dirs.push_back(p);
    out_.parsed.resolver.dirs.push_back(dir_);
    buffers_ = std::make_unique<GltfBuffers>(
        doc_, [this](const std::string& name) { return out_.parsed.resolver.resolve(name, dir_); },
        std::move(glb_bin_), have_glb_bin_);
    accessors_ = std::make_unique<GltfAccessors>(doc_, *buffers_);
    try {
      check_asset();
      read_parameters();
      root_ = std::make_shared<Node>();
      root_->tag = "scene";
      root_->loc = at("");
      out_.parsed.root = root_;

      report_top_level();
      read_lights();
      walk_scene();
      add_sensor();
      add_integrator();
    } catch (const GltfFieldError& e) {
      bad(e.pointer, e.what());
    }
    out_.warnings = take_warnings();
    return std::move(out_);
  }

 private:
  // --- messages ---

  // Warns about each field of `o` not in `names` (`extensions` and `extras` are handled apart:
  // extras carry application data with no rendering meaning, spec "Extras").
  void known(const json& o, const std::string& pointer, std::set<std::string> names) {
    names.insert("extras");
    names.insert("name");
    for (const auto& [key, value] : o.items()) {
      if (key == "extensions" && !names.count(key)) {
        extensions(value, pointer + "/extensions", {});
      } else if (!names.count(key)) {
        warn(pointer + "/" + key, "not supported by twinray, ignored");
      }
    }
  }

  // Warns about each extension object of `ext` not in `read`.
  void extensions(const json& ext, const std::string& pointer, std::set<std::string> read) {
    if (!ext.is_object()) return;
    for (const auto& [key, value] : ext.items())
      if (!read.count(key))
        warn(pointer + "/" + key, "extension not supported by twinray, ignored");
  }

  // --- typed reads ---

  const json* member(const json& o, const char* key) const {
    auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
  }

  const json& array(const json& v, const std::string& pointer) const {
    if (!v.is_array()) bad(pointer, "expected an array, not ", v.type_name());
    return v;
  }

  double number_or(const json& o, const char* key, double fallback, const std::string& pointer) {
    const json* v = member(o, key);
    return v ? number(*v, pointer + "/" + key) : fallback;
  }

  long long index(const json& v, const std::string& pointer, size_t count) const {
    if (!v.is_number_integer()) bad(pointer, "expected an index, not ", v.type_name());
    long long i = v.get<long long>();
    if (i < 0 || size_t(i) >= count) bad(pointer, "index ", i, " out of range (", count, " items)");
    return i;
  }

  std::vector<double> numbers(const json& v, const std::string& pointer, size_t n) const {
    if (!v.is_array() || v.size() != n) bad(pointer, "expected an array of ", n, " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i) out.push_back(number(v[i], pointer + "/" + std::to_string(i)));
    return out;
  }

  // The top-level array `key` (empty when absent).
  const json& list(const char* key) {
    static const json empty = json::array();
    const json* v = member(doc_, key);
    return v ? array(*v, std::string("/") + key) : empty;
  }

  // --- the container (spec "GLB File Format") and the asset ---

  static uint32_t u32(const std::string& s, size_t at) {
    uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | uint8_t(s[at + k]);
    return v;
  }

  std::string read_document() {
    std::ifstream in(path_, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string s = buffer.str();
    if (s.size() < 4 || s.compare(0, 4, "glTF") != 0) return s;
    // Spec "GLB File Format": a 12-byte header (magic, version 2, length), then chunks of (length,
    // type, data): the first JSON (0x4E4F534A), then an optional BIN (0x004E4942).
    Location top{path_, 0};
    if (s.size() < 20) fail(top, "truncated GLB header");
    if (u32(s, 4) != 2) fail(top, "GLB container version ", u32(s, 4), " (glTF 2.0 is version 2)");
    if (u32(s, 8) != s.size())
      fail(top, "GLB header length ", u32(s, 8), " is not the file's size ", s.size());
    size_t json_length = u32(s, 12);
    if (u32(s, 16) != 0x4E4F534Au || 20 + json_length > s.size())
      fail(top, "the first GLB chunk is not a complete JSON chunk");
    size_t bin = 20 + json_length;
    if (bin + 8 <= s.size() && u32(s, bin + 4) == 0x004E4942u) {
      size_t n = u32(s, bin);
      if (bin + 8 + n > s.size()) fail(top, "truncated GLB BIN chunk");
      glb_bin_ = s.substr(bin + 8, n);
      have_glb_bin_ = true;
    }
    byte_offsets_ = true;
    return s.substr(20, json_length);
  }

  void check_asset() {
    const json* asset = member(doc_, "asset");
    if (!asset) bad("", "\"asset\" is required (glTF 2.0 spec, Asset)");
    object(*asset, "/asset");
    const json* version = member(*asset, "version");
    if (!version) bad("/asset", "\"version\" is required");
    std::string v = text(*version, "/asset/version");
    if (v.rfind("2.", 0) != 0) bad("/asset/version", "glTF ", v, " is not glTF 2.x");
    for (const json& e : list("extensionsRequired"))
      if (!e.is_string() || !kSupportedExtensions.count(e.get<std::string>()))
        bad("/extensionsRequired", "required extension ", e.dump(),
            " is not supported by twinray (spec, Specifying Extensions: a loader must then refuse "
            "the asset)");
  }

  void read_parameters() {
    for (const auto& [name, value] : options_.defines) {
      bool known_name = false;
      for (const char* p : kParameterNames) known_name = known_name || name == p;
      if (!known_name && !options_.unused_defines_allowed)
        fail(at(""), "-D ", name, "=", value,
             " is not used: a glTF scene takes -D width, height, spp and max_depth");
    }
  }

  // -D `name` as a positive (or, for max_depth, >= -1) integer, or `fallback`.
  long long define(const std::string& name, long long fallback, bool* given = nullptr) const {
    auto d = options_.defines.find(name);
    if (given) *given = d != options_.defines.end();
    if (d == options_.defines.end()) return fallback;
    size_t used = 0;
    long long v = 0;
    try {
      v = std::stoll(d->second, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != d->second.size())
      fail(at(""), "-D ", name, "=", d->second, ": expected an integer");
    return v;
  }

  void report_top_level() {
    known(doc_, "",
          {"asset", "scene", "scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers",
           "materials", "textures", "images", "samplers", "cameras", "extensionsUsed",
           "extensionsRequired", "extensions"});
    if (const json* e = member(doc_, "extensions"))
      extensions(*e, "/extensions", {"KHR_lights_punctual"});
    const json& used = list("extensionsUsed");
    for (size_t i = 0; i < used.size(); ++i)
      if (!used[i].is_string() || !kSupportedExtensions.count(used[i].get<std::string>()))
        warn("/extensionsUsed/" + std::to_string(i), "extension ", used[i].dump(),
             " not supported by twinray, its fields are ignored");
    // Spec "Samplers": wrapping and magnification map onto each bitmap (sampler()); twinray's
    // bitmaps are not mipmapped.
    const json& samplers = list("samplers");
    for (size_t i = 0; i < samplers.size(); ++i) {
      std::string p = "/samplers/" + std::to_string(i);
      known(object(samplers[i], p), p, {"magFilter", "minFilter", "wrapS", "wrapT"});
      if (member(samplers[i], "minFilter"))
        note(p + "/minFilter",
             "not used: twinray's path tracer integrates each pixel's footprint by its samples "
             "instead of mipmapping");
    }
  }

  // A primitive written as a PLY file ("" when it has no triangles), with its object-space
  // bounds.
  struct PrimitivePly {
    std::string file;
    bool normals = false;
    bool tangents = false;  // the normal map's tangent frames (scenes/gltf/gltf_tangents.h)
    glm::dvec3 lo{HUGE_VAL}, hi{-HUGE_VAL};
  };

  // meshes[m].primitives[k], of glTF material `material` (-1: the default), as a PLY file,
  // written once for each winding (scenes/assimp/imported_ply.h). Spec "Meshes": a node whose
  // global transform has a negative determinant turns its triangles clockwise; written
  // reversed, so that the front faces stay the counter-clockwise ones after the mirroring
  // transform (tangent frames are made before, from the file's winding). Tangent frames only
  // under a normal map: the file's TANGENT, else generated.
  const PrimitivePly& ply_file(size_t m, size_t k, bool reversed, long long material) {
    auto key = std::make_tuple(m, k, reversed);
    auto it = plys_.find(key);
    if (it != plys_.end()) return it->second;
    ImportedMesh mesh = accessors_->primitive(m, k);
    PrimitivePly out;
    out.normals = !mesh.normals.empty();
    // The bounds of every vertex of the file (generated tangents drop unreferenced ones).
    for (size_t v = 0; v + 2 < mesh.positions.size(); v += 3) {
      glm::dvec3 x(mesh.positions[v], mesh.positions[v + 1], mesh.positions[v + 2]);
      if (!glm::all(glm::isnan(x))) out.lo = glm::min(out.lo, x), out.hi = glm::max(out.hi, x);
    }
    bool normal_mapped =
        material >= 0 && member(list("materials")[size_t(material)], "normalTexture");
    if (!normal_mapped) {
      mesh.tangents.clear();
      mesh.bitangents.clear();
    } else if (mesh.tangents.empty() && !mesh.uv.empty()) {
      generate_tangents(mesh);
    }
    out.tangents = !mesh.tangents.empty();
    if (!mesh.triangles.empty()) {
      if (reversed)
        for (size_t t = 0; t < mesh.triangles.size(); t += 3)
          std::swap(mesh.triangles[t + 1], mesh.triangles[t + 2]);
      out.file = (work_ / ("gltf_mesh_" + std::to_string(plys_.size()) + ".ply")).string();
      try {
        write_imported_ply(mesh, out.file, "written by twinray from a glTF primitive");
      } catch (const std::runtime_error& e) {
        fail(Location{path_, 0}, e.what());
      }
    }
    return plys_.emplace(key, std::move(out)).first->second;
  }

  // --- scene graph (spec "Nodes and Hierarchy") ---

  // Spec "Transformations": `matrix` (column-major), or T * R * S from translation, rotation (unit
  // quaternion x, y, z, w) and scale.
  glm::dmat4 local_transform(const json& n, const std::string& p) {
    if (const json* m = member(n, "matrix")) {
      if (member(n, "translation") || member(n, "rotation") || member(n, "scale"))
        bad(p, "\"matrix\" and TRS properties together (the spec's node schema forbids it)");
      std::vector<double> v = numbers(*m, p + "/matrix", 16);
      return glm::make_mat4(v.data());
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (const json* v = member(n, "translation")) {
      std::vector<double> a = numbers(*v, p + "/translation", 3);
      t = glm::translate(glm::dmat4(1.0), glm::dvec3(a[0], a[1], a[2]));
    }
    if (const json* v = member(n, "rotation")) {
      std::vector<double> a = numbers(*v, p + "/rotation", 4);
      glm::dquat q(a[3], a[0], a[1], a[2]);  // glm takes w first
      if (!(glm::length(q) > 0.0)) bad(p + "/rotation", "a zero quaternion");
      r = glm::mat4_cast(glm::normalize(q));
    }
    if (const json* v = member(n, "scale")) {
      std::vector<double> a = numbers(*v, p + "/scale", 3);
      s = glm::scale(glm::dmat4(1.0), glm::dvec3(a[0], a[1], a[2]));
    }
    return t * r * s;
  }

  void walk_scene() {
    const json& scenes = list("scenes");
    const json& nodes = list("nodes");
    if (scenes.empty()) bad("", "the file has no \"scenes\": nothing to render");
    size_t chosen = 0;
    if (const json* s = member(doc_, "scene")) chosen = size_t(index(*s, "/scene", scenes.size()));
    for (size_t i = 0; i < scenes.size(); ++i)
      if (i != chosen)
        note("/scenes/" + std::to_string(i), "not the default scene (\"scene\": ", chosen,
             "), ignored");
    std::string p = "/scenes/" + std::to_string(chosen);
    const json& scene = object(scenes[chosen], p);
    known(scene, p, {"nodes"});
    if (const json* roots = member(scene, "nodes")) {
      array(*roots, p + "/nodes");
      for (size_t i = 0; i < roots->size(); ++i)
        visit(size_t(index((*roots)[i], p + "/nodes/" + std::to_string(i), nodes.size())),
              glm::dmat4(1.0), 0);
    }
  }

  void visit(size_t i, const glm::dmat4& parent, int depth) {
    std::string p = "/nodes/" + std::to_string(i);
    const json& nodes = list("nodes");
    // Spec "Nodes and Hierarchy": the node hierarchy is a set of disjoint strict trees.
    if (depth > int(nodes.size())) bad(p, "the node hierarchy has a cycle");
    const json& n = object(nodes[i], p);
    known(
        n, p,
        {"camera", "children", "matrix", "mesh", "rotation", "scale", "translation", "extensions"});
    if (const json* e = member(n, "extensions")) {
      extensions(*e, p + "/extensions", {"KHR_lights_punctual"});
      if (const json* l = member(*e, "KHR_lights_punctual")) {
        std::string lp = p + "/extensions/KHR_lights_punctual";
        const json* li = member(object(*l, lp), "light");
        if (!li) bad(lp, "\"light\" is required");
        light_nodes_.push_back({size_t(index(*li, lp + "/light", lights_.size())), i});
      }
    }
    glm::dmat4 world = parent * local_transform(n, p);
    worlds_[i] = world;
    if (const json* c = member(n, "camera")) {
      index(*c, p + "/camera", list("cameras").size());
      camera_nodes_.push_back(i);
    }
    if (const json* m = member(n, "mesh"))
      add_mesh(size_t(index(*m, p + "/mesh", list("meshes").size())), world, p);
    for (const auto& [light, node] : light_nodes_)
      if (node == i) add_light(light, world, p);
    if (const json* children = member(n, "children")) {
      array(*children, p + "/children");
      for (size_t k = 0; k < children->size(); ++k)
        visit(size_t(index((*children)[k], p + "/children/" + std::to_string(k), nodes.size())),
              world, depth + 1);
    }
  }

  void add_mesh(size_t m, const glm::dmat4& world, const std::string& node_pointer) {
    std::string p = "/meshes/" + std::to_string(m);
    const json& mesh = list("meshes")[m];
    known(object(mesh, p), p, {"primitives"});
    const json* prims = member(mesh, "primitives");
    if (!prims) bad(p, "\"primitives\" is required");
    array(*prims, p + "/primitives");
    for (size_t k = 0; k < prims->size(); ++k) {
      std::string pp = p + "/primitives/" + std::to_string(k);
      const json& prim = object((*prims)[k], pp);
      known(prim, pp, {"attributes", "indices", "material", "mode"});
      int mode = int(number_or(prim, "mode", kTriangles, pp));
      if (mode != kTriangles && mode != kTriangleStrip && mode != kTriangleFan) {
        warn(pp + "/mode", "points and lines (mode ", mode, ") are not rendered, ignored");
        continue;
      }
      const json* attributes = member(prim, "attributes");
      if (!attributes || !attributes->contains("POSITION"))
        bad(pp, "\"attributes\" with POSITION is required");
      for (const auto& [name, value] : attributes->items()) {
        std::string ap = pp + "/attributes/" + name;
        if (name == "POSITION" || name == "NORMAL" || name == "TEXCOORD_0") continue;
        if (name == "TANGENT" && !attributes->contains("NORMAL"))
          warn(ap, "ignored: without NORMAL the spec asks for flat normals and ignores TANGENT");
        else if (name == "TANGENT")
          continue;
        else if (name.rfind("TEXCOORD_", 0) == 0)
          warn(ap, "ignored: only TEXCOORD_0 is read");
        else if (name.rfind("COLOR_", 0) == 0)
          warn(ap, "vertex colors are not supported by twinray, ignored");
        else if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0)
          warn(ap, "skinning is not supported by twinray, ignored");
        else
          warn(ap, "attribute not supported by twinray, ignored");
      }
      long long material = -1;
      if (const json* mi = member(prim, "material"))
        material = index(*mi, pp + "/material", list("materials").size());
      const PrimitivePly& ply = ply_file(m, k, glm::determinant(world) < 0.0, material);
      if (ply.file.empty()) {
        warn(pp, "no triangles, ignored");
        continue;
      }
      NodePtr s = make("shape", "ply", pp);
      add(*s, "filename", PropertyKind::String, pp).text = ply.file;
      grow_bounds(ply, world);
      // Spec "Meshes": without NORMAL, flat normals.
      if (!ply.normals) add(*s, "face_normals", PropertyKind::Boolean, pp).boolean = true;
      if (ply.tangents) add(*s, "vertex_tangents", PropertyKind::Boolean, pp).boolean = true;
      add_transform(*s, world, node_pointer);
      attach(*s, material, pp);
      add_object(*root_, s, pp);
    }
  }

  // --- materials (spec "Materials") ---

  struct MaterialNodes {
    NodePtr bsdf;
    glm::dvec3 emission{0.0};  // emissiveFactor x strength
    NodePtr emission_texture;  // its product with emissiveTexture, when there is one
    std::string pointer;
  };

  void attach(Node& s, long long material, const std::string& prim_pointer) {
    auto it = materials_.find(material);
    if (it == materials_.end()) it = materials_.emplace(material, material_nodes(material)).first;
    const MaterialNodes& m = it->second;
    add_object(s, m.bsdf, prim_pointer);
    if (m.emission != glm::dvec3(0.0)) {
      NodePtr area = make("emitter", "area", m.pointer);
      if (m.emission_texture)
        add(*area, "radiance", PropertyKind::Object, m.pointer).object = m.emission_texture;
      else
        add_color(*area, "radiance", m.emission, m.pointer);
      add_object(s, area, prim_pointer);
    }
  }

  // The bitmap of texture reference `info` (a textureInfo) baked as `what`, with
  // `factor` multiplied in (Normal: the normal texture's scale on x and y).
  NodePtr map(const json& info, const std::string& p, Bake what, glm::dvec3 factor) {
    object(info, p);
    const json* ti = member(info, "index");
    if (!ti) bad(p, "\"index\" is required");
    const json& textures = list("textures");
    size_t t = size_t(index(*ti, p + "/index", textures.size()));
    std::set<std::string> fields = {"index", "texCoord"};
    if (what == Bake::Normal) fields.insert("scale");
    if (const json* tc = member(info, "texCoord"); tc && !(tc->is_number_integer() && *tc == 0))
      warn(p + "/texCoord", "ignored: only TEXCOORD_0 is read; the map is read with it");
    for (const auto& [key, value] : info.items())
      if (!fields.count(key) && key != "extensions" && key != "extras")
        warn(p + "/" + key, "not supported by twinray, ignored");
    if (const json* e = member(info, "extensions"))
      for (const auto& [key, value] : e->items())
        if (key != "KHR_texture_transform")
          warn(p + "/extensions/" + key, "extension not supported by twinray, ignored");
    std::string tp = "/textures/" + std::to_string(t);
    const json& tex = object(textures[t], tp);
    if (!reported_textures_.count(t)) {
      reported_textures_.insert(t);
      known(tex, tp, {"sampler", "source"});
    }
    const json* source = member(tex, "source");
    if (!source) bad(tp, "no \"source\" image (twinray reads no texture extension images)");
    size_t image = size_t(index(*source, tp + "/source", list("images").size()));
    NodePtr bitmap = make("texture", "bitmap", p);
    add(*bitmap, "filename", PropertyKind::String, p).text = baked(image, what, factor);
    add(*bitmap, "raw", PropertyKind::Boolean, p).boolean = true;  // PFM: linear values
    if (const json* s = member(tex, "sampler"))
      sampler(*bitmap, size_t(index(*s, tp + "/sampler", list("samplers").size())), p);
    if (const json* e = member(info, "extensions"))
      if (const json* tt = member(*e, "KHR_texture_transform"))
        texture_transform(*bitmap, *tt, p + "/extensions/KHR_texture_transform");
    return bitmap;
  }

  // Spec "Samplers": wrapS and wrapT (10497 REPEAT, the default, 33648 MIRRORED_REPEAT, 33071
  // CLAMP_TO_EDGE) as Mitsuba's bitmap wrap_mode, magFilter 9728 NEAREST as its filter_type.
  void sampler(Node& bitmap, size_t i, const std::string& p) {
    std::string sp = "/samplers/" + std::to_string(i);
    const json& s = list("samplers")[i];
    auto wrap = [&](const char* key) {
      long long w = (long long)number_or(s, key, 10497, sp);
      if (w != 10497 && w != 33648 && w != 33071)
        bad(sp + "/" + key, "expected 10497, 33648 or 33071, not ", w);
      return w == 33071 ? "clamp" : w == 33648 ? "mirror" : "repeat";
    };
    std::string wrap_s = wrap("wrapS"), wrap_t = wrap("wrapT");
    if (wrap_s != wrap_t)
      warn(sp + "/wrapT", "approximate: twinray's bitmaps wrap u and v alike; wrapS (", wrap_s,
           ") used for both");
    if (wrap_s != "repeat") add(bitmap, "wrap_mode", PropertyKind::String, p).text = wrap_s;
    if (const json* m = member(s, "magFilter"); m && *m == 9728)
      add(bitmap, "filter_type", PropertyKind::String, p).text = "nearest";
  }

  // KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv as the bitmap's to_uv, with
  // R = ((cos, sin), (-sin, cos)) in rows: u' = cos u + sin v, v' = -sin u + cos v, a rotation
  // of the uvs counter-clockwise as the image shows them (v down). The GLSL of the extension's
  // README, read column-major, rotates the other way; the TextureTransformTest sample's arrows
  // point at its green markers with this one, as in the Khronos sample viewer.
  void texture_transform(Node& bitmap, const json& t, const std::string& p) {
    known(object(t, p), p, {"offset", "rotation", "scale", "texCoord"});
    if (const json* tc = member(t, "texCoord"); tc && !(tc->is_number_integer() && *tc == 0))
      warn(p + "/texCoord", "ignored: only TEXCOORD_0 is read; the map is read with it");
    glm::dvec2 offset(0.0), scale(1.0);
    if (const json* o = member(t, "offset")) {
      std::vector<double> v = numbers(*o, p + "/offset", 2);
      offset = {v[0], v[1]};
    }
    if (const json* s = member(t, "scale")) {
      std::vector<double> v = numbers(*s, p + "/scale", 2);
      scale = {v[0], v[1]};
    }
    double r = number_or(t, "rotation", 0.0, p);
    glm::dmat4 m(1.0);
    m[0][0] = std::cos(r) * scale.x, m[0][1] = -std::sin(r) * scale.x;
    m[1][0] = std::sin(r) * scale.y, m[1][1] = std::cos(r) * scale.y;
    m[3][0] = offset.x, m[3][1] = offset.y;
    add(bitmap, "to_uv", PropertyKind::Transform, p).matrix = m;
  }

  std::string image_bytes(size_t i) {
    std::string ip = "/images/" + std::to_string(i);
    const json& img = object(list("images")[i], ip);
    known(img, ip, {"uri", "mimeType", "bufferView"});
    if (const json* u = member(img, "uri"))
      return buffers_->uri_bytes(text(*u, ip + "/uri"), ip + "/uri");
    const json* bv = member(img, "bufferView");
    if (!bv) bad(ip, "neither \"uri\" nor \"bufferView\"");
    return std::string(
        buffers_->view(size_t(index(*bv, ip + "/bufferView", list("bufferViews").size()))));
  }

  // Image `i` decoded to linear RGBA (sRGB-decoded when `srgb`: spec "Metallic-Roughness Material",
  // baseColor and emissive textures are sRGB-encoded, the others linear).
  const Image& image(size_t i, bool srgb) {
    auto key = std::make_pair(i, srgb);
    auto it = images_.find(key);
    if (it != images_.end()) return it->second;
    // The image reader takes a path: the bytes go through a scratch file, removed once read.
    fs::path file = work_ / ("gltf_image_" + std::to_string(i));
    std::string bytes = image_bytes(i);
    {
      std::ofstream f(file, std::ios::binary);
      f.write(bytes.data(), std::streamsize(bytes.size()));
      if (!f.flush()) fail(Location{path_, 0}, "cannot write ", file.string());
    }
    try {
      Image decoded = load_image(file.string(), !srgb);
      fs::remove(file);
      return images_[key] = std::move(decoded);
    } catch (const std::exception& e) {
      std::string what = e.what();
      size_t cut = what.find(": ");  // "path: what" names the scratch file
      bad("/images/" + std::to_string(i),
          "cannot read the image: ", cut == std::string::npos ? what : what.substr(cut + 2));
    }
  }

  // Writes image `i` as a PFM (Netpbm portable float map: "PF" colour / "Pf" grey, little-endian
  // when the scale is negative, rows bottom to top) holding `what` times `factor`, linear.
  std::string baked(size_t i, Bake what, glm::dvec3 factor) {
    auto key = std::make_tuple(i, int(what), factor.x, factor.y, factor.z);
    auto done = baked_.find(key);
    if (done != baked_.end()) return done->second;
    fs::path file = work_ / ("gltf_texture_" + std::to_string(baked_.size()) + ".pfm");
    const Image& img = image(i, what == Bake::Color);
    bool color = what == Bake::Color || what == Bake::Normal;
    // A row or column of texels is written twice (N x 2 or 2 x N): the same bilinear lookups,
    // and a size Mitsuba's bitmap reads without resampling (scenes/build_materials.cpp).
    const int rows = img.height == 1 && img.width > 1 ? 2 : 1;
    const int columns = img.width == 1 && img.height > 1 ? 2 : 1;
    std::ofstream f(file, std::ios::binary);
    f << (color ? "PF" : "Pf") << "\n"
      << img.width * columns << " " << img.height * rows << "\n-1.0\n";
    for (int y = img.height * rows - 1; y >= 0; --y) {
      for (int x = 0; x < img.width * columns; ++x) {
        glm::vec4 c = img.texels[size_t(y / rows) * img.width + size_t(x / columns)];
        if (what == Bake::Color) {
          for (int k = 0; k < 3; ++k) {
            float v = float(c[k] * factor[k]);
            f.write(reinterpret_cast<const char*>(&v), 4);
          }
        } else if (what == Bake::Normal) {
          // Spec "Additional Textures": n = normalize((2 c - 1) * (scale, scale, 1)); stored back
          // as (n+1)/2 before normalising, which Mitsuba's normalmap does after 2 c - 1 (a linear
          // map, so it commutes with bilinear filtering).
          for (int k = 0; k < 3; ++k) {
            float v = float(((2.0 * c[k] - 1.0) * factor[k] + 1.0) * 0.5);
            f.write(reinterpret_cast<const char*>(&v), 4);
          }
        } else {
          int k = what == Bake::Red ? 0 : what == Bake::Green ? 1 : what == Bake::Blue ? 2 : 3;
          float v = float(c[k] * factor.x);
          f.write(reinterpret_cast<const char*>(&v), 4);
        }
      }
    }
    if (!f.flush()) fail(Location{path_, 0}, "cannot write ", file.string());
    return baked_[key] = file.string();
  }

  glm::dvec3 rgb(const json& o, const char* key, glm::dvec3 fallback, const std::string& p,
                 size_t n = 3) {
    const json* v = member(o, key);
    if (!v) return fallback;
    std::vector<double> a = numbers(*v, p + "/" + key, n);
    return {a[0], a[1], a[2]};
  }

  MaterialNodes material_nodes(long long index) {
    MaterialNodes out;
    json none = json::object();
    // Spec "Default Material": a primitive without material uses the default material (the
    // metallic-roughness defaults: base colour 1, metallic 1, roughness 1).
    std::string p = index < 0 ? std::string("/meshes") : "/materials/" + std::to_string(index);
    const json& m = index < 0 ? none : object(list("materials")[size_t(index)], p);
    out.pointer = p;
    known(m, p,
          {"pbrMetallicRoughness", "normalTexture", "occlusionTexture", "emissiveTexture",
           "emissiveFactor", "alphaMode", "alphaCutoff", "doubleSided", "extensions"});
    NodePtr bsdf = make("bsdf", "principled", p);
    const json* pbr = member(m, "pbrMetallicRoughness");
    std::string pp = p + "/pbrMetallicRoughness";
    json empty = json::object();
    const json& r = pbr ? object(*pbr, pp) : empty;
    if (pbr)
      known(r, pp,
            {"baseColorFactor", "baseColorTexture", "metallicFactor", "roughnessFactor",
             "metallicRoughnessTexture"});
    glm::dvec3 base = rgb(r, "baseColorFactor", glm::dvec3(1.0), pp, 4);
    double base_alpha = 1.0;
    if (const json* f = member(r, "baseColorFactor"))
      base_alpha = numbers(*f, pp + "/baseColorFactor", 4)[3];
    std::string alpha_mode = "OPAQUE";
    if (const json* a = member(m, "alphaMode")) alpha_mode = text(*a, p + "/alphaMode");
    if (alpha_mode != "OPAQUE" && alpha_mode != "MASK" && alpha_mode != "BLEND")
      bad(p + "/alphaMode", "expected OPAQUE, MASK or BLEND");
    const bool mask = alpha_mode == "MASK", blend = alpha_mode == "BLEND";
    // Spec "Alpha Coverage": alphaCutoff applies in MASK mode only (default 0.5).
    double cutoff = 0.5;
    if (member(m, "alphaCutoff")) {
      if (mask)
        cutoff = number_or(m, "alphaCutoff", 0.5, p);
      else
        warn(p + "/alphaCutoff", "ignored: the material's alphaMode is not MASK");
    }
    double metallic = number_or(r, "metallicFactor", 1.0, pp);
    double roughness = number_or(r, "roughnessFactor", 1.0, pp);
    if (const json* t = member(r, "baseColorTexture"))
      add(*bsdf, "base_color", PropertyKind::Object, pp + "/baseColorTexture").object =
          map(*t, pp + "/baseColorTexture", Bake::Color, base);
    else
      add_color(*bsdf, "base_color", base, pp);
    if (const json* t = member(r, "metallicRoughnessTexture")) {
      std::string tp = pp + "/metallicRoughnessTexture";
      add(*bsdf, "metallic", PropertyKind::Object, tp).object =
          map(*t, tp, Bake::Blue, glm::dvec3(metallic));
      add(*bsdf, "roughness", PropertyKind::Object, tp).object =
          map(*t, tp, Bake::Green, glm::dvec3(roughness));
    } else {
      add_float(*bsdf, "metallic", metallic, pp);
      add_float(*bsdf, "roughness", roughness, pp);
    }
    bool transmits = false;
    double strength = 1.0;  // KHR_materials_emissive_strength
    if (const json* e = member(m, "extensions")) {
      extensions(
          *e, p + "/extensions",
          {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_emissive_strength"});
      if (const json* t = member(*e, "KHR_materials_transmission")) {
        std::string tp = p + "/extensions/KHR_materials_transmission";
        known(object(*t, tp), tp, {"transmissionFactor", "transmissionTexture"});
        double factor = number_or(*t, "transmissionFactor", 0.0, tp);
        transmits = factor > 0.0;
        if (const json* tt = member(*t, "transmissionTexture"))
          add(*bsdf, "spec_trans", PropertyKind::Object, tp).object =
              map(*tt, tp + "/transmissionTexture", Bake::Red, glm::dvec3(factor));
        else
          add_float(*bsdf, "spec_trans", factor, tp);
      }
      if (const json* i = member(*e, "KHR_materials_ior")) {
        std::string ip = p + "/extensions/KHR_materials_ior";
        known(object(*i, ip), ip, {"ior"});
        double ior = number_or(*i, "ior", 1.5, ip);
        // ior = 1: an index-matched interface (principled's eta; Mitsuba's principled takes
        // 1.001 where its spec_trans lobe is on).
        if (!(ior >= 1.0 && std::isfinite(ior)))
          bad(ip + "/ior", "must be at least 1 (twinray's principled reads no other ior)");
        add_float(*bsdf, "eta", ior, ip);
      }
      if (const json* s = member(*e, "KHR_materials_emissive_strength")) {
        std::string sp = p + "/extensions/KHR_materials_emissive_strength";
        known(object(*s, sp), sp, {"emissiveStrength"});
        strength = number_or(*s, "emissiveStrength", 1.0, sp);
      }
    }
    if (const json* t = member(m, "normalTexture")) {
      std::string np = p + "/normalTexture";
      double scale = number_or(object(*t, np), "scale", 1.0, np);
      NodePtr outer = make("bsdf", "normalmap", np);
      add(*outer, "normalmap", PropertyKind::Object, np).object =
          map(*t, np, Bake::Normal, glm::dvec3(scale, scale, 1.0));
      add_object(*outer, bsdf, np);
      bsdf = outer;
    }
    if (member(m, "occlusionTexture"))
      note(p + "/occlusionTexture", "not used: the path tracer computes occlusion itself");
    bool double_sided = false;
    if (const json* d = member(m, "doubleSided")) {
      if (!d->is_boolean()) bad(p + "/doubleSided", "expected true or false");
      double_sided = d->get<bool>();
    }
    if (double_sided && !transmits) {
      NodePtr two = make("bsdf", "twosided", p + "/doubleSided");
      add_object(*two, bsdf, p + "/doubleSided");
      bsdf = two;
    } else if (double_sided) {
      warn(p + "/doubleSided",
           "ignored for a transmissive material (Mitsuba's twosided refuses transmission)");
    }
    if (mask && !(cutoff >= 0.0 && cutoff <= 1.0)) bad(p + "/alphaCutoff", "must lie in [0, 1]");
    const json* base_texture = member(r, "baseColorTexture");
    if (mask || (blend && (base_alpha != 1.0 || base_texture))) {
      // Spec "Alpha Coverage": alpha = baseColorFactor.a x baseColorTexture.a. MASK: against
      // alphaCutoff, twinray's alphatest (core/alpha_test.h), absent for every ray where
      // alpha < cutoff. BLEND: Mitsuba's mask with alpha as its opacity, a surface that camera
      // and scattered rays cross with probability 1 - alpha and shadow rays do not.
      NodePtr outer = make("bsdf", mask ? "alphatest" : "mask", p + "/alphaMode");
      if (base_texture)
        add(*outer, "opacity", PropertyKind::Object, pp + "/baseColorTexture").object =
            map(*base_texture, pp + "/baseColorTexture", Bake::Alpha, glm::dvec3(base_alpha));
      else
        add_float(*outer, "opacity", base_alpha, pp);
      if (mask) add_float(*outer, "cutoff", cutoff, p);
      add_object(*outer, bsdf, p + "/alphaMode");
      bsdf = outer;
      if (blend)
        warn(p + "/alphaMode",
             "approximate: BLEND as Mitsuba's mask of opacity alpha (light is not transmitted "
             "to shadow rays; --strict-gltf refuses it)");
    }
    glm::dvec3 emission = rgb(m, "emissiveFactor", glm::dvec3(0.0), p) * strength;
    if (const json* t = member(m, "emissiveTexture"); t && emission != glm::dvec3(0.0)) {
      // The area emitter's radiance: a bitmap of factor x texel (sRGB-decoded), read at each
      // point's uv (core/emitters/area.h).
      std::string ep = p + "/emissiveTexture";
      out.emission_texture = map(*t, ep, Bake::Color, emission);
    }
    if (mask && emission != glm::dvec3(0.0))
      bad(p,
          "an emissive MASK material: twinray's alphatest surfaces do not emit "
          "(core/alpha_test.h)");
    out.emission = emission;
    add_object(*root_, bsdf, p);
    out.bsdf = bsdf;
    return out;
  }

  // --- lights (KHR_lights_punctual) ---

  void read_lights() {
    const json* e = member(doc_, "extensions");
    const json* l = e ? member(*e, "KHR_lights_punctual") : nullptr;
    if (!l) return;
    std::string p = "/extensions/KHR_lights_punctual";
    const json* ls = member(object(*l, p), "lights");
    if (!ls) return;
    array(*ls, p + "/lights");
    for (size_t i = 0; i < ls->size(); ++i)
      lights_.push_back(object((*ls)[i], p + "/lights/" + std::to_string(i)));
  }

  // KHR_lights_punctual: point and spot intensity in candela (lm/sr), directional in lux
  // (lm/m^2), colour linear RGB; the light at the node's origin, spot and directional along its
  // -z. Photometric units are read as the radiometric ones with a factor of 1 (cd -> W/sr,
  // lux -> W/m^2), the factor under which emissiveFactor (cd/m^2 with
  // KHR_materials_emissive_strength) is read as radiance, so lights keep their ratios.
  void add_light(size_t i, const glm::dmat4& world, const std::string& node_pointer) {
    std::string p = "/extensions/KHR_lights_punctual/lights/" + std::to_string(i);
    const json& l = lights_[i];
    known(l, p, {"type", "color", "intensity", "range", "spot"});
    const json* t = member(l, "type");
    if (!t) bad(p, "\"type\" is required");
    std::string type = text(*t, p + "/type");
    glm::dvec3 color = rgb(l, "color", glm::dvec3(1.0), p);
    double intensity = number_or(l, "intensity", 1.0, p);
    if (intensity < 0.0) bad(p + "/intensity", "must not be negative");
    if (member(l, "range"))
      warn(p + "/range",
           "ignored: twinray's lights fall off with the inverse square law without a cutoff");
    glm::dvec3 origin(world[3]);
    glm::dvec3 forward = glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
    glm::dvec3 up = glm::dvec3(world * glm::dvec4(0, 1, 0, 0));
    NodePtr e;
    if (type == "point") {
      e = make("emitter", "point", p);
      add(*e, "position", PropertyKind::Point, node_pointer).vec = origin;
      add_color(*e, "intensity", color * intensity, p);
    } else if (type == "spot") {
      e = make("emitter", "spot", p);
      std::string sp = p + "/spot";
      json empty = json::object();
      const json& s = l.contains("spot") ? object(l["spot"], sp) : empty;
      known(s, sp, {"innerConeAngle", "outerConeAngle"});
      double inner = number_or(s, "innerConeAngle", 0.0, sp);
      double outer = number_or(s, "outerConeAngle", M_PI / 4.0, sp);
      if (!(inner >= 0.0 && inner < outer && outer <= M_PI / 2.0))
        bad(sp, "needs 0 <= innerConeAngle < outerConeAngle <= pi/2");
      add_color(*e, "intensity", color * intensity, p);
      add_float(*e, "cutoff_angle", glm::degrees(outer), sp);
      add_float(*e, "beam_width", glm::degrees(inner), sp);
      add_transform(*e, look_at(origin, origin + forward, up, at(node_pointer)), node_pointer);
      warn(sp,
           "approximate: Mitsuba's spot falls off linearly in angle between the cone angles; "
           "KHR_lights_punctual recommends a smooth falloff in cos(angle)");
    } else if (type == "directional") {
      e = make("emitter", "directional", p);
      if (!(glm::length(forward) > 0.0)) bad(node_pointer, "the light's direction is zero");
      add(*e, "direction", PropertyKind::Vector, node_pointer).vec = glm::normalize(forward);
      add_color(*e, "irradiance", color * intensity, p);
    } else {
      bad(p + "/type", "unknown light type \"", type, "\" (point, spot or directional)");
    }
    add_object(*root_, e, p);
  }

  // --- camera (spec "Cameras") and integrator ---

  void add_sensor() {
    const std::string& choice = options_.camera;
    if (choice == "auto" || (choice.empty() && camera_nodes_.empty())) {
      if (choice.empty())
        note("",
             "no node of the scene has a camera: rendered through a camera framing the scene's "
             "bounds (--camera auto)");
      add_framing_sensor();
      return;
    }
    size_t node = camera_nodes_.empty() ? 0 : camera_nodes_.front();
    if (!choice.empty()) {
      const size_t n = std::stoul(choice), count = list("cameras").size();
      if (n >= count) fail(at("/cameras"), "--camera ", n, ": the file has ", count, " cameras");
      auto uses = [&](size_t i) { return list("nodes")[i]["camera"] == n; };
      auto it = std::find_if(camera_nodes_.begin(), camera_nodes_.end(), uses);
      if (it == camera_nodes_.end())
        fail(at("/cameras/" + std::to_string(n)), "--camera ", n,
             ": no node of the scene uses cameras[", n, "]");
      node = *it;
    } else {
      for (size_t k = 1; k < camera_nodes_.size(); ++k)
        note("/nodes/" + std::to_string(camera_nodes_[k]) + "/camera",
             "not used: twinray renders through the first camera node, nodes[", node,
             "] (--camera N chooses cameras[N])");
    }
    std::string np = "/nodes/" + std::to_string(node);
    size_t ci = size_t(list("nodes")[node]["camera"].get<long long>());
    std::string p = "/cameras/" + std::to_string(ci);
    const json& c = object(list("cameras")[ci], p);
    known(c, p, {"type", "perspective", "orthographic"});
    const json* type = member(c, "type");
    if (!type) bad(p, "\"type\" is required");
    if (text(*type, p + "/type") != "perspective")
      bad(p + "/type", "only perspective cameras are supported by twinray");
    const json* persp = member(c, "perspective");
    if (!persp) bad(p, "\"perspective\" is required");
    std::string pp = p + "/perspective";
    object(*persp, pp);
    known(*persp, pp, {"yfov", "aspectRatio", "znear", "zfar"});
    const json* yfov = member(*persp, "yfov");
    const json* znear = member(*persp, "znear");
    if (!yfov || !znear) bad(pp, "\"yfov\" and \"znear\" are required");
    double fov = glm::degrees(number(*yfov, pp + "/yfov"));
    if (!(fov > 0.0 && fov < 180.0)) bad(pp + "/yfov", "must be in (0, pi) radians");
    double near = number(*znear, pp + "/znear");
    if (!(near > 0.0)) bad(pp + "/znear", "must be positive");

    NodePtr sensor = make("sensor", "perspective", p);
    add_float(*sensor, "fov", fov, pp + "/yfov");
    add(*sensor, "fov_axis", PropertyKind::String, pp + "/yfov").text = "y";
    add_float(*sensor, "near_clip", near, pp + "/znear");
    if (const json* zfar = member(*persp, "zfar")) {
      double far = number(*zfar, pp + "/zfar");
      if (!(far > near)) bad(pp + "/zfar", "must exceed znear");
      add_float(*sensor, "far_clip", far, pp + "/zfar");
    } else {
      // Spec "Projection Matrices": no zfar is an infinite projection.
      add_float(*sensor, "far_clip", 1e30, pp);
    }
    // glTF cameras look along -z with +y up and +x right; Mitsuba's along +z with +x left.
    const glm::dmat4& w = worlds_.at(node);
    glm::dvec3 origin(w[3]);
    glm::dvec3 forward(w * glm::dvec4(0, 0, -1, 0)), up(w * glm::dvec4(0, 1, 0, 0));
    add_transform(*sensor, look_at(origin, origin + forward, up, at(np)), np);

    double aspect = 0.0;
    if (const json* a = member(*persp, "aspectRatio")) {
      aspect = number(*a, pp + "/aspectRatio");
      if (!(aspect > 0.0)) bad(pp + "/aspectRatio", "must be positive");
    }
    add_film_and_sampler(*sensor, aspect, pp + "/aspectRatio", p);
    add_object(*root_, sensor, p);
  }

  // Adds the film and the sampler of `sensor` and returns the image's aspect ratio. The size:
  // -D width and height; one of them, the other from the aspect ratio (the camera's `aspect`
  // when positive, else Mitsuba's default film's 4:3); neither, Mitsuba's default height.
  double add_film_and_sampler(Node& sensor, double aspect, const std::string& aspect_pointer,
                              const std::string& p) {
    bool have_w = false, have_h = false;
    long long width = define("width", 0, &have_w), height = define("height", 0, &have_h);
    // Spec "Cameras": without aspectRatio, the viewport's (Mitsuba's default film's).
    const bool stated = aspect > 0.0;
    if (!stated) aspect = double(kDefaultWidth) / double(kDefaultHeight);
    if (!have_h) height = have_w ? std::max(1LL, std::llround(width / aspect)) : kDefaultHeight;
    if (!have_w) width = std::max(1LL, std::llround(height * aspect));
    if (have_w && have_h && stated && std::abs(double(width) / height - aspect) > 1e-2)
      warn(aspect_pointer, "the image is ", width, "x", height,
           " (-D width, height): yfov is kept, the horizontal field of view follows the image");
    NodePtr film = make("film", "hdrfilm", p);
    add(*film, "width", PropertyKind::Integer, p).integer = width;
    add(*film, "height", PropertyKind::Integer, p).integer = height;
    out_.parameters.push_back({"width", std::to_string(width), film.get(), "width"});
    out_.parameters.push_back({"height", std::to_string(height), film.get(), "height"});
    add(*film, "component_format", PropertyKind::String, p).text = "float32";
    add_object(sensor, film, p);
    NodePtr sampler = make("sampler", "independent", p);
    long long spp = define("spp", kDefaultSpp);
    add(*sampler, "sample_count", PropertyKind::Integer, p).integer = spp;
    out_.parameters.push_back({"spp", std::to_string(spp), sampler.get(), "sample_count"});
    add_object(sensor, sampler, p);
    return double(width) / double(height);
  }

  // --camera auto, as glTF viewers frame a model: a perspective camera of vertical field of
  // view kAutoYfov looking down -z (+y up) at the centre c of the shapes' world bounds, at the
  // distance d = r / sin(fov / 2) from it at which the bounding sphere (radius r, half the
  // bounds' diagonal) fits the narrower of the two fields of view.
  void add_framing_sensor() {
    if (!(lo_.x <= hi_.x) || !(glm::length(hi_ - lo_) > 0.0) ||
        !std::isfinite(glm::length(hi_ - lo_)))
      bad("", "--camera auto: the scene has no finite extent to frame");
    glm::dvec3 c = 0.5 * (lo_ + hi_);
    double r = 0.5 * glm::length(hi_ - lo_);
    NodePtr sensor = make("sensor", "perspective", "");
    double aspect = add_film_and_sampler(*sensor, 0.0, "", "");
    double yfov = glm::radians(kAutoYfov);
    double xfov = 2.0 * std::atan(std::tan(0.5 * yfov) * aspect);
    double d = r / std::sin(0.5 * std::min(yfov, xfov));
    add_float(*sensor, "fov", kAutoYfov, "");
    add(*sensor, "fov_axis", PropertyKind::String, "").text = "y";
    add_float(*sensor, "near_clip", 0.5 * (d - r), "");
    add_float(*sensor, "far_clip", 2.0 * (d + r), "");
    glm::dvec3 origin = c + glm::dvec3(0.0, 0.0, d);
    add_transform(*sensor, look_at(origin, c, {0.0, 1.0, 0.0}, at("")), "");
    add_object(*root_, sensor, "");
  }

  void grow_bounds(const PrimitivePly& ply, const glm::dmat4& world) {
    if (!(ply.lo.x <= ply.hi.x)) return;
    for (int corner = 0; corner < 8; ++corner) {
      glm::dvec3 x((corner & 1 ? ply.hi : ply.lo).x, (corner & 2 ? ply.hi : ply.lo).y,
                   (corner & 4 ? ply.hi : ply.lo).z);
      glm::dvec3 w(world * glm::dvec4(x, 1.0));
      lo_ = glm::min(lo_, w), hi_ = glm::max(hi_, w);
    }
  }

  void add_integrator() {
    NodePtr path = make("integrator", "path", "");
    long long max_depth = define("max_depth", -1);
    add(*path, "max_depth", PropertyKind::Integer, "").integer = max_depth;
    out_.parameters.push_back({"max_depth", std::to_string(max_depth), path.get(), "max_depth"});
    add_object(*root_, path, "");
  }

  const LoadOptions& options_;
  fs::path work_;
  fs::path dir_;
  std::string glb_bin_;
  bool have_glb_bin_ = false;
  json doc_;
  std::unique_ptr<GltfBuffers> buffers_;
  std::unique_ptr<GltfAccessors> accessors_;
  std::map<std::tuple<size_t, size_t, bool>, PrimitivePly> plys_;
  glm::dvec3 lo_{HUGE_VAL}, hi_{-HUGE_VAL};  // the world-space bounds of the shapes
  std::map<std::pair<size_t, bool>, Image> images_;
  std::map<std::tuple<size_t, int, double, double, double>, std::string> baked_;
  std::map<long long, MaterialNodes> materials_;
  std::set<size_t> reported_textures_;
  std::vector<json> lights_;
  std::vector<std::pair<size_t, size_t>> light_nodes_;  // (light, node)
  std::vector<size_t> camera_nodes_;
  std::map<size_t, glm::dmat4> worlds_;
  GltfScene out_;
  NodePtr root_;
};

}  // namespace

bool is_gltf(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e == ".gltf" || e == ".glb";
}

GltfScene import_gltf(const std::string& path, const LoadOptions& options,
                      const fs::path& work_dir) {
  return Importer(path, options, work_dir).run();
}

}  // namespace tr
