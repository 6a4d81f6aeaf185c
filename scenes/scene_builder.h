// Turns the parsed Node tree into the flat records of tr::SceneBuffers. One builder per load;
// its parts live in build_*.cpp by topic (materials and textures, shapes, emitters, sensor).
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "scenes/mesh.h"
#include "scenes/properties.h"
#include "scenes/xml_parser.h"

namespace tr {

// Mitsuba's bitmap `format` (src/textures/bitmap.cpp): the precision texels are stored in. Auto
// stores sources of at most 16 bits per channel in half precision, others in float.
enum class TexelFormat { Auto, Variant, Float16 };

// A shape waiting for its final index: top-level shapes come first in SceneBuffers::shapes
// (instance 0), then each shapegroup's shapes.
struct PendingShape {
  Shape record{};
  TriangleMesh mesh;  // SHAPE_MESH only; world space (group space inside a shapegroup)
  bool emitting = false;
  bool mitsuba_mesh = false;  // a Mesh in Mitsuba (obj, ply, serialized, rectangle, cube)
  glm::vec3 radiance{0.0f};
  uint radiance_texture = NO_INDEX;  // a textured radiance (core/emitters/area.h)
  double sampling_weight = 1.0;
  Location emitter_loc;
  std::vector<uint> attribute_slots;  // Texture.attribute_slot of each attribute read
  std::vector<float> tangent_frames;  // `vertex_tangents`: as Shape.tangent_frames (world space)
};

struct PendingGroup {
  std::vector<PendingShape> shapes;
  uint first_shape = 0;
};

class SceneBuilder {
 public:
  SceneBuilder(ParsedScene parsed, const std::string& path);
  Scene build();

 private:
  ParsedScene parsed_;
  Scene scene_;
  SceneBuffers& b_;

  // ---- materials and textures (build_materials.cpp)
  std::map<const Node*, uint> material_cache_;
  std::map<std::pair<const Node*, bool>, uint> texture_cache_;
  std::map<std::string, std::pair<uint, glm::uvec2>> texel_cache_;
  uint default_material_ = NO_INDEX;
  // Sets MATERIAL_TEXTURED on every material that reads a texture (core/bsdf.h, material_at).
  void mark_textured_materials();
  uint default_luminaire_material_ = NO_INDEX;
  uint material(Node& bsdf);
  uint default_material(bool emitter);
  Material build_material(Node& bsdf);
  Material build_principled(Node& bsdf);
  Material build_pplastic(Node& bsdf);
  Material build_bumpmap(Node& bsdf);
  // `distribution`, `sample_visible` and `alpha` or `alpha_u`/`alpha_v` (textures allowed) of
  // roughconductor and roughdielectric, Mitsuba's defaults (beckmann, true, 0.1).
  void microfacet_roughness(Node& bsdf, Material& m, uint slot_u, uint slot_v);
  TexturedValue roughplastic_table(const Material& m);
  // Its results by (beckmann, alpha, eta): materials alike share one table.
  std::map<std::tuple<bool, float, float>, TexturedValue> roughplastic_tables_;
  double textured_mean(const TexturedValue& v) const;
  // A BSDF parameter that may be a texture. `scalar`: Mitsuba reads it with eval_1 (one value).
  TexturedValue textured(Node& owner, const std::string& name, glm::dvec3 default_value,
                         bool scalar);
  uint texture(Node& tex, bool scalar);
  uint mesh_attribute_texture(Node& tex, Texture& t, bool scalar);
  // mesh_attribute textures: the attribute names by Texture.attribute_slot, and per texture
  // record what it reads and how (channels: 0 Mitsuba's eval, 1 or 3 for eval_1 or eval_3).
  struct MeshAttributeRead {
    std::string name;
    Location loc;
    int channels = 0;
  };
  std::vector<std::string> attribute_names_;
  std::map<uint, MeshAttributeRead> mesh_attribute_reads_;
  // Linear RGBA texels of an image file appended to texels (shared between identical loads);
  // returns the first texel and the size.
  std::pair<uint, glm::uvec2> load_texels(Node& owner, const std::string& file_name, bool raw,
                                          bool scalar, TexelFormat format);
  std::string resolve_file(Node& owner, const std::string& name, const char* what);

  // ---- shapes (build_shapes.cpp)
  // File contents by path and uv flip (obj, ply) or mesh index (serialized).
  std::map<std::string, TriangleMesh> mesh_cache_;
  std::vector<PendingShape> top_shapes_;
  std::vector<PendingGroup> groups_;
  std::map<const Node*, uint> group_index_;
  struct PendingInstance {
    uint group;
    glm::dmat4 to_world;
    uint scene_index = 0;
  };
  std::vector<PendingInstance> instances_;
  // The object-space mesh of an obj, ply or serialized shape (`filename` and the parameters
  // that select what is read from it; `face_normals`: an OBJ file's vn lines are not read).
  const TriangleMesh& mesh_file(Node& shape, bool face_normals);
  void add_shape(Node& shape, std::vector<PendingShape>& out, bool in_group);
  // Checks that the shape has every mesh attribute its material's textures read, with a
  // channel count Mitsuba accepts there, and records which (PendingShape::attribute_slots).
  void bind_mesh_attributes(Node& shape, PendingShape& s);
  void collect_mesh_attribute_textures(uint material, std::vector<uint>& textures) const;
  void add_shapegroup(Node& group);
  void add_instance(Node& instance);
  // Top-level shapes (false, index into top_shapes_) and instances (true, into instances_) in
  // document order.
  std::vector<std::pair<bool, size_t>> top_level_order_;
  void number_shapes_as_mitsuba();
  void finalize_shapes();

  // ---- emitters (build_emitters.cpp)
  struct PendingEmitter {
    Emitter record{};
    Location loc;
    double sampling_weight = 1.0;
  };
  std::vector<PendingEmitter> emitters_;  // non-area emitters, document order
  // Each record of SceneBuffers::emitters with its `sampling_weight` and its XML location.
  std::vector<std::pair<double, Location>> emitter_weights_;
  void add_emitter(Node& emitter);
  Emitter build_spot(Node& emitter);
  void refuse_mesh_attribute(Node& emitter, const char* name, const TexturedValue& v) const;
  // An area emitter's textured `name` (a bitmap or checkerboard of no negative value): its
  // index in SceneBuffers::textures.
  uint emitted_texture(Node& emitter, const char* name);
  Emitter build_projector(Node& emitter);
  void finalize_emitters();
  // Mitsuba 3's per-emitter `sampling_weight` (src/render/emitter.cpp): finite, >= 0, default 1.
  static double take_sampling_weight(Node& emitter);

  // ---- sensor, film, sampler, integrator (build_sensor.cpp)
  void add_sensor(Node& sensor);
  void add_integrator(Node& integrator);
};

// Row-major 3x4 rows (core/scene_types.h) of an affine transform.
void store_rows(const glm::dmat4& m, vec4 rows[3]);

// Mitsuba's parse_fov (src/render/sensor.cpp): the horizontal field of view in degrees of a
// sensor or projector whose image has this aspect (width / height), from `fov` + `fov_axis`
// or `focal_length`.
double horizontal_fov(Node& s, double aspect);

}  // namespace tr
