// Host/device scene records: one definition, shared by the C++ host and the GLSL shaders.
// Every struct is std430-safe: members are grouped so that each vec3 is followed by a 4-byte
// scalar, vec4/uvec4 sit on 16-byte boundaries, and every struct's size is a multiple of 16
// (checked by static_asserts in scenes/scene.h). Row-major 3x4 affine transforms are stored
// as three vec4 rows; apply them with the helpers in core/transform.h.
#ifndef TWINRAY_CORE_SCENE_TYPES_H
#define TWINRAY_CORE_SCENE_TYPES_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// ---- Textures --------------------------------------------------------------------------
const uint TEXTURE_BITMAP = 0u;
const uint TEXTURE_CHECKERBOARD = 1u;
const uint TEXTURE_MESH_ATTRIBUTE = 2u;  // Mitsuba `mesh_attribute` (core/texture.h)

const uint FILTER_NEAREST = 0u;
const uint FILTER_BILINEAR = 1u;

const uint WRAP_REPEAT = 0u;
const uint WRAP_MIRROR = 1u;
const uint WRAP_CLAMP = 2u;

struct Texture {
  uint type;          // TEXTURE_*
  uint filter_mode;   // FILTER_* (bitmap)
  uint wrap_mode;     // WRAP_* (bitmap)
  uint texel_offset;  // first texel in the texel buffer (bitmap), row-major, top row first
  uint width;
  uint height;
  uint attribute_slot;      // mesh_attribute: entry of Shape.attribute_table (the name)
  uint attribute_per_face;  // mesh_attribute: 1 for a face_* attribute, 0 for vertex_*
  vec4 color0;              // checkerboard color0; mesh_attribute: `scale` in x
  vec4 color1;              // checkerboard color1
  vec4 to_uv[2];            // rows of the 2x3 affine uv transform (Mitsuba `to_uv`)
};

// A BSDF parameter that is either a constant or a texture lookup (texture != NO_INDEX).
// Scalar parameters use value.x.
struct TexturedValue {
  vec3 value;
  uint texture;
};

// ---- Materials (BSDFs) -----------------------------------------------------------------
const uint BSDF_DIFFUSE = 0u;
const uint BSDF_CONDUCTOR = 1u;
const uint BSDF_ROUGHCONDUCTOR = 2u;
const uint BSDF_DIELECTRIC = 3u;
const uint BSDF_ROUGHDIELECTRIC = 4u;
const uint BSDF_THINDIELECTRIC = 5u;
const uint BSDF_PLASTIC = 6u;
const uint BSDF_ROUGHPLASTIC = 7u;
const uint BSDF_PRINCIPLED = 8u;
const uint BSDF_PPLASTIC = 9u;
const uint BSDF_BLEND = 10u;      // Mitsuba `blendbsdf`, children by material index
const uint BSDF_NORMALMAP = 11u;  // Mitsuba `normalmap` around a material (by index)
const uint BSDF_BUMPMAP = 12u;    // Mitsuba `bumpmap` around a material (by index)

// Material.flags
const uint MATERIAL_TWOSIDED = 1u;        // Mitsuba `twosided` wrapper
const uint MATERIAL_MASKED = 2u;          // Mitsuba `mask` wrapper, opacity in Material.opacity
const uint MATERIAL_BECKMANN = 4u;        // microfacet distribution (GGX when clear)
const uint MATERIAL_SAMPLE_VISIBLE = 8u;  // microfacet `sample_visible`
const uint MATERIAL_NONLINEAR = 16u;      // plastic / roughplastic `nonlinear`
const uint MATERIAL_ALPHA_TESTED = 32u;   // twinray `alphatest` wrapper (core/alpha_test.h)
const uint MATERIAL_TEXTURED =
    64u;  // a parameter slot or the opacity reads a texture (material_at)

// Parameter slots, per BSDF type (Material.param[i]); see core/bsdf/*.h for their meaning.
const uint MATERIAL_PARAM_COUNT = 12u;

struct Material {
  uint type;              // BSDF_*
  uint flags;             // MATERIAL_*
  float eta;              // relative IOR int_ior / ext_ior (dielectrics, plastics, principled)
  float extra;            // per-type scalar (e.g. principled sampling rates), see core/bsdf/*.h
  TexturedValue opacity;  // opacity of MATERIAL_MASKED or MATERIAL_ALPHA_TESTED
  TexturedValue param[MATERIAL_PARAM_COUNT];
  float alpha_cutoff;  // MATERIAL_ALPHA_TESTED: the surface is absent where opacity < alpha_cutoff
  uint lobes;  // BSDF_BLEND: the union of its leaves' BSDF_* lobes (core/bsdf.h, blend_lobes)
  uint pad1;
  uint pad2;
};

