// Mitsuba 3's in-memory upgrade of scenes whose version is below 2.0.0 (Mitsuba 0.x files), as
// Mitsuba 3.8 does it: src/core/parser.cpp, transform_upgrade calls upgrade_from_v1 on the
// parameters of every object of such a file (the root <scene> included), once the whole scene is
// parsed. Nothing else changes: Mitsuba 3.8 upgrades nothing between 2.0.0 and 3.x.
#pragma once

#include <string>

#include "scenes/properties.h"

namespace tr {

// Mitsuba's camel_to_underscore_case: an upper-case letter that follows a lower-case one starts
// a new word; it and the upper-case letters right after it become "_" and lower case
// ("maxDepth" -> "max_depth", "intIOR" -> "int_ior").
std::string camel_to_underscore_case(const std::string& name);

// Mitsuba 3.8's upgrade_from_v1, on `node`'s own parameters (not on those of nested objects):
// 1. every parameter name through camel_to_underscore_case, in document order, unless a
//    parameter already has the new name (Properties::rename_property then leaves it as it is);
// 2. on a `diffuse` plugin, `diffuse_reflectance` renamed `reflectance` (unless taken, as 1.);
// 3. `uoffset`, `voffset`, `uscale`, `vscale` (floats or integers; absent: 0, 0, 1, 1) replaced
//    by the transform `to_uv` = scale(uscale, vscale, 1) * translate(uoffset, voffset, 0), an
//    error when `to_uv` is also given (Mitsuba: "specified multiple times").
void upgrade_from_v1(Node& node);

}  // namespace tr
