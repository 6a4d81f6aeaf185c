// The `projector` emitter (core/emitters/projector.h) against closed forms, through the loader.
// A projector is a Dirac delta in position, so, as for the spot, each case checks what the
// deterministic sample carries, at points given in the projector's own frame (Mitsuba's
// look-at: z towards the target, x = up x z, y = z x x):
//  - Mitsuba's normalization: irradiance pi scale / (z^2 cos theta), theta from the axis.
//  - The frustum: lit for |x / z| <= tan(fov_x / 2) and |y / z| <= tan(fov_x / 2) / aspect,
//    dark just outside and behind.
//  - The texture: with a bitmap of aspect 2 and the fov given along y, the point aimed at the
//    centre of texel (i, j) reads texel (i, j); +x of the frame is the image's left, as in
//    Mitsuba's perspective projection.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cpu_backend/bound_scene.h"
#include "delta_emitters.h"

namespace tr {
namespace {

const double kPi = 3.14159265358979323846;

struct Frame3 {
  glm::dvec3 origin, x, y, z;
  glm::dvec3 world(glm::dvec3 local) const {
    return origin + local.x * x + local.y * y + local.z * z;
  }
};

const Frame3 kFrame = [] {
  glm::dvec3 origin(0.5, -1.0, 2.0), target(1.0, 0.5, -0.5), up(0.0, 0.0, 1.0);
  glm::dvec3 z = glm::normalize(target - origin);
  glm::dvec3 x = glm::normalize(glm::cross(up, z));
  return Frame3{origin, x, glm::cross(z, x), z};
}();

const char* kLookat =
    "<transform name=\"to_world\"><lookat origin=\"0.5, -1, 2\" target=\"1, 0.5, -0.5\" "
    "up=\"0, 0, 1\"/></transform>";

// Weight times z^2 cos(theta) / (pi scale): the irradiance the projector was given.
glm::dvec3 given_irradiance(glm::dvec3 local, double scale) {
  EmitterSample s = sample_towards(vec3(kFrame.world(local)));
  if (!(s.pdf > 0.0f)) return glm::dvec3(0.0);
  double cos_theta = local.z / glm::length(local);
  return glm::dvec3(s.weight) * local.z * local.z * cos_theta / (kPi * scale);
}

TEST(ProjectorEmitter, MitsubasNormalizationOnAndOffTheAxis) {
  Scene scene = load_emitter_scene(
      "projector_norm", std::string("<emitter type=\"projector\"><rgb name=\"irradiance\" "
                                    "value=\"2, 3, 4\"/><float name=\"scale\" value=\"1.5\"/>"
                                    "<float name=\"fov\" value=\"50\"/>") +
                            kLookat + "</emitter>");
  ScopedSceneBinding bound(scene.buffers);
  const double t = std::tan(25.0 * kPi / 180.0);
  for (glm::dvec3 p : {glm::dvec3(0, 0, 0.5), glm::dvec3(0, 0, 3), glm::dvec3(0.9 * t, 0, 1),
                       glm::dvec3(-0.5 * t, 0.7 * t, 2), glm::dvec3(0.198 * t, -0.198 * t, 0.2)}) {
    glm::dvec3 e = given_irradiance(p, 1.5);
    EXPECT_NEAR(e.x, 2.0, 1e-5) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(e.z, 4.0, 1e-5) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(ProjectorEmitter, LightsItsFrustumOnly) {
  Scene scene = load_emitter_scene(
      "projector_frustum",
      std::string("<emitter type=\"projector\"><float name=\"fov\" value=\"70\"/>") + kLookat +
          "</emitter>");
  ScopedSceneBinding bound(scene.buffers);
  const double t = std::tan(35.0 * kPi / 180.0);  // a constant irradiance has aspect 1
  for (double z : {0.3, 4.0}) {
    EXPECT_GT(given_irradiance({0.999 * t * z, 0, z}, 1.0).x, 0.5);
    EXPECT_GT(given_irradiance({0, -0.999 * t * z, z}, 1.0).x, 0.5);
    EXPECT_EQ(given_irradiance({1.001 * t * z, 0, z}, 1.0).x, 0.0);
    EXPECT_EQ(given_irradiance({0, 1.001 * t * z, z}, 1.0).x, 0.0);
    EXPECT_EQ(given_irradiance({0, 0, -z}, 1.0).x, 0.0);
  }
}

TEST(ProjectorEmitter, TexelsLandWhereTheProjectionPutsThem) {
  std::string image = write_texel_positions("projector_texels", 4, 2);
  Scene scene = load_emitter_scene(
      "projector_texture",
      "<emitter type=\"projector\"><texture name=\"irradiance\" type=\"bitmap\"><string "
      "name=\"filename\" value=\"" +
          image +
          "\"/><string name=\"filter_type\" value=\"nearest\"/></texture>"
          "<float name=\"fov\" value=\"30\"/><string name=\"fov_axis\" value=\"y\"/>" +
          kLookat + "</emitter>");
  ScopedSceneBinding bound(scene.buffers);
  // fov 30 along y with aspect 2: tan(fov_y / 2) = tan(15 deg), tan(fov_x / 2) twice that.
  const double ty = std::tan(15.0 * kPi / 180.0), tx = 2.0 * ty;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      double u = (i + 0.5) / 4.0, v = (j + 0.5) / 2.0;
      // u = 1/2 - x / (2 z tx), v = 1/2 - y / (2 z ty), at z = 2.
      glm::dvec3 p((0.5 - u) * 2.0 * tx * 2.0, (0.5 - v) * 2.0 * ty * 2.0, 2.0);
      glm::dvec3 e = given_irradiance(p, 1.0);
      EXPECT_NEAR(e.x, double(i), 1e-5) << i << " " << j;
      EXPECT_NEAR(e.y, double(j), 1e-5) << i << " " << j;
      EXPECT_NEAR(e.z, 1.0, 1e-5) << i << " " << j;
    }
}

}  // namespace
}  // namespace tr
