#include "scenes/load_scene.h"

#include <cstdio>
#include <filesystem>
#include <map>

#include "io/temp_file.h"
#include "scenes/added_environment.h"
#include "scenes/emitter_selection.h"
#include "scenes/gltf/gltf_import.h"
#include "scenes/plugins.h"
#include "scenes/scene_builder.h"
#include "scenes/scn/scn_import.h"

namespace tr {

namespace {

// How many properties of the tree hold each node (a node is held once by its parent and once
// more by every <ref> to it).
void count_holders(const Node& node, std::map<const Node*, int>& holders) {
  for (const Property& p : node.props) {
    if (p.kind != PropertyKind::Object) continue;
    if (holders[p.object.get()]++ == 0) count_holders(*p.object, holders);
  }
}

bool is_scn(const std::string& path) { return std::filesystem::path(path).extension() == ".scn"; }

// Objects that Mitsuba accepts at the top level but uses only where another object refers to
// them: an `area` emitter (attached to the shapes that <ref> it), a sampler, film or rfilter
// (nested into a sensor or film by <ref>).
bool used_only_by_reference(const Node& o) {
  return (o.tag == "emitter" && o.type == "area") || o.tag == "sampler" || o.tag == "film" ||
         o.tag == "rfilter";
}

// The build parameters of Mitsuba's own kd-tree (src/render/scene.cpp marks them read in every
// build; only a build without Embree uses them): they shape an acceleration structure that
// twinray does not have, never the image.
bool is_kd_tree_parameter(const std::string& name) {
  static const char* const names[] = {"kd_intersection_cost",
                                      "kd_traversal_cost",
                                      "kd_empty_space_bonus",
                                      "kd_stop_prims",
                                      "kd_max_depth",
                                      "kd_min_max_bins",
                                      "kd_clip",
                                      "kd_retract_bad_splits",
                                      "kd_exact_primitive_threshold"};
  for (const char* n : names)
    if (name == n) return true;
  return false;
}

}  // namespace

SceneBuilder::SceneBuilder(ParsedScene parsed, const std::string& path)
    : parsed_(std::move(parsed)), b_(scene_.buffers) {
  scene_.path = path;
}

Scene SceneBuilder::build() {
  b_.globals = SceneGlobals{};
  b_.globals.environment = NO_INDEX;
  Node& root = *parsed_.root;
  bool have_sensor = false, have_integrator = false;
  std::map<const Node*, int> holders;
  count_holders(root, holders);
  scene_.robust_intersections = take_bool(root, "embree_use_robust_intersections", true);
  for (Property& p : root.props) {
    if (p.kind != PropertyKind::Object) {
      if (p.name == "embree_use_robust_intersections") continue;
      if (!is_kd_tree_parameter(p.name))
        fail(p.loc, "parameter '", p.name, "' cannot be set on <scene>");
      p.used = true;
      continue;
    }
    p.used = true;
    Node& o = *p.object;
    if (used_only_by_reference(o)) {
      // Twinray refuses what would silently do nothing, as it refuses unread parameters.
      if (holders[&o] < 2)
        fail(o.loc, describe(o), o.id.empty() ? "" : " (id \"" + o.id + "\")",
             " is declared at the top level but nothing refers to it; nest it where it is used "
             "or <ref> it there");
      continue;
    }
    if (o.tag == "shape") {
      if (o.type == "shapegroup") {
        add_shapegroup(o);
      } else if (o.type == "instance") {
        add_instance(o);
        top_level_order_.push_back({true, instances_.size() - 1});
      } else {
        add_shape(o, top_shapes_, false);
        top_level_order_.push_back({false, top_shapes_.size() - 1});
      }
    } else if (o.tag == "bsdf") {
      material(o);
    } else if (o.tag == "texture") {
      texture(o, false);
    } else if (o.tag == "emitter") {
      add_emitter(o);
    } else if (o.tag == "sensor") {
      if (have_sensor) fail(o.loc, "more than one <sensor> is not supported");
      add_sensor(o);
      have_sensor = true;
    } else if (o.tag == "integrator") {
      if (have_integrator) fail(o.loc, "more than one <integrator>");
      add_integrator(o);
      have_integrator = true;
    } else {
      fail(o.loc, "<", o.tag, "> must be nested inside ",
           o.tag == "film" || o.tag == "sampler" ? "a <sensor>" : "a <film>");
    }
  }
  if (!have_sensor) fail(root.loc, "the scene has no <sensor>");
  if (!have_integrator) {
    Node path;  // Mitsuba's default integrator
    path.tag = "integrator";
    path.type = "path";
    path.loc = root.loc;
    add_integrator(path);
  }

  mark_textured_materials();
  number_shapes_as_mitsuba();
  finalize_shapes();
  finalize_emitters();
  b_.globals.instance_count = uint(b_.instances.size());
  return std::move(scene_);
}

namespace {

// What the command line adds to a parsed scene of any format.
void adjust(Node& root, const LoadOptions& options) {
  check_plugins(root);
  if (!options.guide_aovs.empty()) wrap_in_guide_aovs(root, options.guide_aovs);
  if (options.environment.any()) add_environment(root, options.environment);
}

Scene build_scene(const std::string& path, const LoadOptions& options) {
  if (is_scn(path)) {
    TemporaryDirectory meshes;
    ScnScene scn = import_scn(path, options, meshes.path(), "scn", false);
    adjust(*scn.parsed.root, options);
    Scene scene = SceneBuilder(std::move(scn.parsed), path).build();
    for (const std::string& w : scn.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    return scene;
  }
  if (is_gltf(path)) {  // glTF 2.0 (scenes/gltf/)
    TemporaryDirectory work;
    GltfScene gltf = import_gltf(path, options, work.path());
    adjust(*gltf.parsed.root, options);
    Scene scene = SceneBuilder(std::move(gltf.parsed), path).build();
    for (const std::string& w : gltf.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    return scene;
  }
  ParsedScene parsed = parse_scene_xml(path, options);
  std::vector<std::string> warnings = parsed.warnings;
  adjust(*parsed.root, options);
  Scene scene = SceneBuilder(std::move(parsed), path).build();
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return scene;
}

}  // namespace

Scene load_scene(const std::string& path, const LoadOptions& options) {
  Scene scene = build_scene(path, options);
  if (scene.buffers.emitters.empty() &&
      scene.buffers.globals.integrator.type != INTEGRATOR_AMBIENT_OCCLUSION)
    std::fprintf(stderr,
                 "warning: %s: the scene has no emitter, so its image is black (light it with "
                 "--envmap FILE or --constant RGB, or add an emitter)\n",
                 path.c_str());
  use_emitter_selection(scene.buffers, options.emitter_selection);
  return scene;
}

}  // namespace tr
