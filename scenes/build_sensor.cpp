// Sensor (perspective, thinlens, orthographic), film (hdrfilm), reconstruction filter (box,
// gaussian, tent, mitchell, catmullrom, lanczos), sampler (independent, stratified, ldsampler,
// multijitter, orthogonal, zsobol, sobol; scenes/sampler.h) and integrator (path, direct, moment,
// aov; pbrt-v4's ambientocclusion)
// -> Camera, Integrator, the sampler and the Scene's spp/seed. Defaults as Mitsuba 3 (src/sensors,
// src/render/sensor.cpp, src/render/film.cpp, src/films, src/rfilters, src/samplers,
// src/integrators).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/rfilter.h"
#include "scenes/sampler.h"
#include "scenes/scene_builder.h"
#include "scenes/values.h"

namespace tr {

namespace {

const double PI_D = 3.14159265358979323846;

Node empty_node(const std::string& tag, const std::string& type, const Location& loc) {
  Node n;
  n.tag = tag;
  n.type = type;
  n.loc = loc;
  return n;
}

// The film's reconstruction filter into Camera.rfilter, filter_radius and Mitsuba's table
// (src/rfilters/*.cpp for the parameters and radii; core/rfilter.h for the table).
void reconstruction_filter(Node& rf, Camera& cam) {
  auto positive = [&](const char* name, double default_value) {
    double v = take_float(rf, name, default_value);
    if (!(v > 0.0) || !std::isfinite(v))
      fail(find_property(rf, name)->loc, describe(rf), ": ", name, " must be positive");
    return v;
  };
  vec4 params(0.0f);
  double radius;
  if (rf.type == "box") {
    cam.rfilter = RFILTER_BOX;
    radius = 0.5;
  } else if (rf.type == "gaussian") {
    cam.rfilter = RFILTER_GAUSSIAN;
    params.x = float(positive("stddev", 0.5));
    radius = 4.0 * double(params.x);  // gaussian.cpp: cut off at 4 standard deviations
  } else if (rf.type == "tent") {
    cam.rfilter = RFILTER_TENT;
    params.x = float(positive("radius", 1.0));
    radius = params.x;
  } else if (rf.type == "mitchell") {
    cam.rfilter = RFILTER_MITCHELL;
    params.x = float(take_float(rf, "B", 1.0 / 3.0));
    params.y = float(take_float(rf, "C", 1.0 / 3.0));
    if (!std::isfinite(params.x) || !std::isfinite(params.y))
      fail(rf.loc, describe(rf), ": B and C must be finite");
    radius = 2.0;
  } else if (rf.type == "catmullrom") {
    cam.rfilter = RFILTER_CATMULLROM;
    radius = 2.0;
  } else if (rf.type == "lanczos") {
    cam.rfilter = RFILTER_LANCZOS;
    long long lobes = take_integer(rf, "lobes", 3);
    if (lobes < 1 || lobes > 64)
      fail(find_property(rf, "lobes")->loc, describe(rf), ": lobes must be in [1, 64]");
    params.x = float(lobes);
    radius = double(lobes);
  } else {
    fail(rf.loc, "unknown rfilter type \"", rf.type,
         "\" (supported: box, gaussian, tent, mitchell, catmullrom, lanczos)");
  }
  check_consumed(rf);
  cam.filter_radius = float(radius);
  // src/core/rfilter.cpp is_box_filter: Mitsuba recognizes the box by its radius alone, so any
  // filter of radius 0.5 renders as the box (src/render/imageblock.cpp drops it).
  if (cam.filter_radius == 0.5f) cam.rfilter = RFILTER_BOX;
  if (cam.rfilter == RFILTER_BOX) return;
  cam.filter_scale = float(FILTER_RESOLUTION) / cam.filter_radius;
  double integral = 0.0;
  for (uint i = 0; i <= FILTER_RESOLUTION; ++i) {
    float v = rfilter_table_entry(cam.rfilter, params, cam.filter_radius, i);
    cam.filter_table[i / 4][i % 4] = v;
    integral += 2.0 * double(v) * (double(cam.filter_radius) / FILTER_RESOLUTION);
  }
  for (uint k = 0; k <= 2 * FILTER_RESOLUTION; ++k)
    cam.filter_cdf[k / 4][k % 4] = filter_cdf_entry(cam.filter_table, cam.filter_radius, k);
  if (!(integral > 0.0)) fail(rf.loc, describe(rf), ": the filter must have a positive integral");
}

// Mitsuba's ProjectiveCamera (src/render/sensor.cpp) refuses scale in the camera-to-world
// transform of perspective and thinlens (Transform::has_scale: the columns of the linear part
// orthonormal within 1e-3).
bool has_scale(const glm::dmat4& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      double dot = 0.0;
      for (int k = 0; k < 3; ++k) dot += m[i][k] * m[j][k];
      if (std::abs(dot - (i == j ? 1.0 : 0.0)) > 1e-3) return true;
    }
  return false;
}

Location location_of(Node& n, const std::string& name) {
  return has_property(n, name) ? find_property(n, name)->loc : n.loc;
}

}  // namespace

