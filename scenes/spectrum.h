// Spectra -> linear sRGB, the way Mitsuba 3's RGB variants convert <spectrum> values
// (src/core/xml.cpp, create_texture_from_spectrum, and spectrum_list_to_srgb in
// src/core/spectrum.cpp, v3.2-v3.5): the piecewise-linear spectrum, scaled by 1/106.75 (so a
// unit spectrum has luminance 1), is integrated against the CIE 1931 matching functions by a
// 1000-point Riemann sum over [360, 830] nm, then XYZ -> linear sRGB. Reflectance-like values
// are weighted by the normalised D65 illuminant (so a flat spectrum maps to grey); emission
// spectra are not (their D65 weighting happens at render time in spectral variants only).
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace tr {

struct CieSample {
  double lambda;
  double x, y, z;  // CIE 1931 2-degree observer
  double d65;      // D65 relative spectral power, 100 at 560 nm
};

const int CIE_SAMPLES = 95;  // 360..830 nm every 5 nm
extern const CieSample CIE_TABLE[CIE_SAMPLES];

const double CIE_MIN = 360.0;
const double CIE_MAX = 830.0;
// A unit spectrum integrates to luminance 1 after this scaling (Mitsuba MI_CIE_Y_NORMALIZATION).
const double CIE_Y_NORMALIZATION = 1.0 / 106.7502593994140625;
// D65 scaled by this integrates to luminance 1 (Mitsuba MI_CIE_D65_NORMALIZATION).
const double CIE_D65_NORMALIZATION = 1.0 / 98.99741751876255;

// How a spectrum-valued parameter is used; decides D65 weighting and clamping.
enum class SpectrumUse {
  Reflectance,  // bounded to [0, 1], D65-weighted
  Unbounded,    // eta, k, int_ior, ext_ior: clamped below at 0 only, D65-weighted
  Emission,     // inside an <emitter>: clamped below at 0 only, not D65-weighted
};

glm::dvec3 cie_xyz(double lambda);  // linear interpolation in the table, 0 outside it
double cie_d65(double lambda);      // normalised by CIE_D65_NORMALIZATION, 0 outside
// IEC 61966-2-1 (sRGB) XYZ -> linear RGB matrix, as Mitsuba's xyz_to_srgb.
glm::dvec3 xyz_to_linear_srgb(glm::dvec3 xyz);

// wavelengths strictly increasing, at least two samples.
glm::dvec3 spectrum_to_rgb(const std::vector<double>& wavelengths,
                           const std::vector<double>& values, SpectrumUse use);
// A constant spectrum: the value itself, except for emission, where Mitsuba (v3.2+) returns
// value * xyz_to_srgb(1, 1, 1) (the colour of an equal-energy spectrum under a D65 white).
glm::dvec3 constant_spectrum_to_rgb(double value, SpectrumUse use);

}  // namespace tr
