// The sensor, film and reconstruction filter parameters of scenes/build_sensor.cpp: every
// parameter Mitsuba 3.8 reads is accepted with Mitsuba's default and meaning, and bad values are
// one-line file:line errors on the offending line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/camera.h"
#include "core/rfilter.h"
#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

Camera load_camera(const std::string& sensor) {
  std::string xml = "<scene version=\"3.0.0\">\n" + sensor + "\n</scene>\n";
  return load_scene(write_file(fresh_dir(), "scene.xml", xml), {}).buffers.globals.camera;
}

std::string film(int w, int h, const std::string& inside = "") {
  return "<film type=\"hdrfilm\"><integer name=\"width\" value=\"" + std::to_string(w) +
         "\"/><integer name=\"height\" value=\"" + std::to_string(h) + "\"/>" + inside + "</film>";
}

// The error of a scene holding `sensor`; it must name the line of the first `marker`.
void expect_sensor_error(const std::string& sensor, const std::string& marker,
                         const std::string& words) {
  std::string xml = "<scene version=\"3.0.0\">\n" + sensor + "\n</scene>\n";
  std::string path = write_file(fresh_dir(), "scene.xml", xml);
  int line = 1 + int(std::count(xml.begin(), xml.begin() + xml.find(marker), '\n'));
  try {
    load_scene(path, {});
    ADD_FAILURE() << "no SceneError for:\n" << xml;
  } catch (const SceneError& e) {
    std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path + ":" + std::to_string(line) + ": ", 0), 0u)
        << "expected line " << line << " in: " << message;
    EXPECT_NE(message.find(words), std::string::npos)
        << "expected \"" << words << "\" in: " << message;
  }
}

double degrees(double radians) { return radians * 180.0 / M_PI; }

// Angle between the rays through two film positions.
double angle_between(const Camera& c, vec2 a, vec2 b) {
  vec3 da = camera_ray(c, a, vec2(0.5f)).d, db = camera_ray(c, b, vec2(0.5f)).d;
  return degrees(std::acos(std::clamp(double(dot(da, db)), -1.0, 1.0)));
}

// parse_fov (src/render/sensor.cpp): the field of view applies to the film's x or y extent, its
// diagonal, or its smaller or larger side; checked on the rays through the film's edges.
TEST(Sensor, FieldOfViewAxesShapeTheRays) {
  auto camera = [](const std::string& axis, int w, int h) {
    return load_camera(
        "<sensor type=\"perspective\"><float name=\"fov\" value=\"50\"/>"
        "<string name=\"fov_axis\" value=\"" +
        axis + "\"/>" + film(w, h) + "</sensor>");
  };
  auto across_x = [](const Camera& c) {
    return angle_between(c, vec2(0.0f, c.film_size.y / 2), vec2(c.film_size.x, c.film_size.y / 2));
  };
  auto across_y = [](const Camera& c) {
    return angle_between(c, vec2(c.film_size.x / 2, 0.0f), vec2(c.film_size.x / 2, c.film_size.y));
  };
  auto across_diagonal = [](const Camera& c) { return angle_between(c, vec2(0.0f), c.film_size); };
  EXPECT_NEAR(across_x(camera("x", 80, 40)), 50.0, 1e-4);
  EXPECT_NEAR(across_y(camera("y", 80, 40)), 50.0, 1e-4);
  EXPECT_NEAR(across_diagonal(camera("diagonal", 80, 40)), 50.0, 1e-4);
  EXPECT_NEAR(across_y(camera("smaller", 80, 40)), 50.0, 1e-4);
  EXPECT_NEAR(across_x(camera("smaller", 40, 80)), 50.0, 1e-4);
  EXPECT_NEAR(across_x(camera("larger", 80, 40)), 50.0, 1e-4);
  EXPECT_NEAR(across_y(camera("larger", 40, 80)), 50.0, 1e-4);
  EXPECT_NEAR(across_x(camera("X", 80, 40)), 50.0, 1e-4);  // Mitsuba lower-cases it
  // Default: x.
  Camera c = load_camera("<sensor type=\"perspective\"><float name=\"fov\" value=\"50\"/>" +
                         film(80, 40) + "</sensor>");
  EXPECT_NEAR(across_x(c), 50.0, 1e-4);
}