double horizontal_fov(Node& s, double aspect) {
  if (has_property(s, "fov") && has_property(s, "focal_length"))
    fail(find_property(s, "fov")->loc, describe(s), ": give either 'fov' or 'focal_length'");
  double fov;
  std::string axis;
  if (has_property(s, "fov")) {
    fov = take_float(s, "fov");
    axis = to_lower(take_string(s, "fov_axis", "x"));
    if (axis == "smaller") axis = aspect > 1 ? "y" : "x";
    if (axis == "larger") axis = aspect > 1 ? "x" : "y";
  } else {
    // Default: a 50 mm lens on a 36 x 24 mm film, along the diagonal.
    std::string f = take_string(s, "focal_length", "50mm");
    Location loc = has_property(s, "focal_length") ? find_property(s, "focal_length")->loc : s.loc;
    if (f.size() > 2 && f.compare(f.size() - 2, 2, "mm") == 0) f = f.substr(0, f.size() - 2);
    double value = parse_double(f, loc, "focal_length");
    if (!(value > 0.0)) fail(loc, "focal_length must be positive");
    fov = 2.0 * std::atan(std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / (2.0 * value)) * 180.0 / PI_D;
    axis = "diagonal";
  }
  auto rad = [](double deg) { return deg * PI_D / 180.0; };
  double result;
  if (axis == "x") {
    result = fov;
  } else if (axis == "y") {
    result = 2.0 * std::atan(std::tan(0.5 * rad(fov)) * aspect) * 180.0 / PI_D;
  } else if (axis == "diagonal") {
    double diagonal = 2.0 * std::tan(0.5 * rad(fov));
    double width = diagonal / std::sqrt(1.0 + 1.0 / (aspect * aspect));
    result = 2.0 * std::atan(width * 0.5) * 180.0 / PI_D;
  } else {
    fail(find_property(s, "fov_axis")->loc, describe(s), ": fov_axis \"", axis,
         "\" must be x, y, diagonal, smaller or larger");
  }
  if (!(result > 0.0 && result < 180.0))
    fail(s.loc, describe(s), ": the field of view must be in (0, 180) degrees");
  return result;
}

