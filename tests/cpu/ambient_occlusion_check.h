// The closed form of ambient occlusion between two parallel planes (scene
// tests/cpu/scenes/ambient_occlusion_planes.xml), shared by the CPU and GPU tests, which check
// renders against it with constant_image_check.h.
//
// At a point of one plane, a direction at angle theta from the normal towards the other plane,
// at distance h, meets it at distance h / cos(theta): it is occluded within maxdistance R iff
// cos(theta) > h / R. The ambient occlusion (1 / pi) ∫ V cos(theta) dw is therefore
// (1 / pi) ∫_0^{2 pi} ∫_0^{c} cos(theta) d(cos(theta)) dphi = c^2 with c = min(h / R, 1): with
// cosine-weighted directions cos^2(theta) is uniform on [0, 1], so P(unoccluded) = c^2; with
// uniform ones the score 2 cos(theta) [cos(theta) <= c] has the same mean, ∫_0^c 2z dz = c^2.
// R <= h gives 1. The planes are 200 x 200 squares: an occluding direction reaches the other
// plane within R horizontally of the point (all points seen lie within 0.1 of the centre), so
// with R < 99 the finite size changes nothing.
#pragma once

#include <algorithm>

namespace tr::test {

inline double ambient_occlusion_between_planes(double h, double max_distance) {
  double c = std::min(h / max_distance, 1.0);
  return c * c;
}

}  // namespace tr::test
