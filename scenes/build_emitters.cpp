// Emitter plugins -> Emitter records, the envmap's texel alias table and the emitter-selection
// table. Parameters, defaults and refusals as Mitsuba 3.8's src/emitters/*.cpp and
// src/render/endpoint.cpp (tests/scenes/plugin_defaults_test.cpp pins them).
#include <algorithm>
#include <cmath>

#include "scenes/alias_table.h"
#include "scenes/scene_builder.h"

namespace tr {

namespace {

const double PI_D = 3.14159265358979323846;

double lum(glm::dvec3 c) { return 0.212671 * c.x + 0.715160 * c.y + 0.072169 * c.z; }

glm::dvec3 emitter_color(Node& e, const std::string& name) {
  Property* p = find_property(e, name);
  if (p && p->kind == PropertyKind::Object)
    fail(p->loc, describe(e), ": a textured '", name, "' is not supported");
  glm::dvec3 c = take_color(e, name, glm::dvec3(1.0));
  if (glm::any(glm::lessThan(c, glm::dvec3(0.0))))
    fail(p->loc, describe(e), ": a negative '", name,
         "' is not supported by twinray (Mitsuba accepts negative emission)");
  return c;
}

Emitter blank_emitter(uint type) {
  Emitter e{};
  e.type = type;
  e.shape = NO_INDEX;
  e.texture = NO_INDEX;
  e.alias_offset = NO_INDEX;
  e.alias_count = 0u;
  e.scale = 1.0f;
  store_rows(glm::dmat4(1.0), e.to_world);
  store_rows(glm::dmat4(1.0), e.to_local);
  return e;
}

}  // namespace

void SceneBuilder::add_emitter(Node& n) {
  if (n.type == "constant" || n.type == "envmap") {
    for (const PendingEmitter& other : emitters_)
      if (other.record.type == EMITTER_CONSTANT || other.record.type == EMITTER_ENVMAP)
        fail(n.loc,
             "only one environment emitter (constant or envmap) is allowed; another one is at ",
             to_string(other.loc));
  }
  PendingEmitter pe;
  pe.loc = n.loc;
  Emitter& e = pe.record;
  if (n.type == "point") {
    e = blank_emitter(EMITTER_POINT);
    if (has_property(n, "position") && has_property(n, "to_world"))
      fail(n.loc, describe(n), ": give either 'position' or 'to_world', not both");
    glm::dmat4 to_world = take_transform(n, "to_world");
    // Mitsuba stores <point> and <vector> as one type, so either gives the position.
    glm::dvec3 position = take_vector(n, "position", glm::dvec3(to_world[3]));
    e.position = vec3(position);
    e.radiance = vec3(emitter_color(n, "intensity"));
  } else if (n.type == "spot") {
    e = build_spot(n);
  } else if (n.type == "projector") {
    e = build_projector(n);
  } else if (n.type == "directional") {
    e = blank_emitter(EMITTER_DIRECTIONAL);
    if (has_property(n, "direction") && has_property(n, "to_world"))
      fail(n.loc, describe(n), ": give either 'direction' or 'to_world', not both");
    glm::dmat4 to_world = take_transform(n, "to_world");
    glm::dvec3 d = take_vector(n, "direction", glm::dvec3(to_world * glm::dvec4(0, 0, 1, 0)));
    if (!(glm::length(d) > 0.0)) fail(n.loc, describe(n), ": the direction is zero");
    e.direction = vec3(glm::normalize(d));
    e.radiance = vec3(emitter_color(n, "irradiance"));
  } else if (n.type == "constant") {
    e = blank_emitter(EMITTER_CONSTANT);
    e.radiance = vec3(emitter_color(n, "radiance"));
    // Every emitter reads `to_world` (Endpoint); a constant environment is the same under any.
    take_transform(n, "to_world");
  } else if (n.type == "envmap") {
    e = blank_emitter(EMITTER_ENVMAP);
    std::string file = take_string(n, "filename");
    double scale = take_float(n, "scale", 1.0);
    if (!(scale >= 0.0)) fail(find_property(n, "scale")->loc, describe(n), ": scale must be >= 0");
    e.scale = float(scale);
    if (take_bool(n, "mis_compensation", false))
      fail(find_property(n, "mis_compensation")->loc, describe(n),
           ": mis_compensation is not supported");
    glm::dmat4 to_world = take_transform(n, "to_world");
    if (glm::determinant(glm::dmat3(to_world)) == 0.0)
      fail(find_property(n, "to_world")->loc, describe(n), ": to_world is singular");
    store_rows(to_world, e.to_world);
    store_rows(glm::inverse(to_world), e.to_local);
    // Mitsuba converts the map to the variant's float type (no half-precision storage).
    // (Not a structured binding: the lambda below uses offset, which C++17 cannot capture.)
    const std::pair<uint, glm::uvec2> texels =
        load_texels(n, file, false, false, TexelFormat::Variant);
    const uint offset = texels.first;
    const glm::uvec2 size = texels.second;
    if (size.x < 2u || size.y < 3u)
      fail(find_property(n, "filename")->loc, describe(n), ": \"", file, "\" is ", size.x, "x",
           size.y, " pixels; an environment map must be at least 2x3 (as in Mitsuba)");
    Texture t{};
    t.type = TEXTURE_BITMAP;
    t.filter_mode = FILTER_BILINEAR;
    t.wrap_mode = WRAP_REPEAT;
    t.texel_offset = offset;
    t.width = size.x;
    t.height = size.y;
    t.to_uv[0] = vec4(1, 0, 0, 0);
    t.to_uv[1] = vec4(0, 1, 0, 0);
    e.texture = uint(b_.textures.size());
    b_.textures.push_back(t);

    // Texel weights: sin(theta_j) (lum(i, j) + max lum over the 3x3 neighbourhood) / 2, u
    // wrapping, v clamped, theta_j = pi (j + 0.5) / H (the equirectangular Jacobian times a
    // radiance estimate that also covers bilinear spill from brighter neighbours).
    const int w = int(size.x), h = int(size.y);
    auto texel_lum = [&](int i, int j) {
      i = ((i % w) + w) % w;
      j = std::clamp(j, 0, h - 1);
      return lum(glm::dvec3(glm::vec3(b_.texels[offset + size_t(j) * w + i])));
    };
    std::vector<double> weights(size_t(w) * h);
    for (int j = 0; j < h; ++j) {
      double sin_theta = std::sin(PI_D * (j + 0.5) / h);
      for (int i = 0; i < w; ++i) {
        double l = texel_lum(i, j), neighbourhood = 0.0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            neighbourhood = std::max(neighbourhood, texel_lum(i + di, j + dj));
        weights[size_t(j) * w + i] = sin_theta * (l + neighbourhood) / 2.0;
        if (l < 0.0)
          fail(find_property(n, "filename")->loc, describe(n), ": negative radiance in the map");
      }
    }
    e.radiance = vec3(1.0f);  // the map itself holds the radiance (times `scale`)
    std::vector<AliasEntry> table;
    try {
      table = build_alias_table(weights);
    } catch (const std::exception&) {
      fail(find_property(n, "filename")->loc, describe(n), ": the environment map is black");
    }
    e.alias_offset = uint(b_.alias.size());
    e.alias_count = uint(table.size());
    b_.alias.insert(b_.alias.end(), table.begin(), table.end());
  } else if (n.type == "area") {
    fail(n.loc, "an \"area\" emitter must be nested inside a <shape>");
  } else {
    fail(n.loc, "unknown emitter type \"", n.type,
         "\" (supported: area, point, spot, projector, directional, constant, envmap)");
  }
  pe.sampling_weight = take_sampling_weight(n);
  check_consumed(n);
  emitters_.push_back(pe);
}

// A mesh_attribute texture is evaluated on the shape hit; an emitter's texture has none.
void SceneBuilder::refuse_mesh_attribute(Node& emitter, const char* name,
                                         const TexturedValue& v) const {
  if (v.texture != NO_INDEX && b_.textures[v.texture].type == TEXTURE_MESH_ATTRIBUTE)
    fail(find_property(emitter, name)->loc, describe(emitter), ": '", name,
         "' cannot be a mesh_attribute texture (it is not evaluated on a mesh)");
}

// Mitsuba 3.8 `area` with a textured radiance (src/emitters/area.cpp): read at the uv of each
// point of the shape (core/emitters/area.h). A mesh_attribute texture is refused as Mitsuba
// refuses it when sampling the light (Texture::sample_position is not implemented for it), and
// so is negative emission, as for a constant radiance.
uint SceneBuilder::emitted_texture(Node& emitter, const char* name) {
  const TexturedValue v = textured(emitter, name, glm::dvec3(1.0), false);
  const Location& loc = find_property(emitter, name)->loc;
  const Texture& t = b_.textures[v.texture];
  if (t.type == TEXTURE_MESH_ATTRIBUTE)
    fail(loc, describe(emitter), ": '", name,
         "' cannot be a mesh_attribute texture (Mitsuba 3.8 cannot sample an area light by it)");
  auto negative = [](const vec4& c) { return !(c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f); };
  bool refused = false;
  if (t.type == TEXTURE_CHECKERBOARD) {
    refused = negative(t.color0) || negative(t.color1);
  } else {
    for (size_t i = 0; i < size_t(t.width) * t.height && !refused; ++i)
      refused = negative(b_.texels[t.texel_offset + i]);
  }
  if (refused)
    fail(loc, describe(emitter), ": a negative or NaN value in the '", name,
         "' texture is not supported by twinray (Mitsuba accepts negative emission)");
  return v.texture;
}

// Mitsuba 3.8 `spot` (src/emitters/spot.cpp), parameter by parameter:
//   intensity     emitted intensity (W/sr), a colour or spectrum, not a texture; 1
//   texture       optional spatially varying texture over the cone (a bitmap or checkerboard)
//   cutoff_angle  degrees, 20;  beam_width  degrees, 3/4 of cutoff_angle
//   to_world      the light at its origin, shining along its +z
// Mitsuba checks neither angle (its assertion beam_width <= cutoff_angle is compiled out of
// release builds): every pair renders as Mitsuba renders it (core/emitters/spot.h).
Emitter SceneBuilder::build_spot(Node& n) {
  Emitter e = blank_emitter(EMITTER_SPOT);
  e.radiance = vec3(emitter_color(n, "intensity"));
  if (has_property(n, "texture")) {
    TexturedValue t = textured(n, "texture", glm::dvec3(1.0), false);
    refuse_mesh_attribute(n, "texture", t);
    if (t.texture == NO_INDEX)
      fail(find_property(n, "texture")->loc, describe(n),
           ": 'texture' must be spatially varying (a bitmap or checkerboard), as in Mitsuba");
    e.texture = t.texture;
  }
  double cutoff_deg = take_float(n, "cutoff_angle", 20.0);
  double beam_deg = take_float(n, "beam_width", cutoff_deg * 3.0 / 4.0);
  double cutoff = glm::radians(cutoff_deg), beam = glm::radians(beam_deg);
  e.cone = vec4(float(std::cos(cutoff)), float(std::cos(beam)), float(cutoff),
                float(1.0 / (cutoff - beam)));
  e.tan_cutoff = float(std::tan(cutoff));
  glm::dmat4 to_world = take_transform(n, "to_world");
  if (glm::determinant(glm::dmat3(to_world)) == 0.0)
    fail(find_property(n, "to_world")->loc, describe(n), ": to_world is singular");
  e.position = vec3(glm::dvec3(to_world[3]));
  store_rows(glm::inverse(to_world), e.to_local);
  return e;
}

// Mitsuba 3.8 `projector` (src/emitters/projector.cpp), parameter by parameter:
//   irradiance    a colour or texture (its resolution sets the aspect; 1 for a non-bitmap); 1
//   scale         irradiance multiplier, 1
//   fov, fov_axis or focal_length   as the perspective sensor's, over the texture's aspect
//   to_world      the projector at its origin, looking along its +z
Emitter SceneBuilder::build_projector(Node& n) {
  Emitter e = blank_emitter(EMITTER_PROJECTOR);
  Property* p = find_property(n, "irradiance");
  TexturedValue irradiance = textured(n, "irradiance", glm::dvec3(1.0), false);
  refuse_mesh_attribute(n, "irradiance", irradiance);
  if (irradiance.texture == NO_INDEX && glm::any(glm::lessThan(irradiance.value, vec3(0.0f))))
    fail(p->loc, describe(n),
         ": a negative 'irradiance' is not supported by twinray (Mitsuba accepts negative "
         "emission)");
  e.radiance = irradiance.value;
  e.texture = irradiance.texture;
  double aspect = 1.0;
  if (e.texture != NO_INDEX && b_.textures[e.texture].type == TEXTURE_BITMAP)
    aspect = double(b_.textures[e.texture].width) / b_.textures[e.texture].height;
  double scale = take_float(n, "scale", 1.0);
  if (!(scale >= 0.0))
    fail(find_property(n, "scale")->loc, describe(n),
         ": a negative 'scale' is not supported by twinray (Mitsuba accepts negative emission)");
  e.scale = float(scale);
  double half_cot = 0.5 / std::tan(0.5 * glm::radians(horizontal_fov(n, aspect)));
  e.cone = vec4(float(half_cot), float(aspect * half_cot), 0.0f, 0.0f);
  glm::dmat4 to_world = take_transform(n, "to_world");
  if (glm::determinant(glm::dmat3(to_world)) == 0.0)
    fail(find_property(n, "to_world")->loc, describe(n), ": to_world is singular");
  e.position = vec3(glm::dvec3(to_world[3]));
  e.direction = vec3(glm::dvec3(to_world * glm::dvec4(0.0, 0.0, 1.0, 0.0)));
  store_rows(glm::inverse(to_world), e.to_local);
  return e;
}

double SceneBuilder::take_sampling_weight(Node& emitter) {
  double w = take_float(emitter, "sampling_weight", 1.0);
  if (!(w >= 0.0 && std::isfinite(w)))
    fail(find_property(emitter, "sampling_weight")->loc, describe(emitter),
         ": sampling_weight must be finite and >= 0");
  return w;
}

// Emitters are chosen with probability proportional to their `sampling_weight`, uniformly by
// default, as Mitsuba 3's Scene::sample_emitter (src/render/scene.cpp). The choice shapes each
// pixel's variance, which the Mitsuba test references' variance images assume: a power-based
// choice is unbiased too but fails those tests where it trades variance between lights.
void SceneBuilder::finalize_emitters() {
  // Area emitters were appended by finalize_shapes; the others follow in document order.
  for (const PendingEmitter& pe : emitters_) {
    if (pe.record.type == EMITTER_CONSTANT || pe.record.type == EMITTER_ENVMAP)
      b_.globals.environment = uint(b_.emitters.size());
    b_.emitters.push_back(pe.record);
    emitter_weights_.push_back({pe.sampling_weight, pe.loc});
  }
  b_.globals.emitter_count = uint(b_.emitters.size());
  b_.globals.emitter_alias_offset = uint(b_.alias.size());
  if (b_.emitters.empty()) return;
  std::vector<double> weights;
  for (const auto& [w, loc] : emitter_weights_) weights.push_back(w);
  std::vector<AliasEntry> table;
  try {
    table = build_alias_table(weights);
  } catch (const std::exception&) {
    fail(emitter_weights_[0].second, "every emitter of the scene has sampling_weight 0");
  }
  b_.alias.insert(b_.alias.end(), table.begin(), table.end());
}

}  // namespace tr