void SceneBuilder::add_sensor(Node& s) {
  if (s.type != "perspective" && s.type != "thinlens" && s.type != "orthographic")
    fail(s.loc, "unknown sensor type \"", s.type,
         "\" (supported: perspective, thinlens, orthographic)");
  Camera& cam = b_.globals.camera;
  cam.type = s.type == "perspective" ? SENSOR_PERSPECTIVE
             : s.type == "thinlens"  ? SENSOR_THINLENS
                                     : SENSOR_ORTHOGRAPHIC;

  // ---- film (src/render/film.cpp, src/films/hdrfilm.cpp) and its reconstruction filter
  std::vector<Property*> films = take_objects(s, "film");
  if (films.size() > 1) fail(films[1]->loc, describe(s), " has more than one film");
  Node default_film = empty_node("film", "hdrfilm", s.loc);
  Node& film = films.empty() ? default_film : *films[0]->object;
  if (film.type != "hdrfilm")
    fail(film.loc, "unknown film type \"", film.type, "\" (supported: hdrfilm)");
  long long width = take_integer(film, "width", 768), height = take_integer(film, "height", 576);
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
    fail(film.loc, describe(film), ": width and height must be in [1, 65536]");
  long long crop_x = take_integer(film, "crop_offset_x", 0),
            crop_y = take_integer(film, "crop_offset_y", 0);
  long long crop_w = take_integer(film, "crop_width", width),
            crop_h = take_integer(film, "crop_height", height);
  if (crop_x < 0 || crop_y < 0 || crop_w <= 0 || crop_h <= 0 || crop_x + crop_w > width ||
      crop_y + crop_h > height)
    fail(film.loc, describe(film), ": the crop window (offset ", crop_x, ", ", crop_y, ", size ",
         crop_w, " x ", crop_h, ") must be non-empty and inside the ", width, " x ", height,
         " film");
  // A render keeps about 200 bytes per rendered pixel (its moments and the developed image, in
  // double; render/film_state.h); refuse films this machine cannot hold rather than fail late.
  const double film_bytes = 200.0 * double(crop_w) * double(crop_h);
  const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (memory > 0.0 && film_bytes > memory)
    fail(film.loc, describe(film), ": ", crop_w, " x ", crop_h, " pixels need about ",
         std::ceil(film_bytes / 1073741824.0), " GiB of memory, more than this machine's ",
         std::floor(memory / 1073741824.0), " GiB");
  std::string file_format = to_lower(take_string(film, "file_format", "openexr"));
  if (file_format != "openexr" && file_format != "exr")
    fail(find_property(film, "file_format")->loc, describe(film), ": file_format \"", file_format,
         "\" is not supported (twinray writes OpenEXR only)");
  std::string pixel_format = to_lower(take_string(film, "pixel_format", "rgb"));
  if (pixel_format != "rgb")
    fail(find_property(film, "pixel_format")->loc, describe(film), ": pixel_format \"",
         pixel_format, "\" is not supported (rgb; twinray computes no alpha)");
  std::string component_format = to_lower(take_string(film, "component_format", "float16"));
  if (component_format != "float16" && component_format != "float32")
    fail(find_property(film, "component_format")->loc, describe(film), ": component_format \"",
         component_format, "\" is not supported (float16, float32)");
  scene_.film_half = component_format == "float16";
  bool sample_border = take_bool(film, "sample_border", false);
  if (take_bool(film, "compensate", false))
    fail(find_property(film, "compensate")->loc, describe(film), ": compensate is not supported");
  take_bool(film, "banner", false);  // accepted and ignored by Mitsuba 3 as well

  std::vector<Property*> rfilters = take_objects(film, "rfilter");
  if (rfilters.size() > 1) fail(rfilters[1]->loc, describe(film), " has more than one rfilter");
  Node default_rfilter = empty_node("rfilter", "gaussian", film.loc);  // Mitsuba's default
  reconstruction_filter(rfilters.empty() ? default_rfilter : *rfilters[0]->object, cam);
  check_consumed(film);

  cam.width = uint(crop_w);
  cam.height = uint(crop_h);
  cam.film_size = vec2(float(width), float(height));
  cam.crop_offset = vec2(float(crop_x), float(crop_y));
  // src/render/integrator.cpp: the samples cover the crop window, widened with sample_border
  // by the filter's border_size() (src/core/rfilter.cpp: ceil(radius - 0.5 - 2 RayEpsilon),
  // RayEpsilon = 1500 * 2^-24 in float; 0 for the box).
  float border = 0.0f;
  if (sample_border && cam.rfilter != RFILTER_BOX)
    border = std::ceil(cam.filter_radius - 0.5f - 2.0f * (1500.0f * 0x1p-24f));
  cam.sample_min = cam.crop_offset - vec2(border);
  cam.sample_max = cam.crop_offset + vec2(float(crop_w), float(crop_h)) + vec2(border);

  // ---- sampler
  std::vector<Property*> samplers = take_objects(s, "sampler");
  if (samplers.size() > 1) fail(samplers[1]->loc, describe(s), " has more than one sampler");
  Node default_sampler = empty_node("sampler", "independent", s.loc);
  Node& sampler = samplers.empty() ? default_sampler : *samplers[0]->object;
  uint sampler_type;
  if (!sampler_type_of(sampler.type, sampler_type))
    fail(sampler.loc, "unknown sampler type \"", sampler.type,
         "\" (supported: independent, stratified, ldsampler, multijitter, orthogonal, zsobol, "
         "sobol)");
  long long spp = take_integer(sampler, "sample_count", 4), seed = take_integer(sampler, "seed", 0);
  if (spp <= 0 || spp > 0xffffffffLL)
    fail(sampler.loc, describe(sampler), ": sample_count must be positive");
  if (seed < 0 || seed > 0xffffffffLL)
    fail(sampler.loc, describe(sampler), ": seed must be in [0, 2^32)");
  bool jitter = true;
  if (sampler_type == SAMPLER_STRATIFIED || sampler_type == SAMPLER_MULTIJITTER ||
      sampler_type == SAMPLER_ORTHOGONAL)
    jitter = take_bool(sampler, "jitter", true);
  // Mitsuba's Bush construction for strength > 2 permutes p^strength rows while its
  // sample_count stays p^2; only Bose's strength-2 arrays are implemented (its default).
  if (sampler_type == SAMPLER_ORTHOGONAL && take_integer(sampler, "strength", 2) != 2)
    fail(find_property(sampler, "strength")->loc, describe(sampler),
         ": only strength 2 (Bose's orthogonal arrays, Mitsuba's default) is supported");
  try {
    set_sampler(scene_, sampler_type, uint(spp), jitter);
  } catch (const SceneError& e) {
    fail(location_of(sampler, "sample_count"), describe(sampler), ": ", e.what());
  }
  scene_.seed = uint(seed);
  check_consumed(sampler);

  // ---- Sensor (src/render/sensor.cpp): shutter_open/close both default to 0. Nothing in a
  // Mitsuba 3 scene moves over time, so an open shutter interval changes no pixel.
  double shutter_open = take_float(s, "shutter_open", 0.0);
  double shutter_close = take_float(s, "shutter_close", 0.0);
  if (shutter_close < shutter_open)
    fail(location_of(s, "shutter_close"), describe(s),
         ": shutter_close must not be earlier than shutter_open");

  // ---- ProjectiveCamera (src/render/sensor.cpp): clip planes and focus_distance, read by
  // every projective camera (perspective accepts it and, like Mitsuba, ignores it).
  double near_clip = take_float(s, "near_clip", 1e-2), far_clip = take_float(s, "far_clip", 1e4);
  if (!(near_clip > 0.0))
    fail(location_of(s, "near_clip"), describe(s), ": near_clip must be positive");
  if (!(far_clip > near_clip) || !std::isfinite(far_clip))
    fail(location_of(s, "far_clip"), describe(s), ": far_clip must be finite and exceed near_clip");
  cam.near_clip = float(near_clip);
  cam.far_clip = float(far_clip);
  double focus = take_float(s, "focus_distance", double(float(far_clip)));
  glm::dmat4 to_world = take_transform(s, "to_world");
  store_rows(to_world, cam.to_world);

  double aspect = double(width) / double(height);
  cam.principal_point = vec2(0.0f);
  cam.aperture_radius = 0.0f;
  cam.focus_distance = 0.0f;
  if (cam.type == SENSOR_ORTHOGRAPHIC) {
    // include/mitsuba/render/sensor.h orthographic_projection: x in [-1, 1], y in
    // [-1/aspect, 1/aspect] on the near plane.
    cam.half_extent = vec2(1.0f, float(1.0 / aspect));
  } else {
    if (has_scale(to_world))
      fail(location_of(s, "to_world"), describe(s),
           ": scale factors in the camera-to-world transform are not allowed (Mitsuba)");
    double tan_x = std::tan(0.5 * horizontal_fov(s, aspect) * PI_D / 180.0);
    cam.half_extent = vec2(float(tan_x), float(tan_x / aspect));
  }
  if (cam.type == SENSOR_PERSPECTIVE) {
    cam.principal_point = vec2(float(take_float(s, "principal_point_offset_x", 0.0)),
                               float(take_float(s, "principal_point_offset_y", 0.0)));
  } else if (cam.type == SENSOR_THINLENS) {
    double aperture = take_float(s, "aperture_radius");
    if (!std::isfinite(aperture))
      fail(location_of(s, "aperture_radius"), describe(s), ": aperture_radius must be finite");
    if (!(focus > 0.0) || !std::isfinite(focus))
      fail(location_of(s, "focus_distance"), describe(s),
           ": focus_distance must be positive and finite");
    // thinlens.cpp replaces a zero aperture by dr::Epsilon<float> (with a warning).
    cam.aperture_radius = aperture == 0.0 ? 0x1p-24f : float(aperture);
    cam.focus_distance = float(focus);
  }
  check_consumed(s);
}