// ---- Geometry --------------------------------------------------------------------------
const uint SHAPE_MESH = 0u;      // triangles: index buffer + vertex buffers
const uint SHAPE_SPHERE = 1u;    // unit sphere at the origin, through to_world
const uint SHAPE_DISK = 2u;      // unit disk in the z=0 plane, normal +z, through to_world
const uint SHAPE_CYLINDER = 3u;  // radius 1, z in [0,1], no caps, through to_world

// Shape.flags
const uint SHAPE_HAS_NORMALS = 1u;   // per-vertex shading normals present
const uint SHAPE_HAS_UVS = 2u;       // per-vertex uvs present
const uint SHAPE_FLIP_NORMALS = 4u;  // Mitsuba `flip_normals`
const uint SHAPE_HAS_TANGENTS = 8u;  // twinray `vertex_tangents`: Shape.tangent_frames is set

struct Shape {
  uint type;            // SHAPE_*
  uint flags;           // SHAPE_*
  uint material;        // index into materials
  uint emitter;         // index into emitters, or NO_INDEX
  uint first_index;     // meshes: offset into the index buffer (3 indices per triangle)
  uint triangle_count;  // meshes: number of triangles
  uint first_vertex;    // meshes: added to every index
  uint vertex_count;
  vec4 to_world[3];      // analytic shapes: object->world (mesh vertices are pre-transformed)
  vec4 to_object[3];     // analytic shapes: world->object
  float area;            // world-space surface area
  uint scene_index;      // position in Mitsuba's Scene::shapes() (scenes/build_shapes.cpp,
                         // number_shapes_as_mitsuba)
  uint prim_offset;      // Mitsuba's prim_index of triangle 0 (meshes merged into one), or
                         // NO_INDEX: one primitive (sphere, disk, cylinder)
  uint attribute_table;  // meshes read by mesh_attribute textures: first word of this mesh's
                         // table in the attribute buffer (core/texture.h), else NO_INDEX
  uint tangent_frames;   // SHAPE_HAS_TANGENTS: first word, in the attribute buffer, of the
                         // vertex tangents (3 floats a vertex), then the bitangents (same)
  uint pad1;
  uint pad2;
  uint pad3;
};

// An instance places a range of shapes (a top-level set or a Mitsuba `shapegroup`) in the
// world. Shapes outside any shapegroup belong to instance 0, whose transform is the identity.
struct Instance {
  vec4 to_world[3];
  vec4 to_object[3];
  uint first_shape;
  uint shape_count;
  uint scene_index;  // as Shape.scene_index, for the instance itself (unused by instance 0)
  uint pad1;
};

// ---- Emitters --------------------------------------------------------------------------
const uint EMITTER_AREA = 0u;
const uint EMITTER_POINT = 1u;
const uint EMITTER_DIRECTIONAL = 2u;
const uint EMITTER_CONSTANT = 3u;
const uint EMITTER_ENVMAP = 4u;
const uint EMITTER_SPOT = 5u;
const uint EMITTER_PROJECTOR = 6u;

struct Emitter {
  uint type;          // EMITTER_*
  uint shape;         // area: the emitting shape
  uint alias_offset;  // area meshes: per-triangle alias table; envmap: per-texel alias table
  uint alias_count;
  vec3 radiance;    // area, constant: radiance; point, spot: intensity; directional:
                    // irradiance; projector: irradiance when untextured
  uint light_leaf;  // EMITTER_SELECTION_BVH: its leaf in light_nodes, NO_INDEX outside the tree
                    // (scenes/emitter_selection.cpp); read with no other selection
  // area: its shape's type, flags, first_index, first_vertex and area, copied here so that a
  // light sample on a mesh and its density read this record's first 64 bytes and not also the
  // shape's (with many emitters, each record read is a cache miss on the sample's path).
  uint shape_type;
  uint shape_flags;
  uint first_index;
  uint first_vertex;
  float area;
  uint texture;      // envmap: its bitmap; spot, projector: their texture, or NO_INDEX
  float scale;       // envmap, projector: `scale`
  float tan_cutoff;  // spot: tan(cutoff_angle), the texture's uv scale
  vec3 position;     // point, spot, projector: position
  uint pad0;
  vec3 direction;  // directional: unit direction of travel; projector: to_world (0, 0, 1)
  uint pad1;
  vec4 to_world[3];  // envmap: rotation local->world; area, a mesh of one triangle: its vertices
  vec4 to_local[3];  // envmap, spot, projector: world->local; area, a mesh of one triangle with
                     // vertex normals: its normals (scenes/build_shapes.cpp)
  vec4 cone;         // spot: cos(cutoff), cos(beam_width), cutoff, 1 / (cutoff - beam_width);
                     // projector: uv scales cot(fov_x / 2) / 2 and aspect cot(fov_x / 2) / 2
};

