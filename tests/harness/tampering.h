// Deliberately wrong renders for the harness's power tests: edits of a loaded scene (so the
// render itself is wrong, through the real renderer) and of a rendered image.
#pragma once

#include "scenes/scene.h"
#include "validation/image/rgb_image.h"

namespace tr {
namespace testing {

// Index of the one diffuse material whose reflectance is the constant `rgb`; throws otherwise.
uint find_diffuse_material(const Scene& scene, vec3 rgb);

// Multiplies the constant reflectance of a diffuse material by `factor`.
void scale_diffuse_reflectance(Scene& scene, uint material, float factor);

// Makes a diffuse material, lit by the scene's single point light with direct lighting only
// (max_depth 2), render as a BSDF that forgets the cosine of its eval (f instead of f cos):
// the constant reflectance rho becomes a bitmap texture rho / cos(theta_i) baked over the uv
// domain of the one mesh that uses the material (texel centres inside a triangle in uv take
// the interpolated shading normal and position; cos clamped to at least min_cos; uncovered
// texels keep rho), so that (rho / cos) / pi * cos * I / r^2 = rho / pi * I / r^2.
void drop_diffuse_cosine(Scene& scene, uint material, int texture_width, int texture_height,
                         float min_cos);

// Multiplies a size x size patch with top-left pixel (x0, y0) by factor.
void scale_patch(RgbImage& img, int x0, int y0, int size, double factor);

}  // namespace testing
}  // namespace tr
