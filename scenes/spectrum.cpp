#include "scenes/spectrum.h"

#include <algorithm>

namespace tr {

namespace {

// Table position of a wavelength: the lower sample index and the interpolation weight of the
// upper one. Returns false outside [CIE_MIN, CIE_MAX].
bool table_position(double lambda, int& i0, double& w1) {
  if (!(lambda >= CIE_MIN && lambda <= CIE_MAX)) return false;
  double t = (lambda - CIE_MIN) * ((CIE_SAMPLES - 1) / (CIE_MAX - CIE_MIN));
  i0 = std::clamp(int(t), 0, CIE_SAMPLES - 2);
  w1 = t - i0;
  return true;
}

}  // namespace

glm::dvec3 cie_xyz(double lambda) {
  int i;
  double w1;
  if (!table_position(lambda, i, w1)) return glm::dvec3(0.0);
  const CieSample& a = CIE_TABLE[i];
  const CieSample& b = CIE_TABLE[i + 1];
  double w0 = 1.0 - w1;
  return glm::dvec3(w0 * a.x + w1 * b.x, w0 * a.y + w1 * b.y, w0 * a.z + w1 * b.z);
}

double cie_d65(double lambda) {
  int i;
  double w1;
  if (!table_position(lambda, i, w1)) return 0.0;
  return ((1.0 - w1) * CIE_TABLE[i].d65 + w1 * CIE_TABLE[i + 1].d65) * CIE_D65_NORMALIZATION;
}

glm::dvec3 xyz_to_linear_srgb(glm::dvec3 xyz) {
  return glm::dvec3(3.240479 * xyz.x - 1.537150 * xyz.y - 0.498535 * xyz.z,
                    -0.969256 * xyz.x + 1.875991 * xyz.y + 0.041556 * xyz.z,
                    0.055648 * xyz.x - 0.204043 * xyz.y + 1.057311 * xyz.z);
}

glm::dvec3 spectrum_to_rgb(const std::vector<double>& wavelengths,
                           const std::vector<double>& values, SpectrumUse use) {
  const int steps = 1000;
  const size_t n = wavelengths.size();
  glm::dvec3 xyz(0.0);
  for (int s = 0; s < steps; ++s) {
    double lambda = CIE_MIN + (s / double(steps - 1)) * (CIE_MAX - CIE_MIN);
    if (lambda < wavelengths.front() || lambda > wavelengths.back()) continue;
    // Last interval [w_i, w_i+1] with w_i <= lambda.
    size_t i = size_t(std::upper_bound(wavelengths.begin(), wavelengths.end(), lambda) -
                      wavelengths.begin());
    i = std::clamp<size_t>(i, 1, n - 1) - 1;
    double w0 = wavelengths[i], w1 = wavelengths[i + 1];
    double v0 = values[i] * CIE_Y_NORMALIZATION, v1 = values[i + 1] * CIE_Y_NORMALIZATION;
    double v = ((lambda - w1) * v0 + (w0 - lambda) * v1) / (w0 - w1);
    double weight = use == SpectrumUse::Emission ? 1.0 : cie_d65(lambda);
    xyz += cie_xyz(lambda) * v * weight;
  }
  xyz *= (CIE_MAX - CIE_MIN) / steps;
  glm::dvec3 rgb = xyz_to_linear_srgb(xyz);
  if (use == SpectrumUse::Reflectance) return glm::clamp(rgb, 0.0, 1.0);
  return glm::max(rgb, 0.0);
}

glm::dvec3 constant_spectrum_to_rgb(double value, SpectrumUse use) {
  if (use == SpectrumUse::Emission) return value * xyz_to_linear_srgb(glm::dvec3(1.0));
  return glm::dvec3(value);
}

}  // namespace tr