// Walker/Vose alias table entry (Vose 1991): pick bin i = floor(u * n); keep it with
// probability q, otherwise take `alias`. `pmf` is bin i's own probability.
struct AliasEntry {
  float q;
  uint alias;
  float pmf;
  uint pad;
};

// ---- Emitter selection (core/emitter.h) ------------------------------------------------
// Which emitter a light sample starts from. UNIFORM is Mitsuba's: the scene's alias table over
// `sampling_weight` (uniform by default). POWER: an alias table over power times sampling_weight
// (pbrt-v4's PowerLightSampler). BVH: a light BVH over the emitters with a position (Conty
// Estevez & Kulla 2018; pbrt-v4 §12.6.3, BVHLightSampler), the infinite ones chosen apart.
const uint EMITTER_SELECTION_UNIFORM = 0u;
const uint EMITTER_SELECTION_POWER = 1u;
const uint EMITTER_SELECTION_BVH = 2u;

// A node of the light BVH (core/light_bvh.h): a sphere holding the emitters below it (around
// their bounding box), their summed power phi, and a cone around w holding every direction of
// their surface normals (or their emission axis) with half-angle theta_o; emission reaches at
// most theta_e beyond that cone. An interior node has 2 to LIGHT_BVH_WIDTH children, stored
// side by side so that one descent step reads one contiguous group; the groups are in
// depth-first order, each node's group before the groups below it, so that the nodes a descent
// visits near the leaves lie together in memory (emitters listed in scene order would scatter
// them). A leaf has child_count 0 and its emitter; Emitter.light_leaf leads back to it.
const uint LIGHT_BVH_WIDTH = 4u;

struct LightNode {
  vec3 centre;
  float radius;
  vec3 w;
  float phi;
  float cos_theta_o;
  float sin_theta_o;
  float cos_theta_e;
  uint first_child;  // interior: its children are first_child .. first_child + child_count - 1
  uint child_count;  // 0 for leaves
  uint emitter;      // leaves: the emitter; NO_INDEX for interior nodes
  uint parent;       // NO_INDEX at the root
  uint pad0;
};

// ---- Camera, film, integrator ----------------------------------------------------------
const uint SENSOR_PERSPECTIVE = 0u;
const uint SENSOR_THINLENS = 1u;
const uint SENSOR_ORTHOGRAPHIC = 2u;

// Reconstruction filters (core/rfilter.h). Every filter but the box is sampled through its
// table (core/film.h).
const uint RFILTER_BOX = 0u;
const uint RFILTER_GAUSSIAN = 1u;
const uint RFILTER_TENT = 2u;
const uint RFILTER_MITCHELL = 3u;
const uint RFILTER_CATMULLROM = 4u;
const uint RFILTER_LANCZOS = 5u;

const uint INTEGRATOR_PATH = 0u;
const uint INTEGRATOR_DIRECT = 1u;
const uint INTEGRATOR_AMBIENT_OCCLUSION = 2u;  // pbrt-v4's `ambientocclusion`

// Output variables of Mitsuba's `aov` integrator (src/integrators/aov.cpp), at most AOV_MAX.
const uint AOV_ALBEDO = 0u;
const uint AOV_DEPTH = 1u;
const uint AOV_POSITION = 2u;
const uint AOV_UV = 3u;
const uint AOV_GEO_NORMAL = 4u;
const uint AOV_SH_NORMAL = 5u;
const uint AOV_PRIM_INDEX = 6u;
const uint AOV_SHAPE_INDEX = 7u;
const uint AOV_MAX = 16u;