// A focal length in 35 mm film equivalents sets the diagonal field of view,
// 2 atan(sqrt(36^2 + 24^2) / (2 f)); the default is 50mm.
TEST(Sensor, FocalLengthSetsTheDiagonalFieldOfView) {
  Camera c = load_camera(
      "<sensor type=\"thinlens\"><string name=\"focal_length\" value=\"28mm\"/>"
      "<float name=\"aperture_radius\" value=\"0.1\"/>" +
      film(60, 50) + "</sensor>");
  const double diagonal = std::sqrt(36.0 * 36.0 + 24.0 * 24.0);
  EXPECT_NEAR(angle_between(c, vec2(0.0f), c.film_size), degrees(2.0 * std::atan(diagonal / 56.0)),
              1e-4);
  c = load_camera("<sensor type=\"perspective\"><string name=\"focal_length\" value=\"35\"/>" +
                  film(60, 50) + "</sensor>");
  EXPECT_NEAR(std::hypot(c.half_extent.x, c.half_extent.y), diagonal / 70.0, 1e-6);
  c = load_camera("<sensor type=\"perspective\">" + film(60, 50) + "</sensor>");
  EXPECT_NEAR(std::hypot(c.half_extent.x, c.half_extent.y), diagonal / 100.0, 1e-6);
}

// ProjectiveCamera: near_clip 1e-2, far_clip 1e4, focus_distance defaulting to far_clip and read
// by every projective camera (perspective ignores it). Perspective's principal point offset.
TEST(Sensor, PerspectiveParameters) {
  Camera c = load_camera(
      "<sensor type=\"perspective\"><float name=\"fov\" value=\"60\"/>"
      "<float name=\"near_clip\" value=\"0.5\"/><float name=\"far_clip\" value=\"20\"/>"
      "<float name=\"focus_distance\" value=\"3\"/>"
      "<float name=\"principal_point_offset_x\" value=\"0.1\"/>"
      "<float name=\"principal_point_offset_y\" value=\"-0.2\"/>" +
      film(32, 32) + "</sensor>");
  EXPECT_EQ(c.type, SENSOR_PERSPECTIVE);
  EXPECT_FLOAT_EQ(c.near_clip, 0.5f);
  EXPECT_FLOAT_EQ(c.far_clip, 20.0f);
  EXPECT_EQ(c.principal_point, vec2(0.1f, -0.2f));
  EXPECT_EQ(c.aperture_radius, 0.0f);
  c = load_camera("<sensor type=\"perspective\">" + film(32, 32) + "</sensor>");
  EXPECT_FLOAT_EQ(c.near_clip, 1e-2f);
  EXPECT_FLOAT_EQ(c.far_clip, 1e4f);
  EXPECT_EQ(c.principal_point, vec2(0.0f));
}

TEST(Sensor, ThinLensParameters) {
  Camera c = load_camera(
      "<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0.25\"/>"
      "<float name=\"focus_distance\" value=\"7\"/>" +
      film(32, 32) + "</sensor>");
  EXPECT_EQ(c.type, SENSOR_THINLENS);
  EXPECT_FLOAT_EQ(c.aperture_radius, 0.25f);
  EXPECT_FLOAT_EQ(c.focus_distance, 7.0f);
  // A zero aperture becomes dr::Epsilon<float> (thinlens.cpp).
  c = load_camera("<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0\"/>" +
                  film(32, 32) + "</sensor>");
  EXPECT_EQ(c.aperture_radius, 0x1p-24f);
  EXPECT_FLOAT_EQ(c.focus_distance, 1e4f);
}

