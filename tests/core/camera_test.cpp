// Primary rays of core/camera.h against Mitsuba's projections (src/sensors/*.cpp,
// include/mitsuba/render/sensor.h), worked out by hand for simple cameras.
#include "core/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tr {
namespace {

Camera camera(uint type, vec2 film, vec2 half_extent) {
  Camera c{};
  c.to_world[0] = vec4(1, 0, 0, 0);
  c.to_world[1] = vec4(0, 1, 0, 0);
  c.to_world[2] = vec4(0, 0, 1, 0);
  c.type = type;
  c.film_size = film;
  c.half_extent = half_extent;
  c.near_clip = 0.5f;
  c.far_clip = 100.0f;
  return c;
}

// Film (0, 0) is the top-left corner: camera +x is left, +y up, so it looks along
// (+e_x, +e_y, 1); the film centre looks along +z. The ray spans near to far along z.
TEST(Camera, PerspectiveCornersAndClipPlanes) {
  Camera c = camera(SENSOR_PERSPECTIVE, vec2(40, 20), vec2(0.8f, 0.4f));
  Ray r = camera_ray(c, vec2(0.0f), vec2(0.5f));
  EXPECT_NEAR(r.d.x / r.d.z, 0.8f, 1e-6f);
  EXPECT_NEAR(r.d.y / r.d.z, 0.4f, 1e-6f);
  r = camera_ray(c, vec2(40.0f, 20.0f), vec2(0.5f));
  EXPECT_NEAR(r.d.x / r.d.z, -0.8f, 1e-6f);
  EXPECT_NEAR(r.d.y / r.d.z, -0.4f, 1e-6f);
  r = camera_ray(c, vec2(20.0f, 10.0f), vec2(0.5f));
  EXPECT_NEAR(r.d.z, 1.0f, 1e-7f);
  EXPECT_NEAR(r.o.z, 0.5f, 1e-7f);
  EXPECT_NEAR(r.tmax, 99.5f, 1e-4f);
  r = camera_ray(c, vec2(0.0f), vec2(0.5f));
  EXPECT_NEAR((r.o + r.d * r.tmax).z, 100.0f, 1e-3f);
  EXPECT_NEAR(r.o.z, 0.5f, 1e-6f);
}

// Mitsuba's perspective camera unprojects (film sample + principal_point_offset): with an
// offset of +0.25 along x, the film centre looks where the film point 0.75 would, i.e. at
// camera-space x/z = (1 - 2 * 0.75) tan(fov_x / 2).
TEST(Camera, PrincipalPointOffsetShiftsTheFilmSample) {
  Camera c = camera(SENSOR_PERSPECTIVE, vec2(2, 2), vec2(1.0f));
  c.principal_point = vec2(0.25f, -0.125f);
  Ray r = camera_ray(c, vec2(1.0f, 1.0f), vec2(0.5f));
  EXPECT_NEAR(r.d.x / r.d.z, -0.5f, 1e-6f);
  EXPECT_NEAR(r.d.y / r.d.z, 0.25f, 1e-6f);
}

// orthographic_projection: the film spans x in [-1, 1], y in [-1/aspect, 1/aspect] on the near
// plane, through to_world with its scale; every ray runs along to_world's +z, tmax = far - near.
TEST(Camera, OrthographicExtentThroughAScaledTransform) {
  Camera c = camera(SENSOR_ORTHOGRAPHIC, vec2(40, 20), vec2(1.0f, 0.5f));
  // to_world = translate(1, 2, 3) * scale(3, 3, 2): world = (3x + 1, 3y + 2, 2z + 3).
  c.to_world[0] = vec4(3, 0, 0, 1);
  c.to_world[1] = vec4(0, 3, 0, 2);
  c.to_world[2] = vec4(0, 0, 2, 3);
  Ray r = camera_ray(c, vec2(0.0f), vec2(0.5f));
  EXPECT_NEAR(r.o.x, 3.0f * 1.0f + 1.0f, 1e-6f);
  EXPECT_NEAR(r.o.y, 3.0f * 0.5f + 2.0f, 1e-6f);
  EXPECT_NEAR(r.o.z, 2.0f * 0.5f + 3.0f, 1e-6f);
  EXPECT_NEAR(r.d.z, 1.0f, 1e-7f);
  EXPECT_NEAR(r.tmax, 99.5f, 1e-5f);
  r = camera_ray(c, vec2(30.0f, 15.0f), vec2(0.5f));
  EXPECT_NEAR(r.o.x, 3.0f * -0.5f + 1.0f, 1e-6f);
  EXPECT_NEAR(r.o.y, 3.0f * -0.25f + 2.0f, 1e-6f);
  EXPECT_EQ(r.d, vec3(0.0f, 0.0f, 1.0f));
}

// Every lens sample's ray through one film position crosses the plane of focus where the
// pinhole ray does, and starts on the aperture disk (moved to the near plane).
TEST(Camera, ThinLensRaysMeetOnThePlaneOfFocus) {
  Camera c = camera(SENSOR_THINLENS, vec2(40, 20), vec2(0.8f, 0.4f));
  c.aperture_radius = 0.3f;
  c.focus_distance = 7.0f;
  const vec2 film(9.0f, 13.0f);
  Camera pinhole = c;
  pinhole.type = SENSOR_PERSPECTIVE;
  Ray p = camera_ray(pinhole, film, vec2(0.5f));
  vec3 focus = p.o + p.d * ((7.0f - p.o.z) / p.d.z);
  for (vec2 u : {vec2(0.1f, 0.2f), vec2(0.9f, 0.5f), vec2(0.5f, 0.95f)}) {
    Ray r = camera_ray(c, film, u);
    vec3 at = r.o + r.d * ((7.0f - r.o.z) / r.d.z);
    EXPECT_NEAR(at.x, focus.x, 1e-5f);
    EXPECT_NEAR(at.y, focus.y, 1e-5f);
    vec3 lens = r.o - r.d * (0.5f / r.d.z);  // back to z = 0
    EXPECT_LE(std::hypot(lens.x, lens.y), 0.3f + 1e-6f);
    EXPECT_GT(std::hypot(lens.x, lens.y), 1e-3f);
  }
}

}  // namespace
}  // namespace tr
