// twinray's `vertex_tangents` (the shading frame of glTF's TANGENT, core/interaction.h
// tangent_frame): scene tests/cpu/scenes/vertex_tangents.xml, a diffuse square (rho = 0.5)
// under a normalmap of constant normal n = (0, sin 30, cos 30) in (tangent, bitangent, normal),
// lit by a directional emitter (irradiance E = 1) from l = (0, sin 30, cos 30), seen from
// above; normalmap's shadowing term off. Every sample scores rho / pi E max(0, n_world . l): its
// light sample is exact and its BSDF sample escapes into nothing, so the image is that constant.
//  - Bitangent +y: n_world = l, Lo = rho / pi.
//  - Bitangent -y (a mirrored uv layout): n_world = (0, -sin 30, cos 30), Lo = rho / pi cos 60.
//    Mitsuba's frame (bitangent = normal x tangent = +y) would give rho / pi here.
//  - Bitangent +y with the square turned 90 degrees about z and the light from (-sin 30, 0,
//    cos 30): the frame turns with the square, Lo = rho / pi (untransformed: rho / pi cos 41.4).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_fixture.h"

namespace tr::test {
namespace {

void expect_constant(const std::string& quad, const std::string& angle,
                     const std::string& direction, double expected) {
  LoadOptions load;
  load.defines = {{"quad", quad}, {"angle", angle}, {"direction", direction}};
  Scene scene = load_scene(test_scene("vertex_tangents.xml"), load);
  ASSERT_NE(scene.buffers.shapes[0].flags & SHAPE_HAS_TANGENTS, 0u);
  RenderOptions options;
  options.seed = 1;
  RenderResult r = render_cpu(scene, options);
  ASSERT_FALSE(r.mean.empty());
  for (size_t i = 0; i < r.mean.size(); ++i)
    ASSERT_NEAR(r.mean[i], expected, 1e-5 * expected) << quad << ", value " << i;
}

const double kRho = 0.5;

TEST(VertexTangents, TheBitangentsSideTurnsTheNormalMap) {
  expect_constant("vertex_tangents_quad_b_plus.ply", "0", "0, -0.5, -0.8660254", kRho / M_PI);
  expect_constant("vertex_tangents_quad_b_minus.ply", "0", "0, -0.5, -0.8660254",
                  kRho / M_PI * 0.5);
}

TEST(VertexTangents, FramesTurnWithTheShapesTransform) {
  expect_constant("vertex_tangents_quad_b_plus.ply", "90", "0.5, 0, -0.8660254", kRho / M_PI);
}

}  // namespace
}  // namespace tr::test
