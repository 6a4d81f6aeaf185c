// Walker's alias method with Vose's numerically stable construction: M. D. Vose, "A Linear
// Algorithm for Generating Random Numbers with a Given Distribution", IEEE Transactions on
// Software Engineering 17(9), 1991. Sampling (core side): bin i = floor(u n), keep it with
// probability q_i, else take alias_i.
#pragma once

#include <vector>

#include "core/scene_types.h"

namespace tr {

// One entry per weight, pmf_i = w_i / sum(w). Throws std::invalid_argument for an empty list,
// a negative or non-finite weight, or an all-zero list.
std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights);

}  // namespace tr
