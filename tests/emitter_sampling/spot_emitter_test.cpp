// The `spot` emitter (core/emitters/spot.h) against closed forms, through the loader. A spot is
// a Dirac delta in position: emitter sampling from a point is deterministic, so instead of a
// density test each case checks what the sample carries.
//  - Total power: with ref points on a sphere of radius R around the light, weight R^2 is the
//    intensity towards them; its integral over the sphere of directions must be Mitsuba's
//    falloff integrated in closed form, 2 pi I (1 - (sin c - sin b) / (c - b)) for cutoff c
//    and beam width b (1 - cos b inside the beam, the linear ramp in theta beyond it).
//  - The profile: full intensity inside the beam, the ramp's value halfway, nothing at or past
//    the cutoff or behind the light, under a rotated and translated to_world.
//  - The texture: the lookup direction's uv, (1/2, 1/2) on the axis and the cutoff circle
//    inscribed in the unit square, read from a bitmap whose texels say where they are.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cpu_backend/bound_scene.h"
#include "delta_emitters.h"

namespace tr {
namespace {

const double kPi = 3.14159265358979323846;

std::string spot(const std::string& params) {
  return "<emitter type=\"spot\"><rgb name=\"intensity\" value=\"2, 3, 4\"/>" + params +
         "<transform name=\"to_world\"><rotate x=\"1\" y=\"2\" z=\"0.5\" angle=\"70\"/>"
         "<translate x=\"0.3\" y=\"-1\" z=\"2\"/></transform></emitter>";
}

// The light's axis and a unit vector perpendicular to it, in world space.
struct Axes {
  glm::dvec3 origin, axis, side;
};
Axes axes_of(const Emitter& e) {
  glm::dmat3 to_local(glm::dvec3(e.to_local[0]), glm::dvec3(e.to_local[1]),
                      glm::dvec3(e.to_local[2]));  // columns = rows of to_local
  glm::dmat3 to_world = glm::inverse(glm::transpose(to_local));
  return {glm::dvec3(e.position), glm::normalize(to_world * glm::dvec3(0, 0, 1)),
          glm::normalize(to_world * glm::dvec3(1, 0, 0))};
}

// Intensity (weight times distance squared) towards the direction at angle theta from the
// axis, azimuth phi, seen from distance r.
glm::dvec3 intensity(const Axes& a, double theta, double phi, double r) {
  glm::dvec3 third = glm::cross(a.axis, a.side);
  glm::dvec3 d =
      std::cos(theta) * a.axis + std::sin(theta) * (std::cos(phi) * a.side + std::sin(phi) * third);
  EmitterSample s = sample_towards(vec3(a.origin + r * d));
  return s.pdf > 0.0f ? glm::dvec3(s.weight) * r * r : glm::dvec3(0.0);
}

double falloff_power(double cutoff_deg, double beam_deg) {
  double c = cutoff_deg * kPi / 180.0, b = beam_deg * kPi / 180.0;
  return 2.0 * kPi * (1.0 - (std::sin(c) - std::sin(b)) / (c - b));
}

TEST(SpotEmitter, TotalPowerIsTheClosedFormOfTheFalloff) {
  for (auto [cutoff, beam] : {std::pair{20.0, 15.0}, {35.0, 5.0}, {60.0, 59.0}, {89.0, 10.0}}) {
    Scene scene = load_emitter_scene(
        "power", spot("<float name=\"cutoff_angle\" value=\"" + std::to_string(cutoff) +
                      "\"/><float name=\"beam_width\" "
                      "value=\"" +
                      std::to_string(beam) + "\"/>"));
    ScopedSceneBinding bound(scene.buffers);
    Axes a = axes_of(scene.buffers.emitters[0]);
    // Midpoint rule in theta (the profile's kinks at b and c fall on cell edges' neighbours,
    // so 20000 cells bound the error far below the tolerance) and 8 azimuths.
    const int n_theta = 20000, n_phi = 8;
    glm::dvec3 power(0.0);
    for (int i = 0; i < n_theta; ++i) {
      double theta = kPi * (i + 0.5) / n_theta;
      for (int j = 0; j < n_phi; ++j)
        power += intensity(a, theta, 2.0 * kPi * (j + 0.5) / n_phi, 1.7) * std::sin(theta) *
                 (kPi / n_theta) * (2.0 * kPi / n_phi);
    }
    double expected = falloff_power(cutoff, beam);
    EXPECT_NEAR(power.x / 2.0, expected, 2e-4 * expected) << cutoff << " " << beam;
    EXPECT_NEAR(power.z / 4.0, expected, 2e-4 * expected) << cutoff << " " << beam;
  }
}

TEST(SpotEmitter, ProfileInsideTheBeamOnTheRampAndPastTheCutoff) {
  Scene scene = load_emitter_scene("profile", spot("<float name=\"cutoff_angle\" value=\"30\"/>"
                                                   "<float name=\"beam_width\" value=\"10\"/>"));
  ScopedSceneBinding bound(scene.buffers);
  Axes a = axes_of(scene.buffers.emitters[0]);
  const double deg = kPi / 180.0;
  for (double phi : {0.0, 1.0, 2.5, 4.0}) {
    EXPECT_NEAR(intensity(a, 0.0, phi, 3.0).y, 3.0, 1e-5);
    EXPECT_NEAR(intensity(a, 9.9 * deg, phi, 3.0).y, 3.0, 1e-5);
    EXPECT_NEAR(intensity(a, 20.0 * deg, phi, 3.0).y, 1.5, 1e-4);  // halfway down the ramp
    EXPECT_NEAR(intensity(a, 25.0 * deg, phi, 0.01).y, 0.75, 1e-4);
    EXPECT_EQ(intensity(a, 30.01 * deg, phi, 3.0).y, 0.0);
    EXPECT_EQ(intensity(a, 120.0 * deg, phi, 3.0).y, 0.0);
    EXPECT_EQ(intensity(a, kPi, phi, 3.0).y, 0.0);  // behind the light
  }
}

TEST(SpotEmitter, BeamWidthDefaultsToThreeQuartersOfTheCutoff) {
  Scene absent = load_emitter_scene("default", spot("<float name=\"cutoff_angle\" value=\"40\"/>"));
  Scene given = load_emitter_scene("given", spot("<float name=\"cutoff_angle\" value=\"40\"/>"
                                                 "<float name=\"beam_width\" value=\"30\"/>"));
  const Emitter &x = absent.buffers.emitters[0], &y = given.buffers.emitters[0];
  EXPECT_EQ(x.cone.x, y.cone.x);
  EXPECT_EQ(x.cone.y, y.cone.y);
  EXPECT_EQ(x.cone.w, y.cone.w);
  Scene defaults = load_emitter_scene("defaults", spot(""));
  EXPECT_FLOAT_EQ(defaults.buffers.emitters[0].cone.z, float(20.0 * kPi / 180.0));
  EXPECT_FLOAT_EQ(defaults.buffers.emitters[0].cone.y, float(std::cos(15.0 * kPi / 180.0)));
}

// A 3x3 float EXR whose texel (i, j) holds (i, j, 1): the intensity says which texel the
// direction read (nearest filtering; row 0 at the top, as in Mitsuba's bitmaps).
TEST(SpotEmitter, TextureCoordinatesInscribeTheCutoffCircleInTheUnitSquare) {
  std::string image = write_texel_positions("spot_texels", 3, 3);
  Scene scene = load_emitter_scene(
      "texture",
      "<emitter type=\"spot\"><float name=\"cutoff_angle\" value=\"40\"/><float "
      "name=\"beam_width\" value=\"40\"/>"
      "<texture name=\"texture\" type=\"bitmap\"><string name=\"filename\" value=\"" +
          image + "\"/><string name=\"filter_type\" value=\"nearest\"/></texture></emitter>");
  ScopedSceneBinding bound(scene.buffers);
  const double t = std::tan(40.0 * kPi / 180.0);
  // Local directions (x, y, 1): uv = 1/2 + 1/2 (x, y) / tan(cutoff). On the axis the centre
  // texel; at 0.8 tan(cutoff) along +x, u = 0.9 (column 2); along -y, v = 0.1 (row 0). The
  // beam is as wide as the cone, so the falloff is 1 wherever it is read.
  struct Probe {
    double x, y;
    glm::dvec2 texel;
  };
  for (Probe p : {Probe{0.0, 0.0, {1, 1}}, Probe{0.8 * t, 0.0, {2, 1}},
                  Probe{0.0, -0.8 * t, {1, 0}}, Probe{-0.5 * t, 0.5 * t, {0, 2}}}) {
    glm::dvec3 d = glm::normalize(glm::dvec3(p.x, p.y, 1.0));
    EmitterSample s = sample_towards(vec3(2.0 * d));
    ASSERT_GT(s.pdf, 0.0f);
    glm::dvec3 i = glm::dvec3(s.weight) * 4.0;  // intensity times texel over distance^2 = 4
    EXPECT_NEAR(i.x, p.texel.x, 1e-5) << p.x << " " << p.y;
    EXPECT_NEAR(i.y, p.texel.y, 1e-5) << p.x << " " << p.y;
  }
}

// Mitsuba 3.8 refuses a `texture` that is not spatially varying and an `intensity` that is.
TEST(SpotEmitter, RefusesAConstantTextureAndATexturedIntensity) {
  auto error_of = [](const std::string& body) {
    try {
      load_emitter_scene("refused", body);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("<emitter type=\"spot\"><rgb name=\"texture\" value=\"0.5\"/></emitter>")
                .find("'texture' must be spatially varying"),
            std::string::npos);
  EXPECT_NE(error_of("<emitter type=\"spot\"><texture name=\"intensity\" type=\"checkerboard\"/>"
                     "</emitter>")
                .find("a textured 'intensity' is not supported"),
            std::string::npos);
}

}  // namespace
}  // namespace tr