// orthographic_projection: x in [-1, 1], y in [-1/aspect, 1/aspect], scaled by to_world.
TEST(Sensor, OrthographicExtent) {
  Camera c = load_camera(
      "<sensor type=\"orthographic\"><float name=\"near_clip\" value=\"1\"/>"
      "<float name=\"far_clip\" value=\"9\"/><transform name=\"to_world\">"
      "<scale x=\"2\" y=\"2\"/><translate z=\"-5\"/></transform>" +
      film(40, 20) + "</sensor>");
  EXPECT_EQ(c.type, SENSOR_ORTHOGRAPHIC);
  EXPECT_EQ(c.half_extent, vec2(1.0f, 0.5f));
  Ray r = camera_ray(c, vec2(0.0f), vec2(0.5f));
  EXPECT_NEAR(r.o.x, 2.0f, 1e-6f);
  EXPECT_NEAR(r.o.y, 1.0f, 1e-6f);
  EXPECT_NEAR(r.o.z, -4.0f, 1e-6f);
  EXPECT_NEAR(r.tmax, 8.0f, 1e-6f);
  r = camera_ray(c, vec2(40.0f, 20.0f), vec2(0.5f));
  EXPECT_NEAR(r.o.x, -2.0f, 1e-6f);
  EXPECT_NEAR(r.o.y, -1.0f, 1e-6f);
}

// src/render/film.cpp: a crop window renders a sub-rectangle of the film; the projection stays
// that of the full film.
TEST(Sensor, CropWindow) {
  Camera c = load_camera(
      "<sensor type=\"perspective\"><float name=\"fov\" value=\"60\"/>" +
      film(100, 50,
           "<integer name=\"crop_offset_x\" value=\"10\"/><integer name=\"crop_offset_y\" "
           "value=\"5\"/><integer name=\"crop_width\" value=\"30\"/><integer "
           "name=\"crop_height\" value=\"20\"/>") +
      "</sensor>");
  EXPECT_EQ(c.width, 30u);
  EXPECT_EQ(c.height, 20u);
  EXPECT_EQ(c.film_size, vec2(100.0f, 50.0f));
  EXPECT_EQ(c.crop_offset, vec2(10.0f, 5.0f));
  EXPECT_EQ(c.sample_min, vec2(10.0f, 5.0f));
  EXPECT_EQ(c.sample_max, vec2(40.0f, 25.0f));
  EXPECT_NEAR(c.half_extent.x, std::tan(M_PI / 6), 1e-6);
  EXPECT_NEAR(c.half_extent.y, std::tan(M_PI / 6) / 2, 1e-6);
}

// Each filter with Mitsuba's radius and its parameters in the table; sample_border widens the
// sampled rectangle by border_size = ceil(radius - 0.5 - 2 RayEpsilon).
TEST(Sensor, ReconstructionFilters) {
  auto camera = [](const std::string& rfilter, const std::string& more = "") {
    return load_camera("<sensor type=\"perspective\">" + film(20, 10, rfilter + more) +
                       "</sensor>");
  };
  Camera c = camera("<rfilter type=\"tent\"><float name=\"radius\" value=\"1.6\"/></rfilter>",
                    "<boolean name=\"sample_border\" value=\"true\"/>");
  EXPECT_EQ(c.rfilter, RFILTER_TENT);
  EXPECT_FLOAT_EQ(c.filter_radius, 1.6f);
  EXPECT_FLOAT_EQ(c.filter_table[0][1], 1.0f - 1.0f / 31.0f);
  EXPECT_EQ(c.sample_min, vec2(-2.0f));
  EXPECT_EQ(c.sample_max, vec2(22.0f, 12.0f));
  c = camera("<rfilter type=\"tent\"/>", "<boolean name=\"sample_border\" value=\"true\"/>");
  EXPECT_FLOAT_EQ(c.filter_radius, 1.0f);
  EXPECT_EQ(c.sample_min, vec2(-1.0f));
  c = camera(
      "<rfilter type=\"mitchell\"><float name=\"B\" value=\"0.2\"/>"
      "<float name=\"C\" value=\"0.45\"/></rfilter>");
  EXPECT_EQ(c.rfilter, RFILTER_MITCHELL);
  EXPECT_FLOAT_EQ(c.filter_radius, 2.0f);
  EXPECT_FLOAT_EQ(c.filter_table[0][0], (6.0f - 2.0f * 0.2f) / 6.0f);
  EXPECT_EQ(c.sample_min, vec2(0.0f));
  c = camera("<rfilter type=\"mitchell\"/>");
  EXPECT_FLOAT_EQ(c.filter_table[0][0], (6.0f - 2.0f / 3.0f) / 6.0f);
  c = camera("<rfilter type=\"catmullrom\"/>");
  EXPECT_EQ(c.rfilter, RFILTER_CATMULLROM);
  EXPECT_FLOAT_EQ(c.filter_radius, 2.0f);
  EXPECT_FLOAT_EQ(c.filter_table[0][0], 1.0f);
  c = camera("<rfilter type=\"lanczos\"><integer name=\"lobes\" value=\"2\"/></rfilter>",
             "<boolean name=\"sample_border\" value=\"true\"/>");
  EXPECT_EQ(c.rfilter, RFILTER_LANCZOS);
  EXPECT_FLOAT_EQ(c.filter_radius, 2.0f);
  EXPECT_EQ(c.sample_min, vec2(-2.0f));
  EXPECT_FLOAT_EQ(camera("<rfilter type=\"lanczos\"/>").filter_radius, 3.0f);
  c = camera("<rfilter type=\"gaussian\"><float name=\"stddev\" value=\"0.3\"/></rfilter>");
  EXPECT_EQ(c.rfilter, RFILTER_GAUSSIAN);
  EXPECT_FLOAT_EQ(c.filter_radius, 1.2f);
  // The cumulative table ends at the filter's full |mass| over both sides.
  float mass = 0.0f;
  for (uint i = 0; i < FILTER_RESOLUTION; ++i)
    mass += 2.0f * std::abs(c.filter_table[i / 4][i % 4]) * 1.2f / 31.0f;
  EXPECT_NEAR(c.filter_cdf[15][2], mass, 1e-5f);
  // Mitsuba takes any filter of radius 0.5 for the box (rfilter.cpp is_box_filter).
  EXPECT_EQ(
      camera("<rfilter type=\"tent\"><float name=\"radius\" value=\"0.5\"/></rfilter>").rfilter,
      RFILTER_BOX);
  c = camera("<rfilter type=\"box\"/>", "<boolean name=\"sample_border\" value=\"true\"/>");
  EXPECT_EQ(c.rfilter, RFILTER_BOX);
  EXPECT_EQ(c.sample_min, vec2(0.0f));
}

