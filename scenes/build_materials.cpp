// BSDF plugins -> Material records (slot meaning: core/material_slots.h), textures -> Texture
// records. Parameters, defaults and refusals are Mitsuba 3.8's (src/bsdfs/*.cpp,
// src/textures/*.cpp; tests/scenes/plugin_defaults_test.cpp pins them).
#include <Imath/half.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>
#include <tuple>

#include "core/bsdf.h"
#include "core/material_slots.h"
#include "scenes/bitmap.h"
#include "scenes/ior.h"
#include "scenes/scene_builder.h"
#include "scenes/values.h"

namespace tr {

namespace {

TexturedValue constant_value(glm::dvec3 v) {
  TexturedValue t;
  t.value = vec3(v);
  t.texture = NO_INDEX;
  return t;
}

Material empty_material(uint type) {
  Material m;
  m.type = type;
  m.flags = 0u;
  m.eta = 1.0f;
  m.extra = 0.0f;
  m.opacity = constant_value(glm::dvec3(1.0));
  for (uint i = 0; i < MATERIAL_PARAM_COUNT; ++i) m.param[i] = constant_value(glm::dvec3(0.0));
  m.alpha_cutoff = 0.0f;
  m.lobes = m.pad1 = m.pad2 = 0u;
  return m;
}

double luminance_d(glm::dvec3 c) { return 0.212671 * c.x + 0.715160 * c.y + 0.072169 * c.z; }

// eval_1 of a constant color: Mitsuba's srgb texture returns mean() there, the average of the
// three channels (src/spectra/srgb.cpp); a float (uniform texture) is its value, which the
// average of the broadcast color reproduces.
double scalar_of_constant(glm::dvec3 c) { return (c.x + c.y + c.z) / 3.0; }

// Mitsuba's lookup_ior (include/mitsuba/render/ior.h): a <float>, or a name from the IOR
// table; it reads anything else, an <integer> included, as a string and fails.
double ior_parameter(Node& node, const std::string& name, const char* default_name) {
  Property* p = find_property(node, name);
  double ior = 0.0;
  if (p && p->kind == PropertyKind::Integer)
    fail(p->loc, describe(node), ": ", name,
         " must be a <float> or an IOR name (Mitsuba refuses an <integer> here)");
  if (p && p->kind == PropertyKind::Float) {
    ior = take_float(node, name);
  } else {
    std::string value = take_string(node, name, default_name);
    if (!lookup_dielectric_ior(value, ior))
      fail(p ? p->loc : node.loc, describe(node), ": unknown ", name, " \"", value,
           "\"; known names: ", dielectric_ior_names());
  }
  if (!(ior > 0.0)) fail(p ? p->loc : node.loc, describe(node), ": ", name, " must be positive");
  return ior;
}

// `distribution` of the microfacet BSDFs: Mitsuba's default is beckmann.
void microfacet_flags(Node& node, Material& m) {
  std::string d = to_lower(take_string(node, "distribution", "beckmann"));
  if (d == "beckmann")
    m.flags |= MATERIAL_BECKMANN;
  else if (d != "ggx")
    fail(find_property(node, "distribution")->loc, describe(node), ": unknown distribution \"", d,
         "\" (expected beckmann or ggx)");
  if (take_bool(node, "sample_visible", true)) m.flags |= MATERIAL_SAMPLE_VISIBLE;
}

// roughplastic's `alpha`, a float (Mitsuba's MicrofacetDistribution(props), default 0.1):
// alpha_u and alpha_v are accepted together when equal; the BSDF itself is isotropic only.
double roughplastic_alpha(Node& n) {
  if (!has_property(n, "alpha_u") && !has_property(n, "alpha_v"))
    return take_float(n, "alpha", 0.1);
  if (has_property(n, "alpha"))
    fail(find_property(n, "alpha")->loc, describe(n), ": give either alpha or alpha_u/alpha_v");
  if (!has_property(n, "alpha_u") || !has_property(n, "alpha_v"))
    fail(n.loc, describe(n), ": alpha_u and alpha_v must be given together");
  double alpha_u = take_float(n, "alpha_u"), alpha_v = take_float(n, "alpha_v");
  if (float(alpha_u) != float(alpha_v))
    fail(find_property(n, "alpha_v")->loc, describe(n),
         ": anisotropic roughness (alpha_u != alpha_v) is not supported by roughplastic, as in "
         "Mitsuba");
  return alpha_u;
}

// Mitsuba's get_flag (src/bsdfs/principledhelpers.h): the spec_trans lobe is on when the
// parameter is given, unless it is a <float> equal to 0 (an <integer> 0 or a texture turns it on).
bool principled_has_spec_trans(Node& n) {
  Property* p = find_property(n, "spec_trans");
  return p && !(p->kind == PropertyKind::Float && float(p->number) == 0.0f);
}

// Whether a BSDF has a transmission or null lobe (Mitsuba's BSDFFlags::Transmission).
bool has_transmission(Node& bsdf) {
  const std::string& t = bsdf.type;
  if (t == "dielectric" || t == "roughdielectric" || t == "thindielectric" || t == "mask")
    return true;
  if (t == "principled") return principled_has_spec_trans(bsdf);
  if (t == "twosided" || t == "blendbsdf" || t == "normalmap" || t == "bumpmap" || t == "alphatest")
    for (Property& p : bsdf.props)
      if (p.kind == PropertyKind::Object && p.object->tag == "bsdf" && has_transmission(*p.object))
        return true;
  return false;
}

// Levels of blends in the tree rooted at a material (0 for any other BSDF).
uint blend_depth(const std::vector<Material>& materials, const Material& m) {
  if (m.type != BSDF_BLEND) return 0u;
  uint d0 = blend_depth(materials, materials[uint(m.param[BLEND_BSDF_0].value.x)]);
  uint d1 = blend_depth(materials, materials[uint(m.param[BLEND_BSDF_1].value.x)]);
  return 1u + std::max(d0, d1);
}

}  // namespace

void SceneBuilder::microfacet_roughness(Node& n, Material& m, uint slot_u, uint slot_v) {
  microfacet_flags(n, m);
  if (has_property(n, "alpha_u") || has_property(n, "alpha_v")) {
    if (has_property(n, "alpha"))
      fail(find_property(n, "alpha")->loc, describe(n), ": give either alpha or alpha_u/alpha_v");
    if (!has_property(n, "alpha_u") || !has_property(n, "alpha_v"))
      fail(n.loc, describe(n), ": alpha_u and alpha_v must be given together");
    m.param[slot_u] = textured(n, "alpha_u", glm::dvec3(0.1), true);
    m.param[slot_v] = textured(n, "alpha_v", glm::dvec3(0.1), true);
  } else {
    m.param[slot_u] = m.param[slot_v] = textured(n, "alpha", glm::dvec3(0.1), true);
  }
}

void store_rows(const glm::dmat4& m, vec4 rows[3]) {
  for (int r = 0; r < 3; ++r)
    rows[r] = vec4(float(m[0][r]), float(m[1][r]), float(m[2][r]), float(m[3][r]));
}

std::string SceneBuilder::resolve_file(Node& owner, const std::string& name, const char* what) {
  Property* p = find_property(owner, "filename");
  Location loc = p ? p->loc : owner.loc;
  std::filesystem::path dir = std::filesystem::path(loc.file).parent_path();
  std::filesystem::path file = parsed_.resolver.resolve(name, dir.empty() ? "." : dir);
  if (file.empty())
    fail(loc, what, " \"", name,
         "\" not found (searched the scene's <path> folders, -a paths and the scene folder)");
  return file.string();
}

std::pair<uint, glm::uvec2> SceneBuilder::load_texels(Node& owner, const std::string& file_name,
                                                      bool raw, bool scalar, TexelFormat format) {
  std::string path = resolve_file(owner, file_name, "image file");
  std::string key = path + (raw ? "|raw" : "|srgb") + (scalar ? "|scalar" : "|color") + "|" +
                    std::to_string(int(format));
  auto it = texel_cache_.find(key);
  if (it != texel_cache_.end()) return it->second;
  Image image;
  try {
    image = load_image(path, raw);
  } catch (const std::exception& e) {
    fail(find_property(owner, "filename")->loc, path, ": ", e.what());
  }
  // Mitsuba rounds the linear texels to half precision before any lookup (Bitmap::convert to
  // Float16, round to nearest even).
  bool half = format == TexelFormat::Float16 ||
              (format == TexelFormat::Auto && image.bytes_per_channel <= 2);
  auto stored = [half](float c) { return half ? float(Imath::half(c)) : c; };
  uint offset = uint(b_.texels.size());
  for (glm::vec4 t : image.texels) {
    t = glm::vec4(stored(t.x), stored(t.y), stored(t.z), t.w);
    if (scalar) {
      // Mitsuba's eval_1 of an RGB bitmap is the luminance of the interpolated color.
      float y = float(luminance_d(glm::dvec3(t)));
      b_.texels.push_back(vec4(y, y, y, t.w));
    } else {
      b_.texels.push_back(vec4(t));
    }
  }
  auto result = std::make_pair(offset, glm::uvec2(image.width, image.height));
  texel_cache_[key] = result;
  return result;
}

uint SceneBuilder::texture(Node& tex, bool scalar) {
  auto key = std::make_pair(static_cast<const Node*>(&tex), scalar);
  auto it = texture_cache_.find(key);
  if (it != texture_cache_.end()) return it->second;

  Texture t;
  t.filter_mode = FILTER_BILINEAR;
  t.wrap_mode = WRAP_REPEAT;
  t.texel_offset = 0u;
  t.width = t.height = 0u;
  t.attribute_slot = t.attribute_per_face = 0u;
  t.color0 = t.color1 = vec4(0.0f);
  if (tex.type == "mesh_attribute") return mesh_attribute_texture(tex, t, scalar);
  glm::dmat4 to_uv = take_transform(tex, "to_uv");
  // Rows of the 2D affine map: rows/columns 0, 1 and 3 of the 4x4 transform.
  t.to_uv[0] = vec4(float(to_uv[0][0]), float(to_uv[1][0]), float(to_uv[3][0]), 0.0f);
  t.to_uv[1] = vec4(float(to_uv[0][1]), float(to_uv[1][1]), float(to_uv[3][1]), 0.0f);

  if (tex.type == "bitmap") {
    t.type = TEXTURE_BITMAP;
    std::string filter = take_string(tex, "filter_type", "bilinear");
    if (filter == "nearest")
      t.filter_mode = FILTER_NEAREST;
    else if (filter != "bilinear")
      fail(find_property(tex, "filter_type")->loc, describe(tex), ": filter_type \"", filter,
           "\" must be nearest or bilinear");
    std::string wrap = take_string(tex, "wrap_mode", "repeat");
    if (wrap == "mirror")
      t.wrap_mode = WRAP_MIRROR;
    else if (wrap == "clamp")
      t.wrap_mode = WRAP_CLAMP;
    else if (wrap != "repeat")
      fail(find_property(tex, "wrap_mode")->loc, describe(tex), ": wrap_mode \"", wrap,
           "\" must be repeat, mirror or clamp");
    bool raw = take_bool(tex, "raw", false);
    take_bool(tex, "accel", true);  // a CUDA texture-unit hint in Mitsuba; no effect on values
    std::string format_name = take_string(tex, "format", "auto");
    TexelFormat format = TexelFormat::Auto;
    if (format_name == "variant")
      format = TexelFormat::Variant;
    else if (format_name == "fp16")
      format = TexelFormat::Float16;
    else if (format_name != "auto")
      fail(find_property(tex, "format")->loc, describe(tex), ": format \"", format_name,
           "\" must be auto, variant or fp16");
    std::string file = take_string(tex, "filename");
    auto [offset, size] = load_texels(tex, file, raw, scalar, format);
    // Mitsuba resamples a bitmap narrower than 2 pixels to 2 with a tent filter; only a 1x1
    // one comes out as the same (constant) texture without that resampling.
    if ((size.x < 2u || size.y < 2u) && size != glm::uvec2(1u))
      fail(find_property(tex, "filename")->loc, describe(tex), ": \"", file, "\" is ", size.x, "x",
           size.y,
           " pixels; Mitsuba resamples bitmaps smaller than 2x2 with a tent filter, which twinray "
           "does not do (use a 1x1 or at least 2x2 image)");
    t.texel_offset = offset;
    t.width = size.x;
    t.height = size.y;
  } else if (tex.type == "checkerboard") {
    t.type = TEXTURE_CHECKERBOARD;
    for (const char* name : {"color0", "color1"}) {
      Property* p = find_property(tex, name);
      if (p && p->kind == PropertyKind::Object)
        fail(p->loc, describe(tex), ": a nested texture as '", name,
             "' is not supported by twinray (its checkerboard holds two constant colors)");
    }
    glm::dvec3 c0 = take_color(tex, "color0", glm::dvec3(0.4));
    glm::dvec3 c1 = take_color(tex, "color1", glm::dvec3(0.2));
    if (scalar) {
      // Mitsuba's checkerboard eval_1 picks color0 where eval picks color1 and vice versa
      // (src/textures/checkerboard.cpp: `neq` in eval_1, `eq` in eval); scalar parameters are
      // read through eval_1, so they see the colors swapped. Reproduced here, with each
      // constant color reduced as its own eval_1 does.
      glm::dvec3 s0(scalar_of_constant(c1)), s1(scalar_of_constant(c0));
      c0 = s0;
      c1 = s1;
    }
    t.color0 = vec4(vec3(c0), 1.0f);
    t.color1 = vec4(vec3(c1), 1.0f);
  } else {
    fail(tex.loc, "unknown texture type \"", tex.type,
         "\" (supported: bitmap, checkerboard, mesh_attribute)");
  }
  check_consumed(tex);
  uint index = uint(b_.textures.size());
  b_.textures.push_back(t);
  texture_cache_[key] = index;
  return index;
}

// Mitsuba 3.8 `mesh_attribute` (src/textures/mesh_attribute.cpp): `name` (required; Mitsuba
// refuses a name containing neither "vertex_" nor "face_") and `scale` (1). Which meshes it is
// evaluated on, and whether they have the attribute, is known once the shapes are read
// (SceneBuilder::bind_mesh_attributes).
uint SceneBuilder::mesh_attribute_texture(Node& tex, Texture& t, bool scalar) {
  std::string name = take_string(tex, "name");
  if (name.find("vertex_") == std::string::npos && name.find("face_") == std::string::npos)
    fail(find_property(tex, "name")->loc, describe(tex), ": invalid attribute name \"", name,
         "\": it must start with \"vertex_\" or \"face_\" (as Mitsuba requires)");
  t.type = TEXTURE_MESH_ATTRIBUTE;
  t.color0 = vec4(float(take_float(tex, "scale", 1.0)), 0.0f, 0.0f, 0.0f);
  auto slot = std::find(attribute_names_.begin(), attribute_names_.end(), name);
  t.attribute_slot = uint(slot - attribute_names_.begin());
  if (slot == attribute_names_.end()) attribute_names_.push_back(name);
  t.attribute_per_face = name.rfind("face_", 0) == 0 ? 1u : 0u;
  check_consumed(tex);
  uint index = uint(b_.textures.size());
  b_.textures.push_back(t);
  texture_cache_[std::make_pair(static_cast<const Node*>(&tex), scalar)] = index;
  mesh_attribute_reads_[index] = {name, tex.loc, scalar ? 1 : 0};
  return index;
}

TexturedValue SceneBuilder::textured(Node& owner, const std::string& name, glm::dvec3 default_value,
                                     bool scalar) {
  Property* p = find_property(owner, name);
  if (p && p->kind == PropertyKind::Object) {
    p->used = true;
    if (p->object->tag != "texture")
      fail(p->loc, "parameter '", name, "' of ", describe(owner),
           " must be a texture or a value, not a <", p->object->tag, ">");
    TexturedValue v;
    v.value = vec3(0.0f);
    v.texture = texture(*p->object, scalar);
    return v;
  }
  glm::dvec3 c = take_color(owner, name, default_value);
  if (scalar) c = glm::dvec3(scalar_of_constant(c));
  return constant_value(c);
}

uint SceneBuilder::default_material(bool emitter) {
  // Mitsuba 3.8 (shape.cpp): a shape without a BSDF gets a diffuse BSDF of reflectance 0.5, or
  // of reflectance 0 when it carries an area emitter (a luminaire reflects nothing).
  uint& index = emitter ? default_luminaire_material_ : default_material_;
  if (index == NO_INDEX) {
    Material m = empty_material(BSDF_DIFFUSE);
    m.param[DIFFUSE_REFLECTANCE] = constant_value(glm::dvec3(emitter ? 0.0 : 0.5));
    index = uint(b_.materials.size());
    b_.materials.push_back(m);
  }
  return index;
}

uint SceneBuilder::material(Node& bsdf) {
  auto it = material_cache_.find(&bsdf);
  if (it != material_cache_.end()) return it->second;
  Material m = build_material(bsdf);
  uint index = uint(b_.materials.size());
  b_.materials.push_back(m);
  material_cache_[&bsdf] = index;
  return index;
}

// Mitsuba's precomputed roughplastic terms (core/bsdf/roughplastic_table.h): the external
// transmittance table as a one-row texture, the internal reflectance in value.x.
TexturedValue SceneBuilder::roughplastic_table(const Material& m) {
  const bool beckmann = (m.flags & MATERIAL_BECKMANN) != 0u;
  const float alpha = m.param[PLASTIC_ALPHA].value.x;
  const auto key = std::make_tuple(beckmann, alpha, m.eta);
  if (auto cached = roughplastic_tables_.find(key); cached != roughplastic_tables_.end())
    return cached->second;
  // 64 table entries and 64 terms of the internal reflectance, each a quadrature of its own.
  float transmittance[ROUGHPLASTIC_TABLE_RES];
  float internal[ROUGHPLASTIC_TABLE_RES];
  tbb::parallel_for(0u, 2u * ROUGHPLASTIC_TABLE_RES, [&](uint k) {
    if (k < ROUGHPLASTIC_TABLE_RES)
      transmittance[k] =
          roughplastic_external_transmittance(beckmann, alpha, m.eta, roughplastic_table_mu(k));
    else
      internal[k - ROUGHPLASTIC_TABLE_RES] =
          roughplastic_internal_term(beckmann, alpha, m.eta, k - ROUGHPLASTIC_TABLE_RES);
  });
  Texture t{};
  t.type = TEXTURE_BITMAP;
  t.filter_mode = FILTER_BILINEAR;
  t.wrap_mode = WRAP_CLAMP;
  t.texel_offset = uint(b_.texels.size());
  t.width = ROUGHPLASTIC_TABLE_RES;
  t.height = 1u;
  t.to_uv[0] = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  t.to_uv[1] = vec4(0.0f, 1.0f, 0.0f, 0.0f);
  for (float T : transmittance) b_.texels.push_back(vec4(T, T, T, 1.0f));
  TexturedValue v;
  v.value = vec3(roughplastic_internal_reflectance_of(internal));
  v.texture = uint(b_.textures.size());
  b_.textures.push_back(t);
  roughplastic_tables_.emplace(key, v);
  return v;
}

// Mean over the surface of a parameter (Mitsuba's Texture::mean): the constant's channel
// mean, a bitmap's mean texel luminance (BitmapTextureImpl::rebuild_internals), a
// checkerboard's mean of its two colours' means.
double SceneBuilder::textured_mean(const TexturedValue& v) const {
  if (v.texture == NO_INDEX) return (double(v.value.x) + v.value.y + v.value.z) / 3.0;
  const Texture& t = b_.textures[v.texture];
  if (t.type == TEXTURE_MESH_ATTRIBUTE)
    fail(mesh_attribute_reads_.at(v.texture).loc,
         "a mesh_attribute texture has no mean, which this BSDF needs (Mitsuba 3.8 raises "
         "NotImplementedError for Texture::mean there)");
  if (t.type == TEXTURE_CHECKERBOARD)
    return (double(t.color0.x) + t.color0.y + t.color0.z + t.color1.x + t.color1.y + t.color1.z) /
           6.0;
  double sum = 0.0;
  size_t count = size_t(t.width) * t.height;
  for (size_t i = 0; i < count; ++i) {
    const vec4& texel = b_.texels[t.texel_offset + i];
    sum += luminance_d(glm::dvec3(texel.x, texel.y, texel.z));
  }
  return count ? sum / double(count) : 0.0;
}

Material SceneBuilder::build_material(Node& n) {
  const std::string& type = n.type;
  Material m;
  if (type == "diffuse") {
    m = empty_material(BSDF_DIFFUSE);
    m.param[DIFFUSE_REFLECTANCE] = textured(n, "reflectance", glm::dvec3(0.5), false);
  } else if (type == "conductor" || type == "roughconductor") {
    m = empty_material(type == "conductor" ? BSDF_CONDUCTOR : BSDF_ROUGHCONDUCTOR);
    std::string material_name = take_string(n, "material", "none");
    for (const char* name : {"eta", "k"})
      if (has_property(n, name) && material_name != "none")
        fail(find_property(n, name)->loc, describe(n),
             ": give either a named 'material' or 'eta'/'k', not both");
    if (material_name == "none") {
      // Mitsuba's default: eta = 0, k = 1, a perfect mirror.
      m.param[CONDUCTOR_ETA] = textured(n, "eta", glm::dvec3(0.0), false);
      m.param[CONDUCTOR_K] = textured(n, "k", glm::dvec3(1.0), false);
    } else {
      const ConductorIor* c = lookup_conductor_ior(material_name);
      if (!c)
        fail(find_property(n, "material")->loc, describe(n), ": unknown conductor material \"",
             material_name, "\"; known: ", conductor_ior_names());
      m.param[CONDUCTOR_ETA] = constant_value(glm::dvec3(c->eta[0], c->eta[1], c->eta[2]));
      m.param[CONDUCTOR_K] = constant_value(glm::dvec3(c->k[0], c->k[1], c->k[2]));
    }
    m.param[CONDUCTOR_SPECULAR_REFLECTANCE] =
        textured(n, "specular_reflectance", glm::dvec3(1.0), false);
    if (type == "roughconductor") {
      microfacet_roughness(n, m, CONDUCTOR_ALPHA_U, CONDUCTOR_ALPHA_V);
    }
  } else if (type == "dielectric" || type == "roughdielectric" || type == "thindielectric") {
    m = empty_material(type == "dielectric"        ? BSDF_DIELECTRIC
                       : type == "roughdielectric" ? BSDF_ROUGHDIELECTRIC
                                                   : BSDF_THINDIELECTRIC);
    double int_ior = ior_parameter(n, "int_ior", "bk7");
    double ext_ior = ior_parameter(n, "ext_ior", "air");
    m.eta = float(int_ior / ext_ior);
    m.param[DIELECTRIC_SPECULAR_REFLECTANCE] =
        textured(n, "specular_reflectance", glm::dvec3(1.0), false);
    m.param[DIELECTRIC_SPECULAR_TRANSMITTANCE] =
        textured(n, "specular_transmittance", glm::dvec3(1.0), false);
    if (type == "roughdielectric") {
      if (int_ior == ext_ior) fail(n.loc, describe(n), ": int_ior and ext_ior must differ");
      microfacet_roughness(n, m, DIELECTRIC_ALPHA_U, DIELECTRIC_ALPHA_V);
    }
  } else if (type == "plastic" || type == "roughplastic") {
    m = empty_material(type == "plastic" ? BSDF_PLASTIC : BSDF_ROUGHPLASTIC);
    double int_ior = ior_parameter(n, "int_ior", "polypropylene");
    double ext_ior = ior_parameter(n, "ext_ior", "air");
    m.eta = float(int_ior / ext_ior);
    m.param[PLASTIC_DIFFUSE_REFLECTANCE] =
        textured(n, "diffuse_reflectance", glm::dvec3(0.5), false);
    m.param[PLASTIC_SPECULAR_REFLECTANCE] =
        textured(n, "specular_reflectance", glm::dvec3(1.0), false);
    if (take_bool(n, "nonlinear", false)) m.flags |= MATERIAL_NONLINEAR;
    // Mitsuba's specular sampling weight s_mean / (d_mean + s_mean), means over the textures.
    double d_mean = textured_mean(m.param[PLASTIC_DIFFUSE_REFLECTANCE]);
    double s_mean = textured_mean(m.param[PLASTIC_SPECULAR_REFLECTANCE]);
    m.extra = d_mean + s_mean > 0.0 ? float(s_mean / (d_mean + s_mean)) : 0.5f;
    if (type == "roughplastic") {
      if (int_ior == ext_ior) fail(n.loc, describe(n), ": int_ior and ext_ior must differ");
      microfacet_flags(n, m);
      m.param[PLASTIC_ALPHA] = constant_value(glm::dvec3(roughplastic_alpha(n)));
      m.param[ROUGHPLASTIC_TABLE] = roughplastic_table(m);
    }
  } else if (type == "pplastic") {
    m = build_pplastic(n);
  } else if (type == "principled") {
    m = build_principled(n);
  } else if (type == "alphatest") {
    // twinray extension (core/alpha_test.h): opacity (texture or float, required) and cutoff
    // (default 0.5, glTF 2.0's alphaCutoff) around exactly one nested BSDF.
    std::vector<Property*> inner = take_objects(n, "bsdf");
    if (inner.size() != 1)
      fail(inner.size() > 1 ? inner[1]->loc : n.loc, describe(n),
           " takes exactly one nested BSDF (it has ", inner.size(), ")");
    if (!has_property(n, "opacity")) fail(n.loc, describe(n), " needs an 'opacity'");
    TexturedValue opacity = textured(n, "opacity", glm::dvec3(1.0), true);
    double cutoff = take_float(n, "cutoff", 0.5);
    if (!(cutoff >= 0.0 && cutoff <= 1.0))
      fail(find_property(n, "cutoff")->loc, describe(n), ": cutoff must lie in [0, 1]");
    m = build_material(*inner[0]->object);
    if (m.flags & (MATERIAL_ALPHA_TESTED | MATERIAL_MASKED))
      fail(inner[0]->loc, describe(n), " around a ",
           (m.flags & MATERIAL_MASKED) ? "mask" : "nested alphatest",
           " is not supported (both use the opacity slot)");
    m.flags |= MATERIAL_ALPHA_TESTED;
    m.opacity = opacity;
    m.alpha_cutoff = float(cutoff);
  } else if (type == "twosided" || type == "mask") {
    std::vector<Property*> inner = take_objects(n, "bsdf");
    if (inner.empty()) fail(n.loc, describe(n), " needs a nested BSDF");
    for (Property* p : inner)
      if (p->object != inner[0]->object)
        fail(p->loc, describe(n), ": different front and back BSDFs are not supported");
    if (type == "mask" && inner.size() != 1)
      fail(inner[1]->loc, describe(n), " takes exactly one nested BSDF");
    if (inner.size() > 2) fail(inner[2]->loc, describe(n), " takes at most two nested BSDFs");
    TexturedValue opacity = constant_value(glm::dvec3(1.0));
    if (type == "mask") opacity = textured(n, "opacity", glm::dvec3(0.5), true);
    // Mitsuba 3.8 twosided.cpp refuses a nested BSDF with a transmission (or null) lobe
    // unless allow_transmission is set.
    if (type == "twosided" && !take_bool(n, "allow_transmission", false) &&
        has_transmission(*inner[0]->object))
      fail(n.loc, describe(n), ": the nested ", describe(*inner[0]->object),
           " transmits light; Mitsuba accepts it only with allow_transmission = true");
    m = build_material(*inner[0]->object);
    if (type == "mask" &&
        (m.type == BSDF_BLEND || m.type == BSDF_NORMALMAP || m.type == BSDF_BUMPMAP))
      fail(n.loc, describe(n), " around a ",
           m.type == BSDF_BLEND       ? "blendbsdf"
           : m.type == BSDF_NORMALMAP ? "normalmap"
                                      : "bumpmap",
           " is not supported");
    if (type == "twosided") {
      // A nested twosided is the identity here: wi is already on the front side.
      m.flags |= MATERIAL_TWOSIDED;
    } else {
      if (m.flags & MATERIAL_MASKED) fail(n.loc, describe(n), ": nested mask BSDFs");
      if (m.flags & MATERIAL_ALPHA_TESTED)
        fail(n.loc, describe(n),
             " around an alphatest is not supported (both use the opacity slot)");
      m.flags |= MATERIAL_MASKED;
      m.opacity = opacity;
    }
  } else if (type == "blendbsdf") {
    // Mitsuba 3.8 src/bsdfs/blendbsdf.cpp: exactly two nested BSDFs and a required `weight`.
    std::vector<Property*> inner = take_objects(n, "bsdf");
    if (inner.size() != 2)
      fail(inner.size() > 2 ? inner[2]->loc : n.loc, describe(n),
           " takes exactly two nested BSDFs (it has ", inner.size(), ")");
    if (!has_property(n, "weight")) fail(n.loc, describe(n), " needs a 'weight'");
    m = empty_material(BSDF_BLEND);
    m.param[BLEND_WEIGHT] = textured(n, "weight", glm::dvec3(0.5), true);
    m.param[BLEND_BSDF_0] = constant_value(glm::dvec3(material(*inner[0]->object)));
    m.param[BLEND_BSDF_1] = constant_value(glm::dvec3(material(*inner[1]->object)));
    m.lobes = blend_lobes(b_.materials[blend_child(m, 0u)], b_.materials[blend_child(m, 1u)]);
    for (uint slot : {BLEND_BSDF_0, BLEND_BSDF_1})
      if (b_.materials[uint(m.param[slot].value.x)].type == BSDF_NORMALMAP)
        fail(n.loc, describe(n), ": a normalmap inside a blendbsdf is not supported");
      else if (b_.materials[uint(m.param[slot].value.x)].type == BSDF_BUMPMAP)
        fail(n.loc, describe(n), ": a bumpmap inside a blendbsdf is not supported");
    if (blend_depth(b_.materials, m) > BLEND_MAX_DEPTH)
      fail(n.loc, describe(n), ": blendbsdfs nested more than ", BLEND_MAX_DEPTH,
           " deep are not supported");
  } else if (type == "normalmap") {
    // Mitsuba 3.8 src/bsdfs/normalmap.cpp: one nested BSDF, a required `normalmap` texture.
    std::vector<Property*> inner = take_objects(n, "bsdf");
    if (inner.size() != 1)
      fail(inner.size() > 1 ? inner[1]->loc : n.loc, describe(n),
           " takes exactly one nested BSDF (it has ", inner.size(), ")");
    if (!has_property(n, "normalmap")) fail(n.loc, describe(n), " needs a 'normalmap' texture");
    m = empty_material(BSDF_NORMALMAP);
    m.param[NORMALMAP_NORMALMAP] = textured(n, "normalmap", glm::dvec3(0.5, 0.5, 1.0), false);
    // Mitsuba's normalmap reads its texture with eval_3: a mesh attribute needs 3 channels.
    auto read = mesh_attribute_reads_.find(m.param[NORMALMAP_NORMALMAP].texture);
    if (read != mesh_attribute_reads_.end()) read->second.channels = 3;
    bool flip = take_bool(n, "flip_invalid_normals", true);
    bool shadowing = take_bool(n, "use_shadowing_function", true);
    m.param[NORMALMAP_OPTIONS] =
        constant_value(glm::dvec3(flip ? 1.0 : 0.0, shadowing ? 1.0 : 0.0, 0.0));
    uint child = material(*inner[0]->object);
    if (b_.materials[child].type == BSDF_NORMALMAP || b_.materials[child].type == BSDF_BUMPMAP)
      fail(inner[0]->loc, describe(n),
           ": a normalmap or bumpmap inside a normalmap is not supported");
    m.param[NORMALMAP_BSDF] = constant_value(glm::dvec3(child));
  } else if (type == "bumpmap") {
    m = build_bumpmap(n);
  } else {
    fail(n.loc, "unknown BSDF type \"", type,
         "\" (supported: diffuse, conductor, roughconductor, dielectric, roughdielectric, "
         "thindielectric, plastic, roughplastic, pplastic, principled, twosided, mask, alphatest, "
         "blendbsdf, normalmap, bumpmap)");
  }
  check_consumed(n);
  return m;
}

// Mitsuba 3.8 `bumpmap` (src/bsdfs/bumpmap.cpp): exactly one nested BSDF and one texture of
// any name (the height), `scale` (1), `flip_invalid_normals` and `use_shadowing_function`
// (true). Mitsuba reads the height through Texture::eval_1_grad, which 3.8 implements for
// bitmap (and uniform spectra, which twinray has no texture for); the other textures raise
// NotImplementedError when rendering, refused here when loading.
Material SceneBuilder::build_bumpmap(Node& n) {
  std::vector<Property*> inner = take_objects(n, "bsdf");
  if (inner.size() != 1)
    fail(inner.size() > 1 ? inner[1]->loc : n.loc, describe(n),
         " takes exactly one nested BSDF (it has ", inner.size(), ")");
  std::vector<Property*> textures = take_objects(n, "texture");
  if (textures.size() != 1)
    fail(textures.size() > 1 ? textures[1]->loc : n.loc, describe(n),
         " takes exactly one nested texture (it has ", textures.size(), ")");
  Node& height = *textures[0]->object;
  if (height.type != "bitmap")
    fail(height.loc, describe(n), ": its height ", describe(height),
         " has no uv gradient (Mitsuba 3.8 implements eval_1_grad only for bitmap)");
  Material m = empty_material(BSDF_BUMPMAP);
  m.param[BUMPMAP_HEIGHT].value = vec3(0.0f);
  m.param[BUMPMAP_HEIGHT].texture = texture(height, true);
  bool flip = take_bool(n, "flip_invalid_normals", true);
  bool shadowing = take_bool(n, "use_shadowing_function", true);
  double scale = take_float(n, "scale", 1.0);
  m.param[BUMPMAP_OPTIONS] =
      constant_value(glm::dvec3(flip ? 1.0 : 0.0, shadowing ? 1.0 : 0.0, scale));
  uint child = material(*inner[0]->object);
  if (b_.materials[child].type == BSDF_NORMALMAP || b_.materials[child].type == BSDF_BUMPMAP)
    fail(inner[0]->loc, describe(n), ": a normalmap or bumpmap inside a bumpmap is not supported");
  m.param[BUMPMAP_BSDF] = constant_value(glm::dvec3(child));
  return m;
}

// Mitsuba 3 `pplastic` (src/bsdfs/pplastic.cpp), parameter by parameter:
//   diffuse_reflectance  texture, 0.5      specular_reflectance  texture, 1
//   int_ior / ext_ior    polypropylene / air (numbers or names), positive and different
//   eta                  texture (unbounded), instead of int_ior/ext_ior, never with them
//   distribution         beckmann | ggx, beckmann   sample_visible  true
//   alpha, or alpha_u with alpha_v   textures (unbounded), 0.1
// Material.extra is the specular sampling weight s_mean / (d_mean + s_mean); Mitsuba divides
// 0 by 0 when both reflectances are black (a black BSDF either way): 0.5 here.
Material SceneBuilder::build_pplastic(Node& n) {
  Material m = empty_material(BSDF_PPLASTIC);
  m.param[PLASTIC_DIFFUSE_REFLECTANCE] = textured(n, "diffuse_reflectance", glm::dvec3(0.5), false);
  m.param[PLASTIC_SPECULAR_REFLECTANCE] =
      textured(n, "specular_reflectance", glm::dvec3(1.0), false);
  if (has_property(n, "eta")) {
    for (const char* name : {"int_ior", "ext_ior"})
      if (has_property(n, name))
        fail(find_property(n, name)->loc, describe(n),
             ": give either eta or int_ior/ext_ior, not both");
    m.param[PPLASTIC_ETA] = textured(n, "eta", glm::dvec3(0.0), true);
  } else {
    double int_ior = ior_parameter(n, "int_ior", "polypropylene");
    double ext_ior = ior_parameter(n, "ext_ior", "air");
    if (int_ior == ext_ior) fail(n.loc, describe(n), ": int_ior and ext_ior must differ");
    m.param[PPLASTIC_ETA] = constant_value(glm::dvec3(int_ior / ext_ior));
  }
  microfacet_roughness(n, m, PPLASTIC_ALPHA_U, PPLASTIC_ALPHA_V);
  double d_mean = textured_mean(m.param[PLASTIC_DIFFUSE_REFLECTANCE]);
  double s_mean = textured_mean(m.param[PLASTIC_SPECULAR_REFLECTANCE]);
  m.extra = d_mean + s_mean > 0.0 ? float(s_mean / (d_mean + s_mean)) : 0.5f;
  return m;
}

Material SceneBuilder::build_principled(Node& n) {
  // Mitsuba src/bsdfs/principled.cpp: defaults and the eta <-> specular correspondence
  // eta = 2 / (1 - sqrt(0.08 specular)) - 1.
  Material m = empty_material(BSDF_PRINCIPLED);
  m.param[PRINCIPLED_BASE_COLOR] = textured(n, "base_color", glm::dvec3(0.5), false);
  m.param[PRINCIPLED_ROUGHNESS] = textured(n, "roughness", glm::dvec3(0.5), true);
  m.param[PRINCIPLED_METALLIC] = textured(n, "metallic", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_SPEC_TINT] = textured(n, "spec_tint", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_ANISOTROPIC] = textured(n, "anisotropic", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_SHEEN] = textured(n, "sheen", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_SHEEN_TINT] = textured(n, "sheen_tint", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_CLEARCOAT] = textured(n, "clearcoat", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_CLEARCOAT_GLOSS] = textured(n, "clearcoat_gloss", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_SPEC_TRANS] = textured(n, "spec_trans", glm::dvec3(0.0), true);
  m.param[PRINCIPLED_FLATNESS] = textured(n, "flatness", glm::dvec3(0.0), true);
  double srate_diffuse = take_float(n, "diffuse_reflectance_sampling_rate", 1.0);
  double srate_specular = take_float(n, "main_specular_sampling_rate", 1.0);
  double srate_clearcoat = take_float(n, "clearcoat_sampling_rate", 1.0);
  m.param[PRINCIPLED_SAMPLING_RATES] =
      constant_value(glm::dvec3(srate_diffuse, srate_specular, srate_clearcoat));

  bool has_spec_trans = principled_has_spec_trans(n);
  double eta;
  if (has_property(n, "eta") && has_property(n, "specular"))
    fail(find_property(n, "eta")->loc, describe(n), ": give either 'eta' or 'specular', not both");
  if (has_property(n, "eta")) {
    eta = take_float(n, "eta");
    if (has_spec_trans && eta == 1.0) eta = 1.001;  // eta = 1 is not plausible for transmission
    if (!(eta > 0.0)) fail(find_property(n, "eta")->loc, describe(n), ": eta must be positive");
  } else {
    double specular = take_float(n, "specular", 0.5);
    if (has_spec_trans && specular == 0.0) specular = 1e-3;
    if (!(specular >= 0.0 && specular < 12.5))
      fail(find_property(n, "specular")->loc, describe(n), ": specular must be in [0, 12.5)");
    eta = 2.0 / (1.0 - std::sqrt(0.08 * specular)) - 1.0;
  }
  m.eta = float(eta);
  return m;
}

// MATERIAL_TEXTURED: the roughplastic table slot holds a precomputed table, not a parameter.
void SceneBuilder::mark_textured_materials() {
  for (Material& m : b_.materials) {
    bool textured = m.opacity.texture != NO_INDEX;
    for (uint k = 0; k < MATERIAL_PARAM_COUNT; ++k)
      textured |= m.param[k].texture != NO_INDEX &&
                  !(m.type == BSDF_ROUGHPLASTIC && k == ROUGHPLASTIC_TABLE);
    if (textured) m.flags |= MATERIAL_TEXTURED;
  }
}

}  // namespace tr
