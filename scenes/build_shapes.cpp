// Shape plugins -> Shape/Instance records and vertex buffers. Meshes outside shapegroups are
// pre-transformed to world space; analytic shapes keep a canonical object and its transforms
// (core/scene_types.h). Semantics follow Mitsuba 3's src/shapes/*.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>

#include "core/frame.h"
#include "core/material_slots.h"
#include "scenes/alias_table.h"
#include "scenes/obj_file.h"
#include "scenes/scene_builder.h"
#include "scenes/serialized.h"

namespace tr {

namespace {

const double PI_D = 3.14159265358979323846;

glm::dmat4 translation(glm::dvec3 t) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

glm::dmat4 scaling(glm::dvec3 s) {
  glm::dmat4 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  m[2][2] = s.z;
  return m;
}

// Fails unless the linear part of `m` maps the given axes to mutually orthogonal vectors of
// equal length (a similarity on them), the condition under which the analytic shape's area
// formula holds; returns that common length.
double similarity_scale(const Node& n, const glm::dmat4& m, bool include_z) {
  glm::dvec3 c0(m[0]), c1(m[1]), c2(m[2]);
  double l0 = glm::length(c0), l1 = glm::length(c1);
  double tol = 1e-5;
  bool ok =
      std::abs(l0 - l1) <= tol * std::max(l0, l1) && std::abs(glm::dot(c0, c1)) <= tol * l0 * l1;
  if (include_z) {
    double l2 = glm::length(c2);
    ok = ok && std::abs(l2 - l0) <= tol * std::max(l0, l2) &&
         std::abs(glm::dot(c0, c2)) <= tol * l0 * l2 && std::abs(glm::dot(c1, c2)) <= tol * l1 * l2;
  }
  if (!ok || !(l0 > 0.0))
    fail(n.loc, describe(n),
         ": to_world must be a rotation, translation and uniform scale for this analytic shape");
  return l0;
}

void set_transforms(Shape& r, const glm::dmat4& m) {
  store_rows(m, r.to_world);
  store_rows(glm::inverse(m), r.to_object);
}

}  // namespace

const TriangleMesh& SceneBuilder::mesh_file(Node& n, bool face_normals) {
  std::string path = resolve_file(n, take_string(n, "filename"), "mesh file");
  const Location& file_loc = find_property(n, "filename")->loc;
  if (n.type == "serialized") {
    Property* index_property = find_property(n, "shape_index");
    long long index = take_integer(n, "shape_index", 0);
    if (index < 0 || index > std::numeric_limits<int>::max())
      fail(index_property->loc, path, ": shape_index must be a non-negative int, not ", index);
    std::string key = path + "|serialized@" + std::to_string(index);
    auto cached = mesh_cache_.find(key);
    if (cached != mesh_cache_.end()) return cached->second;
    try {
      return mesh_cache_.emplace(key, load_serialized_mesh(path, uint32_t(index)).mesh)
          .first->second;
    } catch (const ShapeIndexError& e) {
      fail(index_property ? index_property->loc : file_loc, path, ": ", e.what());
    } catch (const std::exception& e) {
      fail(file_loc, path, ": ", e.what());
    }
  } else {
    bool flip_tex = take_bool(n, "flip_tex_coords", n.type == "obj");
    const bool obj = n.type == "obj";
    std::string key = path + (obj ? "|obj" : "|ply") + (flip_tex ? "|flip" : "") +
                      (obj && face_normals ? "|face_normals" : "");
    auto cached = mesh_cache_.find(key);
    if (cached != mesh_cache_.end()) return cached->second;
    try {
      TriangleMesh mesh =
          obj ? read_obj_file(path, flip_tex, face_normals) : load_ply_mesh(path, flip_tex);
      return mesh_cache_.emplace(key, std::move(mesh)).first->second;
    } catch (const std::exception& e) {
      fail(file_loc, path, ": ", e.what());
    }
  }
}

void SceneBuilder::add_shape(Node& n, std::vector<PendingShape>& out, bool in_group) {
  PendingShape s;
  Shape& r = s.record;
  r.flags = 0u;
  r.emitter = NO_INDEX;
  r.first_index = r.triangle_count = r.first_vertex = r.vertex_count = 0u;
  r.scene_index = r.prim_offset = 0u;
  r.attribute_table = NO_INDEX;
  r.tangent_frames = NO_INDEX;
  r.pad1 = r.pad2 = r.pad3 = 0u;
  set_transforms(r, glm::dmat4(1.0));

  glm::dmat4 to_world = take_transform(n, "to_world");
  if (std::abs(glm::determinant(glm::dmat3(to_world))) == 0.0)
    fail(find_property(n, "to_world")->loc, describe(n), ": to_world is singular");
  if (take_bool(n, "flip_normals", false)) r.flags |= SHAPE_FLIP_NORMALS;
  // Read by every Mitsuba shape (shape.cpp); it weighs silhouette sampling in differentiable
  // rendering only, so it changes nothing here.
  take_float(n, "silhouette_sampling_weight", 1.0);

  std::vector<Property*> bsdfs = take_objects(n, "bsdf");
  if (bsdfs.size() > 1) fail(bsdfs[1]->loc, describe(n), " has more than one BSDF");
  std::vector<Property*> emitters = take_objects(n, "emitter");
  if (emitters.size() > 1) fail(emitters[1]->loc, describe(n), " has more than one emitter");
  r.material = bsdfs.empty() ? default_material(!emitters.empty()) : material(*bsdfs[0]->object);
  if (!emitters.empty()) {
    Node& e = *emitters[0]->object;
    if (in_group) fail(e.loc, "emitters inside a <shapegroup> are not supported");
    if (e.type != "area")
      fail(e.loc, "a shape can only carry an \"area\" emitter, not \"", e.type, "\"");
    if (has_property(e, "to_world"))
      fail(find_property(e, "to_world")->loc, describe(e),
           ": an area emitter takes its shape's transform; to_world is refused (as in Mitsuba)");
    Property* rad = find_property(e, "radiance");
    if (rad && rad->kind == PropertyKind::Object) {
      s.radiance_texture = emitted_texture(e, "radiance");
      s.radiance = glm::vec3(1.0f);  // the texture holds the radiance
    } else {
      glm::dvec3 radiance = take_color(e, "radiance", glm::dvec3(1.0));
      if (glm::any(glm::lessThan(radiance, glm::dvec3(0.0))))
        fail(rad->loc, describe(e), ": radiance must not be negative");
      s.radiance = glm::vec3(radiance);
    }
    s.sampling_weight = take_sampling_weight(e);
    check_consumed(e);
    s.emitting = true;
    s.emitter_loc = e.loc;
  }

  const std::string& type = n.type;
  bool from_file = type == "obj" || type == "ply" || type == "serialized";
  s.mitsuba_mesh = from_file || type == "rectangle" || type == "cube";
  if (!s.mitsuba_mesh) r.prim_offset = NO_INDEX;
  if (from_file || type == "rectangle" || type == "cube") {
    r.type = SHAPE_MESH;
    bool face_normals = take_bool(n, "face_normals", false);  // every Mitsuba mesh reads it
    if (from_file) {
      s.mesh = mesh_file(n, face_normals);
      // Mitsuba 3.8's serialized loader skips the vertex colors (src/shapes/serialized.cpp):
      // such a mesh has no attributes there.
      if (type == "serialized") s.mesh.attributes.clear();
    } else {
      s.mesh = type == "rectangle" ? make_rectangle() : make_cube();
    }
    if (type == "ply" && take_bool(n, "vertex_tangents", false)) {
      try {
        s.tangent_frames = mesh_tangent_frames(s.mesh, to_world);
      } catch (const std::runtime_error& e) {
        fail(find_property(n, "vertex_tangents")->loc, describe(n), ": ", e.what());
      }
      r.flags |= SHAPE_HAS_TANGENTS;
    }
    transform_mesh(s.mesh, to_world);
    if (face_normals)
      s.mesh.normals.clear();
    else if (s.mesh.normals.empty())
      s.mesh.normals = mesh_vertex_normals(s.mesh);  // Mitsuba recomputes after to_world
    if (!s.mesh.normals.empty()) r.flags |= SHAPE_HAS_NORMALS;
    if (!s.mesh.uvs.empty()) r.flags |= SHAPE_HAS_UVS;
    r.triangle_count = uint(s.mesh.indices.size() / 3);
    r.vertex_count = uint(s.mesh.positions.size());
    double area = 0.0;
    for (size_t t = 0; t < r.triangle_count; ++t) area += triangle_area(s.mesh, t);
    r.area = float(area);
  } else if (type == "sphere") {
    r.type = SHAPE_SPHERE;
    glm::dvec3 center = take_point(n, "center", glm::dvec3(0.0));
    double radius = take_float(n, "radius", 1.0);
    if (!(radius > 0.0)) fail(n.loc, describe(n), ": radius must be positive");
    glm::dmat4 m = to_world * translation(center) * scaling(glm::dvec3(radius));
    double world_radius = similarity_scale(n, m, true);
    set_transforms(r, m);
    r.area = float(4.0 * PI_D * world_radius * world_radius);
  } else if (type == "disk") {
    r.type = SHAPE_DISK;
    set_transforms(r, to_world);
    // The unit disk's image under an affine map has area pi |M e_x x M e_y|.
    r.area =
        float(PI_D * glm::length(glm::cross(glm::dvec3(to_world[0]), glm::dvec3(to_world[1]))));
  } else if (type == "cylinder") {
    r.type = SHAPE_CYLINDER;
    double radius = take_float(n, "radius", 1.0);
    glm::dvec3 p0 = take_point(n, "p0", glm::dvec3(0.0));
    glm::dvec3 p1 = take_point(n, "p1", glm::dvec3(0.0, 0.0, 1.0));
    double length = glm::length(p1 - p0);
    if (!(radius > 0.0) || !(length > 0.0))
      fail(n.loc, describe(n), ": needs a positive radius and p0 != p1");
    // Mitsuba: to_world * translate(p0) * to_frame(Frame(d)) * scale(r, r, length), with the
    // frame of Duff et al. 2017 (core/frame.h).
    glm::dvec3 d = (p1 - p0) / length;
    Frame f = frame_from_normal(vec3(d));
    glm::dmat4 frame(1.0);
    frame[0] = glm::dvec4(glm::dvec3(f.s), 0.0);
    frame[1] = glm::dvec4(glm::dvec3(f.t), 0.0);
    frame[2] = glm::dvec4(d, 0.0);
    glm::dmat4 m = to_world * translation(p0) * frame * scaling(glm::dvec3(radius, radius, length));
    double world_radius = similarity_scale(n, m, false);
    glm::dvec3 axis(m[2]);
    if (std::abs(glm::dot(axis, glm::dvec3(m[0]))) > 1e-5 * glm::length(axis) * world_radius ||
        std::abs(glm::dot(axis, glm::dvec3(m[1]))) > 1e-5 * glm::length(axis) * world_radius)
      fail(n.loc, describe(n), ": to_world must not shear the cylinder");
    set_transforms(r, m);
    r.area = float(2.0 * PI_D * world_radius * glm::length(axis));
  } else if (type == "shapegroup" || type == "instance") {
    fail(n.loc, "<shape type=\"", type, "\"> cannot be nested here");
  } else {
    fail(n.loc, "unknown shape type \"", type,
         "\" (supported: obj, ply, serialized, rectangle, cube, sphere, disk, cylinder, "
         "shapegroup, instance)");
  }
  if (s.radiance_texture != NO_INDEX && r.type == SHAPE_MESH && !(r.flags & SHAPE_HAS_UVS))
    fail(find_property(*emitters[0]->object, "radiance")->loc, describe(n),
         ": a textured radiance needs a mesh with uv coordinates (Mitsuba places the texture "
         "through them and fails without)");
  if (b_.materials[r.material].flags & MATERIAL_ALPHA_TESTED) {
    // core/alpha_test.h: the any-hit test reads mesh uvs; an emitter's area sampling would
    // also land on the cut-away parts.
    if (r.type != SHAPE_MESH)
      fail(bsdfs[0]->loc, describe(n), ": an alphatest BSDF needs a mesh, not an analytic ", type);
    if (s.emitting) fail(s.emitter_loc, describe(n), ": an alphatest surface cannot emit");
  }
  check_consumed(n);
  bind_mesh_attributes(n, s);
  out.push_back(std::move(s));
}

void SceneBuilder::collect_mesh_attribute_textures(uint material,
                                                   std::vector<uint>& textures) const {
  const Material& m = b_.materials[material];
  auto add = [&](const TexturedValue& v) {
    if (v.texture != NO_INDEX && b_.textures[v.texture].type == TEXTURE_MESH_ATTRIBUTE &&
        std::find(textures.begin(), textures.end(), v.texture) == textures.end())
      textures.push_back(v.texture);
  };
  add(m.opacity);
  for (const TexturedValue& v : m.param) add(v);
  if (m.type == BSDF_BLEND) {
    collect_mesh_attribute_textures(uint(m.param[BLEND_BSDF_0].value.x), textures);
    collect_mesh_attribute_textures(uint(m.param[BLEND_BSDF_1].value.x), textures);
  } else if (m.type == BSDF_NORMALMAP || m.type == BSDF_BUMPMAP) {
    collect_mesh_attribute_textures(uint(m.param[NORMALMAP_BSDF].value.x), textures);
  }
}

// Mitsuba evaluates a mesh_attribute texture through the shape hit (Shape::eval_attribute),
// and fails while rendering when that shape has no such attribute or one of a size the
// evaluation cannot take (src/render/mesh.cpp: eval takes 1 or 3 channels, eval_1 1, eval_3 3);
// here each case is an error when loading.
void SceneBuilder::bind_mesh_attributes(Node& n, PendingShape& s) {
  std::vector<uint> textures;
  collect_mesh_attribute_textures(s.record.material, textures);
  for (uint t : textures) {
    const MeshAttributeRead& read = mesh_attribute_reads_.at(t);
    const std::string where = read.loc.file + ":" + std::to_string(read.loc.line);
    auto it = s.mesh.attributes.find(read.name);
    if (s.record.type != SHAPE_MESH || it == s.mesh.attributes.end()) {
      std::string present;
      for (const auto& [name, a] : s.mesh.attributes)
        present += (present.empty() ? "" : ", ") + name;
      fail(n.loc, describe(n), " has no mesh attribute \"", read.name,
           "\", which the mesh_attribute texture at ", where, " reads (",
           s.record.type != SHAPE_MESH ? "only meshes have attributes"
           : present.empty()           ? "it has none"
                                       : "it has: " + present,
           ")");
    }
    const int dim = it->second.dim;
    const bool ok = read.channels == 0 ? dim == 1 || dim == 3 : dim == read.channels;
    if (!ok)
      fail(n.loc, describe(n), ": its mesh attribute \"", read.name, "\" has ", dim,
           " channels; the mesh_attribute texture at ", where, " is read as ",
           read.channels == 0   ? "a color (1 or 3 channels"
           : read.channels == 1 ? "a scalar (1 channel"
                                : "a normal map (3 channels",
           ", as in Mitsuba)");
    uint slot = b_.textures[t].attribute_slot;
    if (std::find(s.attribute_slots.begin(), s.attribute_slots.end(), slot) ==
        s.attribute_slots.end())
      s.attribute_slots.push_back(slot);
  }
}

void SceneBuilder::add_shapegroup(Node& g) {
  if (group_index_.count(&g)) return;
  PendingGroup group;
  for (Property* p : take_objects(g, "shape")) add_shape(*p->object, group.shapes, true);
  if (group.shapes.empty()) fail(g.loc, describe(g), " contains no shapes");
  check_consumed(g);
  group_index_[&g] = uint(groups_.size());
  groups_.push_back(std::move(group));
}

void SceneBuilder::add_instance(Node& inst) {
  glm::dmat4 to_world = take_transform(inst, "to_world");
  if (glm::determinant(glm::dmat3(to_world)) == 0.0)
    fail(find_property(inst, "to_world")->loc, describe(inst), ": to_world is singular");
  std::vector<Property*> shapes = take_objects(inst, "shape");
  if (shapes.size() != 1 || shapes[0]->object->type != "shapegroup")
    fail(inst.loc, describe(inst), " must reference exactly one shapegroup");
  Node& g = *shapes[0]->object;
  add_shapegroup(g);
  check_consumed(inst);
  instances_.push_back({group_index_[&g], to_world});
}

// Mitsuba 3.8's parser (src/core/parser.cpp) reorders the scene's children, area-emitting
// shapes before the others (transform_reorder), then hands them all to a `merge` shape
// (transform_merge_meshes, src/shapes/merge.cpp), which passes non-meshes through in order and
// merges meshes of equal BSDF, emitter, vertex normals and uvs into one mesh, appending each
// later mesh's triangles; the merged meshes come last. Scene::shapes() is that list without
// shapegroups (src/render/scene.cpp). Mitsuba lists the merged meshes in the order of a hash
// table keyed by object addresses; here they follow their first member. Equal BSDFs: the
// parser merges equivalent objects (transform_merge_equivalent), here equal Material records.
void SceneBuilder::number_shapes_as_mitsuba() {
  uint next = 0;
  for (bool emitting_pass : {true, false})
    for (const auto& [is_instance, i] : top_level_order_) {
      if (is_instance) {
        if (!emitting_pass) instances_[i].scene_index = next++;
      } else if (!top_shapes_[i].mitsuba_mesh && top_shapes_[i].emitting == emitting_pass) {
        top_shapes_[i].record.scene_index = next++;
      }
    }
  struct MergedMesh {
    uint scene_index;
    uint triangles;
  };
  // Meshes merge when neither emits nor has mesh attributes (Mitsuba's Mesh::merge refuses
  // those, src/render/mesh.cpp) and they share their material's bytes and the normal/uv flags:
  // the key of their group. Others stand alone. (A search over the groups was quadratic in a
  // scene of 1e5 emitting triangles.)
  std::map<std::string, MergedMesh> merged;
  for (bool emitting_pass : {true, false})
    for (const auto& [is_instance, i] : top_level_order_) {
      if (is_instance) continue;
      PendingShape& s = top_shapes_[i];
      if (!s.mitsuba_mesh || s.emitting != emitting_pass) continue;
      MergedMesh alone{next, 0u};
      MergedMesh* m = &alone;
      if (!s.emitting && s.mesh.attributes.empty()) {
        const uint flags = s.record.flags & (SHAPE_HAS_NORMALS | SHAPE_HAS_UVS);
        std::string key(reinterpret_cast<const char*>(&b_.materials[s.record.material]),
                        sizeof(Material));
        key.append(reinterpret_cast<const char*>(&flags), sizeof(flags));
        m = &merged.try_emplace(std::move(key), MergedMesh{next, 0u}).first->second;
      }
      if (m->scene_index == next) ++next;
      s.record.scene_index = m->scene_index;
      s.record.prim_offset = m->triangles;
      m->triangles += s.record.triangle_count;
    }
}

void SceneBuilder::finalize_shapes() {
  auto append = [&](PendingShape& s) {
    uint index = uint(b_.shapes.size());
    Shape& r = s.record;
    if (r.type == SHAPE_MESH) {
      r.first_vertex = uint(b_.positions.size());
      r.first_index = uint(b_.indices.size());
      for (size_t v = 0; v < s.mesh.positions.size(); ++v) {
        b_.positions.push_back(vec4(s.mesh.positions[v], 1.0f));
        b_.normals.push_back(s.mesh.normals.empty() ? vec4(0.0f) : vec4(s.mesh.normals[v], 0.0f));
        b_.uvs.push_back(s.mesh.uvs.empty() ? vec2(0.0f) : vec2(s.mesh.uvs[v]));
      }
      b_.indices.insert(b_.indices.end(), s.mesh.indices.begin(), s.mesh.indices.end());
      if (!s.attribute_slots.empty()) {
        // Table: per slot, the offset of the values and their count per element
        // (core/texture.h, eval_mesh_attribute); then the values read, as float bits.
        r.attribute_table = uint(b_.attributes.size());
        b_.attributes.resize(b_.attributes.size() + 2 * attribute_names_.size(), 0u);
        for (uint slot : s.attribute_slots) {
          const VertexAttribute& a = s.mesh.attributes.at(attribute_names_[slot]);
          b_.attributes[r.attribute_table + 2 * slot] = uint(b_.attributes.size());
          b_.attributes[r.attribute_table + 2 * slot + 1] = uint(a.dim);
          for (float v : a.values) b_.attributes.push_back(glm::floatBitsToUint(v));
        }
      }
      if (!s.tangent_frames.empty()) {
        r.tangent_frames = uint(b_.attributes.size());
        for (float v : s.tangent_frames) b_.attributes.push_back(glm::floatBitsToUint(v));
      }
    }
    if (s.emitting) {
      Emitter e{};
      e.type = EMITTER_AREA;
      e.shape = index;
      e.shape_type = r.type;
      e.shape_flags = r.flags;
      e.first_index = r.first_index;
      e.first_vertex = r.first_vertex;
      e.area = r.area;
      e.texture = s.radiance_texture;
      e.radiance = vec3(s.radiance);
      e.scale = 1.0f;
      e.alias_offset = NO_INDEX;
      e.alias_count = 0u;
      store_rows(glm::dmat4(1.0), e.to_world);
      store_rows(glm::dmat4(1.0), e.to_local);
      if (r.type == SHAPE_MESH) {
        // Area-proportional triangle choice within the mesh.
        std::vector<double> areas(r.triangle_count);
        for (size_t t = 0; t < areas.size(); ++t) areas[t] = triangle_area(s.mesh, t);
        std::vector<AliasEntry> table;
        try {
          table = build_alias_table(areas);
        } catch (const std::exception&) {
          fail(s.emitter_loc, "the mesh carrying this area emitter has zero area");
        }
        e.alias_offset = uint(b_.alias.size());
        e.alias_count = uint(table.size());
        b_.alias.insert(b_.alias.end(), table.begin(), table.end());
        if (r.triangle_count == 1u) {
          // A mesh of one triangle: its vertices and normals, as the buffers hold them, for a
          // light sample to read here (core/emitters/area.h, sample_mesh_area).
          for (int k = 0; k < 3; ++k) {
            const uint v = s.mesh.indices[k];
            e.to_world[k] = vec4(s.mesh.positions[v], 1.0f);
            e.to_local[k] = s.mesh.normals.empty() ? vec4(0.0f) : vec4(s.mesh.normals[v], 0.0f);
          }
        }
      }
      r.emitter = uint(b_.emitters.size());
      b_.emitters.push_back(e);
      emitter_weights_.push_back({s.sampling_weight, s.emitter_loc});
    }
    b_.shapes.push_back(r);
  };

  for (PendingShape& s : top_shapes_) append(s);
  Instance top{};
  store_rows(glm::dmat4(1.0), top.to_world);
  store_rows(glm::dmat4(1.0), top.to_object);
  top.first_shape = 0u;
  top.shape_count = uint(top_shapes_.size());
  b_.instances.push_back(top);

  for (PendingGroup& g : groups_) {
    g.first_shape = uint(b_.shapes.size());
    for (PendingShape& s : g.shapes) append(s);
  }
  for (const PendingInstance& pi : instances_) {
    const PendingGroup& g = groups_[pi.group];
    Instance inst{};
    store_rows(pi.to_world, inst.to_world);
    store_rows(glm::inverse(pi.to_world), inst.to_object);
    inst.first_shape = g.first_shape;
    inst.shape_count = uint(g.shapes.size());
    inst.scene_index = pi.scene_index;
    b_.instances.push_back(inst);
  }
}

}  // namespace tr
