#include "validation/harness/mitsuba_acceptance.h"

#include <cmath>
#include <cstdio>

namespace tr {

AcceptanceResult mitsuba_acceptance(const RgbImage& img, double spp, const RgbImage& ref,
                                    const RgbImage& ref_variance, double ref_spp) {
  check_same_size(img, "render", ref, "reference");
  check_same_size(ref_variance, "reference variance", ref, "reference");
  AcceptanceResult r;
  r.pixel_z = pixel_z_test(img, spp, ref, ref_variance);
  r.block_z = block_z_test(img, spp, ref, ref_variance, ref_spp);
  r.gain_z = gain_z_test(img, spp, ref, ref_variance, ref_spp);
  r.passed = r.pixel_z.passed && r.block_z.passed;
  return r;
}

std::string describe_test(const HypothesisTestResult& t) {
  char line[512];
  if (t.name.rfind("gain", 0) == 0)
    std::snprintf(line, sizeof line, "%-11s %s  gain X %.5f Y %.5f Z %.5f, min p %.3g (alpha %.3g)",
                  t.name.c_str(), t.passed ? "pass" : "FAIL", t.gain[0], t.gain[1], t.gain[2],
                  t.min_p, t.alpha);
  else
    std::snprintf(line, sizeof line,
                  "%-11s %s  %zu of %zu values fail (%zu of %dx%d cells; at most %.0f may), "
                  "min p %.3g at cell (%d, %d) %c (alpha %.3g)",
                  t.name.c_str(), t.passed ? "pass" : "FAIL", t.failing_values, t.values,
                  t.failing_cells, t.cells_x, t.cells_y,
                  std::floor(double(t.values) * (1.0 - t.required_fraction) + 1e-9), t.min_p,
                  t.min_p_x, t.min_p_y, t.min_p_channel >= 0 ? "XYZ"[t.min_p_channel] : '-',
                  t.alpha);
  return line;
}

// The golden-ratio increment: a seed no nearby suite seed shares.
std::uint32_t confirmation_seed(std::uint32_t seed) { return seed + 0x9e3779b9u; }

}  // namespace tr