namespace {

// Parameters of Mitsuba's Integrator and SamplingIntegrator bases (src/render/integrator.cpp).
// block_size and samples_per_pass only split the work into tiles and passes: twinray's
// estimate does not depend on either. A positive timeout stops Mitsuba's render early, which
// twinray never does, so it is refused.
void take_sampling_integrator_base(Node& m) {
  if (take_float(m, "timeout", -1.0) > 0.0)
    fail(find_property(m, "timeout")->loc, describe(m),
         ": a timeout would stop the render early; twinray renders every sample (refused)");
  if (take_integer(m, "block_size", 0) < 0)
    fail(find_property(m, "block_size")->loc, describe(m), ": block_size must not be negative");
  if (has_property(m, "samples_per_pass") && take_integer(m, "samples_per_pass", 1) <= 0)
    fail(find_property(m, "samples_per_pass")->loc, describe(m),
         ": samples_per_pass must be positive");
}

// Mitsuba's `aov` output variables: `aovs` is a list of name:type pairs separated by commas
// or spaces (string::tokenize(", ")); each type gives the channels name.<suffix> below. The
// channel names of the nested integrator (name.R/G/B/A) may not repeat either
// (hdrfilm.cpp prepare() refuses duplicates).
struct AovSpec {
  std::vector<uint> types;
  std::vector<std::vector<std::string>> channels;
};

AovSpec parse_aovs(Node& n, const std::string& nested_name) {
  Property* p = find_property(n, "aovs");
  std::string list = take_string(n, "aovs");
  struct TypeChannels {
    const char* type;
    uint aov;
    std::vector<std::string> suffixes;
  };
  static const std::vector<TypeChannels> kTypes = {
      {"albedo", AOV_ALBEDO, {"R", "G", "B"}},
      {"depth", AOV_DEPTH, {"T"}},
      {"position", AOV_POSITION, {"X", "Y", "Z"}},
      {"uv", AOV_UV, {"U", "V"}},
      {"geo_normal", AOV_GEO_NORMAL, {"X", "Y", "Z"}},
      {"sh_normal", AOV_SH_NORMAL, {"X", "Y", "Z"}},
      {"prim_index", AOV_PRIM_INDEX, {"I"}},
      {"shape_index", AOV_SHAPE_INDEX, {"I"}},
  };
  AovSpec spec;
  std::set<std::string> seen;
  if (!nested_name.empty())
    for (const char* c : {".R", ".G", ".B", ".A"}) seen.insert(nested_name + c);
  size_t start = 0;
  while (start < list.size()) {
    size_t end = list.find_first_of(", ", start);
    if (end == std::string::npos) end = list.size();
    std::string token = list.substr(start, end - start);
    start = end + 1;
    if (token.empty()) continue;
    size_t colon = token.find(':');
    if (colon == 0 || colon == std::string::npos || colon + 1 == token.size() ||
        token.find(':', colon + 1) != std::string::npos)
      fail(p->loc, describe(n), ": invalid AOV \"", token, "\" (expected <name>:<type>)");
    std::string name = token.substr(0, colon), type = token.substr(colon + 1);
    auto t = std::find_if(kTypes.begin(), kTypes.end(),
                          [&](const TypeChannels& c) { return type == c.type; });
    if (t == kTypes.end()) {
      if (type == "dp_du" || type == "dp_dv" || type == "duv_dx" || type == "duv_dy")
        fail(p->loc, describe(n), ": AOV type \"", type, "\" is not supported by twinray");
      fail(p->loc, describe(n), ": invalid AOV type \"", type,
           "\" (albedo, depth, position, uv, geo_normal, sh_normal, prim_index, shape_index)");
    }
    if (spec.types.size() == AOV_MAX) fail(p->loc, describe(n), ": more than ", AOV_MAX, " AOVs");
    std::vector<std::string> channels;
    for (const std::string& suffix : t->suffixes) {
      channels.push_back(name + "." + suffix);
      if (!seen.insert(channels.back()).second)
        fail(p->loc, describe(n), ": duplicate channel name \"", channels.back(), "\"");
    }
    spec.types.push_back(t->aov);
    spec.channels.push_back(channels);
  }
  return spec;
}

}  // namespace