TEST(Sensor, BadParametersNameTheirLine) {
  const std::string f = film(8, 8);
  expect_sensor_error(
      "<sensor type=\"perspective\">\n<transform name=\"to_world\"><scale "
      "value=\"2\"/></transform>" +
          f + "</sensor>",
      "<transform", "scale factors in the camera-to-world transform");
  expect_sensor_error(
      "<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"1\"/>\n"
      "<transform name=\"to_world\"><scale x=\"1\" y=\"3\"/></transform>" +
          f + "</sensor>",
      "<transform", "scale factors");
  expect_sensor_error(
      "<sensor type=\"perspective\">\n<string name=\"fov_axis\" value=\"z\"/>"
      "<float name=\"fov\" value=\"40\"/>" +
          f + "</sensor>",
      "fov_axis", "fov_axis \"z\" must be x, y, diagonal, smaller or larger");
  expect_sensor_error(
      "<sensor type=\"perspective\"><float name=\"fov\" value=\"40\"/>\n"
      "<string name=\"focal_length\" value=\"35mm\"/>" +
          f + "</sensor>",
      "fov\"", "give either 'fov' or 'focal_length'");
  expect_sensor_error(
      "<sensor type=\"perspective\">\n<string name=\"focal_length\" "
      "value=\"wide\"/>" +
          f + "</sensor>",
      "focal_length", "focal_length");
  expect_sensor_error(
      "<sensor type=\"perspective\">\n<string name=\"fov_axis\" value=\"y\"/>" + f + "</sensor>",
      "fov_axis", "unused parameter 'fov_axis'");
  expect_sensor_error(
      "<sensor type=\"perspective\">\n<float name=\"near_clip\" value=\"0\"/>" + f + "</sensor>",
      "near_clip", "near_clip must be positive");
  expect_sensor_error(
      "<sensor type=\"perspective\"><float name=\"near_clip\" value=\"2\"/>\n"
      "<float name=\"far_clip\" value=\"1\"/>" +
          f + "</sensor>",
      "far_clip", "far_clip must be finite and exceed near_clip");
  expect_sensor_error("<sensor type=\"thinlens\">" + f + "\n</sensor>", "thinlens",
                      "aperture_radius");
  expect_sensor_error(
      "<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"1\"/>\n"
      "<float name=\"focus_distance\" value=\"-1\"/>" +
          f + "</sensor>",
      "focus_distance", "focus_distance must be positive");
  expect_sensor_error(
      "<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"1\"/>\n"
      "<float name=\"principal_point_offset_x\" value=\"0.1\"/>" +
          f + "</sensor>",
      "principal_point", "unused parameter 'principal_point_offset_x'");
  expect_sensor_error(
      "<sensor type=\"orthographic\">\n<float name=\"fov\" value=\"40\"/>" + f + "</sensor>", "fov",
      "unused parameter 'fov'");
  expect_sensor_error(
      "<sensor type=\"perspective\"><float name=\"shutter_open\" value=\"1\"/>\n"
      "<float name=\"shutter_close\" value=\"0.5\"/>" +
          f + "</sensor>",
      "shutter_close", "shutter_close must not be earlier");
  expect_sensor_error("<sensor type=\"fisheye\">\n" + f + "</sensor>", "fisheye",
                      "not supported by twinray: fisheye (Mitsuba 3 has no such plugin)");
}

