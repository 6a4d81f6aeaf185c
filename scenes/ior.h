// Named indices of refraction, as Mitsuba 3 accepts them in int_ior/ext_ior (dielectrics) and
// in a conductor's `material`.
#pragma once

#include <string>

namespace tr {

// Real IORs at ~589 nm (Mitsuba's table in include/mitsuba/render/ior.h, values from Hecht,
// "Optics", 4th ed.). Case-insensitive. Returns false for an unknown name.
bool lookup_dielectric_ior(const std::string& name, double& ior);
std::string dielectric_ior_names();  // for error messages

// Complex IOR eta + i k of a conductor, converted from the spectral data Mitsuba ships
// (mitsuba-data repository, ior/<name>.{eta,k}.spd) to linear sRGB exactly as Mitsuba's RGB
// variants do (complex_ior_from_file in include/mitsuba/render/ior.h: scaled by the CIE Y
// normalisation, integrated against the CIE 1931 curves without D65 weighting, clamped at 0).
struct ConductorIor {
  const char* name;  // Mitsuba's `material` value (case-sensitive, as its file names)
  float eta[3];
  float k[3];
};
extern const ConductorIor CONDUCTOR_IORS[];
extern const int CONDUCTOR_IOR_COUNT;
const ConductorIor* lookup_conductor_ior(const std::string& name);  // nullptr if unknown
std::string conductor_ior_names();

}  // namespace tr
