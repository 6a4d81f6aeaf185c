#include "scenes/ior.h"

#include "scenes/values.h"

namespace tr {

namespace {

struct NamedIor {
  const char* name;
  double ior;
};

// Mitsuba 3 include/mitsuba/render/ior.h (measured at 0-20 degrees C, ~589 nm; Hecht, Optics).
const NamedIor DIELECTRIC_IORS[] = {
    {"vacuum", 1.0},      {"helium", 1.000036},        {"hydrogen", 1.000132},
    {"air", 1.000277},    {"carbon dioxide", 1.00045}, {"water", 1.3330},
    {"acetone", 1.36},    {"ethanol", 1.361},          {"carbon tetrachloride", 1.461},
    {"glycerol", 1.4729}, {"benzene", 1.501},          {"silicone oil", 1.52045},
    {"bromine", 1.661},   {"water ice", 1.31},         {"fused quartz", 1.458},
    {"pyrex", 1.470},     {"acrylic glass", 1.49},     {"polypropylene", 1.49},
    {"bk7", 1.5046},      {"sodium chloride", 1.544},  {"amber", 1.55},
    {"pet", 1.5750},      {"diamond", 2.419},
};

}  // namespace

bool lookup_dielectric_ior(const std::string& name, double& ior) {
  std::string lower = to_lower(name);
  for (const NamedIor& e : DIELECTRIC_IORS) {
    if (lower == e.name) {
      ior = e.ior;
      return true;
    }
  }
  return false;
}

std::string dielectric_ior_names() {
  std::string names;
  for (const NamedIor& e : DIELECTRIC_IORS)
    names += (names.empty() ? "" : ", ") + std::string(e.name);
  return names;
}

const ConductorIor* lookup_conductor_ior(const std::string& name) {
  for (int i = 0; i < CONDUCTOR_IOR_COUNT; ++i)
    if (name == CONDUCTOR_IORS[i].name) return &CONDUCTOR_IORS[i];
  return nullptr;
}

std::string conductor_ior_names() {
  std::string names = "none";
  for (int i = 0; i < CONDUCTOR_IOR_COUNT; ++i) names += ", " + std::string(CONDUCTOR_IORS[i].name);
  return names;
}

}  // namespace tr