// Nothing in a Mitsuba 3 scene moves, so an open shutter renders what a closed one does.
TEST(Sensor, ShutterIntervalChangesNothing) {
  auto camera_of = [](const std::string& shutter) {
    std::string xml =
        "<scene version=\"3.0.0\"><sensor type=\"perspective\">" + shutter +
        "<film type=\"hdrfilm\"><integer name=\"width\" value=\"8\"/><integer name=\"height\" "
        "value=\"8\"/></film></sensor></scene>";
    return load_scene(testing_files::write_file(testing_files::fresh_dir(), "scene.xml", xml), {})
        .buffers.globals.camera;
  };
  Camera closed = camera_of("");
  Camera open = camera_of(
      "<float name=\"shutter_open\" value=\"0.25\"/><float name=\"shutter_close\" value=\"1\"/>");
  EXPECT_EQ(std::memcmp(&closed, &open, sizeof(Camera)), 0);
}

TEST(Sensor, BadFilmAndFilterNameTheirLine) {
  auto sensor = [](const std::string& inside) {
    return "<sensor type=\"perspective\"><film type=\"hdrfilm\"><integer name=\"width\" "
           "value=\"8\"/><integer name=\"height\" value=\"8\"/>\n" +
           inside + "</film></sensor>";
  };
  expect_sensor_error(sensor("<integer name=\"crop_offset_x\" value=\"4\"/><integer "
                             "name=\"crop_width\" value=\"5\"/>"),
                      "<film", "must be non-empty and inside the 8 x 8 film");
  expect_sensor_error(sensor("<integer name=\"crop_height\" value=\"0\"/>"), "<film",
                      "crop window");
  expect_sensor_error(sensor("<rfilter type=\"lanczos\">\n<integer name=\"lobes\" "
                             "value=\"0\"/></rfilter>"),
                      "lobes", "lobes must be in [1, 64]");
  expect_sensor_error(sensor("<rfilter type=\"tent\">\n<float name=\"radius\" "
                             "value=\"-1\"/></rfilter>"),
                      "radius", "radius must be positive");
  expect_sensor_error(sensor("<rfilter type=\"gaussian\">\n<float name=\"stddev\" "
                             "value=\"0\"/></rfilter>"),
                      "stddev", "stddev must be positive");
  expect_sensor_error(sensor("<rfilter type=\"mitchell\">\n<float name=\"A\" "
                             "value=\"0.3\"/></rfilter>"),
                      "\"A\"", "unused parameter 'A'");
  expect_sensor_error(sensor("<rfilter type=\"catmullrom\">\n<float name=\"B\" "
                             "value=\"0.3\"/></rfilter>"),
                      "\"B\"", "unused parameter 'B'");
  expect_sensor_error(sensor("<rfilter type=\"bicubic\"/>"), "bicubic",
                      "not supported by twinray: bicubic (Mitsuba 3 has no such plugin)");
  expect_sensor_error(sensor("<boolean name=\"compensate\" value=\"true\"/>"), "compensate",
                      "compensate is not supported");
}

}  // namespace
}  // namespace tr