void SceneBuilder::add_integrator(Node& n) {
  Node* inner = &n;
  AovSpec aovs;
  bool black = false;  // an aov integrator without a nested one: Mitsuba's colour is zero
  if (n.type == "aov") {
    std::vector<Property*> nested = take_objects(n, "integrator");
    if (nested.size() > 1)
      fail(nested[1]->loc, describe(n),
           ": twinray renders one nested integrator (Mitsuba writes each into its own channels)");
    aovs = parse_aovs(n, nested.empty() ? "" : nested[0]->name);
    // Read by Mitsuba's Integrator base; the AOVs do not depend on it.
    take_bool(n, "hide_emitters", false);
    take_sampling_integrator_base(n);
    check_consumed(n);
    if (nested.empty())
      black = true;
    else
      inner = nested[0]->object.get();
  } else if (n.type == "moment") {
    std::vector<Property*> nested = take_objects(n, "integrator");
    if (nested.size() != 1)
      fail(n.loc, describe(n),
           " must wrap exactly one integrator (twinray writes no AOV channels of several)");
    take_sampling_integrator_base(n);
    check_consumed(n);
    inner = nested[0]->object.get();
  }
  Integrator& it = b_.globals.integrator;
  it = Integrator{};
  it.max_depth = -1;
  it.rr_depth = 5;
  it.min_depth = 1;
  it.emitter_samples = it.bsdf_samples = 1u;
  Node& m = *inner;
  for (size_t i = 0; i < aovs.types.size(); ++i) it.aov_types[i / 4][i % 4] = aovs.types[i];
  it.aov_count = uint(aovs.types.size());
  scene_.aov_channels = aovs.channels;
  if (black) {
    it.type = INTEGRATOR_PATH;
    it.max_depth = 0;
    scene_.integrator_name = "aov";
    return;
  }
  if (m.type == "path") {
    it.type = INTEGRATOR_PATH;
    long long max_depth = take_integer(m, "max_depth", -1),
              rr_depth = take_integer(m, "rr_depth", 5);
    if (max_depth < -1 || max_depth > 1000000)
      fail(find_property(m, "max_depth")->loc, describe(m),
           ": max_depth must be -1 (unbounded) or >= 0");
    if (rr_depth <= 0 || rr_depth > 1000000)
      fail(find_property(m, "rr_depth")->loc, describe(m), ": rr_depth must be positive");
    it.max_depth = int(max_depth);
    it.rr_depth = int(rr_depth);
    // twinray extension (Mitsuba's path reads no min_depth): the shortest path length counted,
    // in max_depth's units (core/integrator.h).
    long long min_depth = take_integer(m, "min_depth", 1);
    if (min_depth < 1 || min_depth > 1000000 ||
        (max_depth >= 0 && min_depth > std::max(max_depth, 1LL)))
      fail(find_property(m, "min_depth")->loc, describe(m),
           ": min_depth must be >= 1 and <= max_depth (-1: unbounded)");
    it.min_depth = int(min_depth);
  } else if (m.type == "direct") {
    it.type = INTEGRATOR_DIRECT;
    // Mitsuba direct.cpp: shading_samples sets both counts unless they are given.
    if (has_property(m, "shading_samples") &&
        (has_property(m, "emitter_samples") || has_property(m, "bsdf_samples")))
      fail(find_property(m, "shading_samples")->loc, describe(m),
           ": give either shading_samples or emitter_samples/bsdf_samples");
    long long shading = take_integer(m, "shading_samples", 1);
    long long emitter = take_integer(m, "emitter_samples", shading);
    long long bsdf = take_integer(m, "bsdf_samples", shading);
    const long long limit = 1 << 20;
    if (shading < 0 || emitter < 0 || bsdf < 0 || emitter + bsdf == 0 || emitter > limit ||
        bsdf > limit)
      fail(m.loc, describe(m), ": sample counts must be in [0, 2^20] and not both zero");
    it.emitter_samples = uint(emitter);
    it.bsdf_samples = uint(bsdf);
  } else if (m.type == "ambientocclusion") {
    // pbrt-v4 (AOIntegrator::Create): cossample (default true), maxdistance (default
    // Infinity); core/integrators/ambient_occlusion.h.
    it.type = INTEGRATOR_AMBIENT_OCCLUSION;
    it.cos_sample = take_bool(m, "cossample", true) ? 1u : 0u;
    double max_distance = take_float(m, "maxdistance", double(FLOAT_MAX));
    if (!(max_distance > 0.0))
      fail(find_property(m, "maxdistance")->loc, describe(m), ": maxdistance must be positive");
    it.max_distance = float(std::min(max_distance, double(FLOAT_MAX)));
  } else if (m.type == "moment") {
    fail(m.loc, "nested moment integrators are not supported");
  } else if (m.type == "aov") {
    fail(m.loc, "nested aov integrators are not supported");
  } else {
    fail(m.loc, "unknown integrator type \"", m.type,
         "\" (supported: path, direct, ambientocclusion, moment, aov)");
  }
  // twinray extension (Mitsuba 3 reads none; Mitsuba 0.6's strictNormals of path and direct,
  // which a 0.x file's strictNormals becomes): core/integrator.h.
  if (m.type == "path" || m.type == "direct")
    it.strict_normals = take_bool(m, "strict_normals", false) ? 1u : 0u;
  // Mitsuba's Integrator base; pbrt-v4's ambientocclusion has no such parameter.
  if (m.type != "ambientocclusion")
    it.hide_emitters = take_bool(m, "hide_emitters", false) ? 1u : 0u;
  take_sampling_integrator_base(m);
  check_consumed(m);
  scene_.integrator_name =
      n.type == "moment" || n.type == "aov" ? n.type + "(" + m.type + ")" : m.type;
}

}  // namespace tr
