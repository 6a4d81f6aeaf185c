#include "scenes/emitter_selection.h"

#include <stdexcept>
#include <string>

#include "scenes/alias_table.h"
#include "scenes/light_bvh_build.h"

namespace tr {

namespace {

// Appends an alias table over `weights` and returns its offset, or NO_INDEX when every weight
// is zero.
uint append_table(SceneBuffers& b, const std::vector<double>& weights) {
  double sum = 0.0;
  for (double w : weights) sum += w;
  if (!(sum > 0.0)) return NO_INDEX;
  std::vector<AliasEntry> table = build_alias_table(weights);
  const uint offset = uint(b.alias.size());
  b.alias.insert(b.alias.end(), table.begin(), table.end());
  return offset;
}

}  // namespace

uint parse_emitter_selection(const std::string& name) {
  if (name == "uniform") return EMITTER_SELECTION_UNIFORM;
  if (name == "power") return EMITTER_SELECTION_POWER;
  if (name == "bvh") return EMITTER_SELECTION_BVH;
  throw std::invalid_argument("emitter selection must be uniform, power or bvh, got '" + name +
                              "'");
}

const char* emitter_selection_name(uint selection) {
  switch (selection) {
    case EMITTER_SELECTION_UNIFORM:
      return "uniform";
    case EMITTER_SELECTION_POWER:
      return "power";
    case EMITTER_SELECTION_BVH:
      return "bvh";
    default:
      throw std::logic_error("emitter selection " + std::to_string(selection) + " has no name");
  }
}

void use_emitter_selection(SceneBuffers& b, uint selection) {
  SceneGlobals& g = b.globals;
  if (selection == g.emitter_selection) return;
  if (g.emitter_selection != EMITTER_SELECTION_UNIFORM)
    throw std::logic_error("emitter selection: switch only from Mitsuba's");
  g.emitter_selection = selection;
  const uint n = g.emitter_count;
  g.light_root = NO_INDEX;
  g.infinite_alias_offset = NO_INDEX;
  g.infinite_probability = 0.0f;
  if (n == 0) return;
  // The table by sampling_weight: pmf_i = w_i / sum(w).
  std::vector<double> weight(n);
  for (uint i = 0; i < n; ++i) weight[i] = b.alias[g.emitter_alias_offset + i].pmf;
  const std::vector<LightBounds> bounds = emitter_light_bounds(b);
  std::vector<double> power(n);
  for (uint i = 0; i < n; ++i) power[i] = weight[i] * bounds[i].phi;

  if (selection == EMITTER_SELECTION_POWER) {
    // Emitters that all emit nothing light nothing whichever is chosen: the table by
    // sampling_weight stays.
    const uint offset = append_table(b, power);
    if (offset != NO_INDEX) g.emitter_alias_offset = offset;
    return;
  }
  std::vector<double> infinite(n, 0.0);
  std::vector<uint> members;
  uint infinite_count = 0;
  for (uint i = 0; i < n; ++i) {
    if (bounds[i].infinite) {
      infinite[i] = weight[i];
      if (weight[i] > 0.0) ++infinite_count;
    } else if (power[i] > 0.0) {
      members.push_back(i);
    }
  }
  g.infinite_alias_offset = append_table(b, infinite);
  std::vector<uint> leaves;
  g.light_root = build_light_bvh(bounds, power, members, b.light_nodes, leaves);
  for (uint i = 0; i < n; ++i) b.emitters[i].light_leaf = leaves[i];
  // pbrt-v4's BVHLightSampler: the tree counts as one more infinite light.
  const uint choices = infinite_count + (g.light_root != NO_INDEX ? 1u : 0u);
  g.infinite_probability = choices == 0 ? 0.0f : float(infinite_count) / float(choices);
}

}  // namespace tr