// Positions on the film are in pixels of the full film, origin at its top-left corner.
struct Camera {
  vec4 to_world[3];  // camera->world; camera looks along +z, +x left, +y up (Mitsuba)
  uint type;         // SENSOR_*
  uint width;        // rendered image (the film's crop window) in pixels
  uint height;
  uint rfilter;  // RFILTER_*
  // Camera-space half-size of the image rectangle: at z = 1 (perspective, thinlens: the
  // tangents of half the fields of view) or on the near plane (orthographic).
  vec2 half_extent;
  vec2 principal_point;  // Mitsuba principal_point_offset_{x,y}, in fractions of the film
  float near_clip;
  float far_clip;
  float aperture_radius;  // thinlens
  float focus_distance;   // thinlens
  vec2 film_size;         // the full film (the frame of the projection)
  vec2 crop_offset;       // top-left corner of the rendered crop window
  vec2 sample_min;        // the rectangle sampled (the crop window, widened by the filter's
  vec2 sample_max;        // border with sample_border)
  float filter_radius;
  float filter_scale;  // FILTER_RESOLUTION / filter_radius: table index of |x| (core/film.h)
  uint pad0;
  uint pad1;
  vec4 filter_table[8];  // Mitsuba's discretized filter, entries 0..31 (core/rfilter.h)
  vec4 filter_cdf[16];   // cumulative |filter| over the 62 bins of an axis (core/film.h)
};

struct Integrator {
  uint type;      // INTEGRATOR_*
  int max_depth;  // -1: unbounded (Mitsuba semantics)
  int rr_depth;
  uint hide_emitters;
  uint emitter_samples;  // direct
  uint bsdf_samples;     // direct
  float max_distance;    // ambientocclusion: occluders count up to it (FLOAT_MAX: infinity)
  uint cos_sample;       // ambientocclusion: 1 cosine-weighted, 0 uniform directions
  uint aov_count;        // Mitsuba `aov`: output variables per sample (core/integrators/aov.h)
  int min_depth;         // path: light of paths shorter than it is not counted (twinray extension)
  uint strict_normals;   // path, direct: Mitsuba 0.6's strictNormals (core/integrator.h)
  uint pad4;
  uvec4 aov_types[4];  // AOV_* of output variable i at [i / 4][i % 4]
};

// ---- Samplers (core/rng.h draws their points) --------------------------------------------
const uint SAMPLER_INDEPENDENT = 0u;
const uint SAMPLER_STRATIFIED = 1u;   // core/samplers/stratified.h
const uint SAMPLER_LDSAMPLER = 2u;    // core/samplers/ldsampler.h
const uint SAMPLER_MULTIJITTER = 3u;  // core/samplers/multijitter.h
const uint SAMPLER_ORTHOGONAL = 4u;   // core/samplers/orthogonal.h
const uint SAMPLER_ZSOBOL = 5u;       // core/samplers/zsobol.h
const uint SAMPLER_SOBOL = 6u;        // core/samplers/sobol.h

// The scene's sampler. A pixel's samples come in passes of sample_count: within a pass each
// dimension's points are stratified (Mitsuba semantics, after its sample_count rounding).
struct Sampler {
  uint type;          // SAMPLER_*
  uint sample_count;  // points of one pass (rounded as Mitsuba rounds it); independent: 1
  uvec2 resolution;   // stratified: sqrt(sample_count) twice; multijitter: its grid;
                      // orthogonal: the prime p twice; zsobol: the film's width and the base-4
                      // digits of its Morton indices
  uint jitter;        // stratified, multijitter, orthogonal: 1 to jitter within strata, 0 for
                      // their centers
  float inv_sample_count;
  vec2 inv_resolution;
};

struct SceneGlobals {
  Camera camera;
  Integrator integrator;
  uint emitter_count;
  uint emitter_alias_offset;  // UNIFORM, POWER: the emitter selection table
  uint environment;           // the constant/envmap emitter, or NO_INDEX
  uint instance_count;
  uint emitter_selection;  // EMITTER_SELECTION_*
  // BVH: the root of the light BVH (NO_INDEX: no emitter has a position), the alias table
  // choosing among the infinite emitters (constant, envmap, directional) by sampling_weight,
  // and the probability of choosing an infinite emitter rather than the tree.
  uint light_root;
  uint infinite_alias_offset;
  float infinite_probability;
  Sampler sampler_params;
};

TR_NAMESPACE_END

#endif
