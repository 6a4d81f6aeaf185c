#include "validation/harness/variant.h"

#include <climits>
#include <sstream>

#include "scenes/emitter_selection.h"
#include "scenes/sampler.h"

namespace tr {
namespace {

int parse_int(const std::string& key, const std::string& value, int minimum) {
  size_t used = 0;
  long v = 0;
  try {
    v = std::stol(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || v < minimum || v > 1000000)
    throw VariantError(key + " expects an integer >= " + std::to_string(minimum) + ", got '" +
                       value + "'");
  return int(v);
}

}  // namespace

RenderVariant parse_variant(const std::string& spec) {
  RenderVariant v;
  std::istringstream fields(spec);
  std::string field;
  while (std::getline(fields, field, ',')) {
    size_t eq = field.find('=');
    if (eq == std::string::npos || eq == 0)
      throw VariantError("variant field '" + field + "' is not KEY=VALUE");
    std::string key = field.substr(0, eq), value = field.substr(eq + 1);
    if (key == "integrator") {
      if (value == "path")
        v.integrator = INTEGRATOR_PATH;
      else if (value == "direct")
        v.integrator = INTEGRATOR_DIRECT;
      else
        throw VariantError("integrator must be path or direct, got '" + value + "'");
    } else if (key == "max_depth") {
      v.max_depth = parse_int(key, value, -1);
    } else if (key == "rr_depth") {
      v.rr_depth = value == "off" ? INT_MAX : parse_int(key, value, 1);
    } else if (key == "sampler") {
      uint type = 0;
      if (!sampler_type_of(value, type)) throw VariantError("unknown sampler '" + value + "'");
      v.sampler = type;
    } else if (key == "emitter_selection") {
      try {
        v.emitter_selection = parse_emitter_selection(value);
      } catch (const std::invalid_argument& e) {
        throw VariantError(e.what());
      }
    } else if (key == "randomizations") {
      v.randomizations = uint(parse_int(key, value, 1));
    } else if (key == "backend") {
      if (value != "cpu" && value != "gpu")
        throw VariantError("backend must be cpu or gpu, got '" + value + "'");
      v.backend = value;
    } else if (key == "label") {
      v.label = value;
    } else {
      throw VariantError("unknown variant field '" + key + "'");
    }
  }
  if (v.label.empty()) v.label = spec.empty() ? "scene" : spec;
  return v;
}

Scene apply_variant(const Scene& scene, const RenderVariant& variant) {
  Scene s = scene;
  Integrator& it = s.buffers.globals.integrator;
  if (variant.integrator) {
    it.type = *variant.integrator;
    if (it.type == INTEGRATOR_DIRECT) it.emitter_samples = it.bsdf_samples = 1u;
  }
  if (variant.max_depth) it.max_depth = *variant.max_depth;
  if (variant.rr_depth) it.rr_depth = *variant.rr_depth;
  if (variant.sampler) set_sampler(s, *variant.sampler, s.spp, true);
  if (variant.emitter_selection) use_emitter_selection(s.buffers, *variant.emitter_selection);
  return s;
}

void set_variant_sample_count(Scene& scene, const RenderVariant& variant, uint spp) {
  if (variant.randomizations)
    set_sample_count_in_passes(scene, spp, *variant.randomizations);
  else
    set_sample_count(scene, spp);
}

}  // namespace tr
