// Loader semantics on small scenes: camera, transforms, defaults/overrides/includes, materials,
// emitters and their alias tables, instancing, bounds.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/bsdf/roughplastic.h"
#include "core/material_slots.h"
#include "core/transform.h"
#include "scene_test_files.h"
#include "scenes/scene_digest.h"

namespace tr {
namespace {

using namespace testing_files;

Scene load_text(const std::string& body, const LoadOptions& options = {}) {
  return load_scene(write_file(fresh_dir(), "scene.xml", scene_xml(body)), options);
}

Scene load_sensor(const std::string& sensor) {
  std::string xml = "<scene version=\"3.0.0\">" + sensor + "</scene>";
  return load_scene(write_file(fresh_dir(), "scene.xml", xml), {});
}

glm::dvec3 apply(const vec4 rows[3], glm::dvec3 p) {
  return glm::dvec3(transform_point(rows[0], rows[1], rows[2], vec3(p)));
}

void expect_near(glm::dvec3 a, glm::dvec3 b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(SceneValues, CameraFieldOfView) {
  auto film = [](int w, int h) {
    return "<film type=\"hdrfilm\"><integer name=\"width\" value=\"" + std::to_string(w) +
           "\"/><integer name=\"height\" value=\"" + std::to_string(h) + "\"/></film>";
  };
  Camera c = load_sensor("<sensor type=\"perspective\"><float name=\"fov\" value=\"90\"/>" +
                         film(200, 100) + "</sensor>")
                 .buffers.globals.camera;
  EXPECT_NEAR(c.half_extent.x, 1.0, 1e-6);
  EXPECT_NEAR(c.half_extent.y, 0.5, 1e-6);
  c = load_sensor(
          "<sensor type=\"perspective\"><float name=\"fov\" value=\"90\"/>"
          "<string name=\"fov_axis\" value=\"y\"/>" +
          film(200, 100) + "</sensor>")
          .buffers.globals.camera;
  EXPECT_NEAR(c.half_extent.x, 2.0, 1e-6);
  EXPECT_NEAR(c.half_extent.y, 1.0, 1e-6);
  // "smaller" is y for a landscape film.
  c = load_sensor(
          "<sensor type=\"perspective\"><float name=\"fov\" value=\"90\"/>"
          "<string name=\"fov_axis\" value=\"smaller\"/>" +
          film(200, 100) + "</sensor>")
          .buffers.globals.camera;
  EXPECT_NEAR(c.half_extent.y, 1.0, 1e-6);
  // diagonal: tan(fov/2) is half the diagonal of the unit-distance image plane.
  c = load_sensor(
          "<sensor type=\"perspective\"><float name=\"fov\" value=\"60\"/>"
          "<string name=\"fov_axis\" value=\"diagonal\"/>" +
          film(300, 400) + "</sensor>")
          .buffers.globals.camera;
  EXPECT_NEAR(std::hypot(c.half_extent.x, c.half_extent.y), std::tan(M_PI / 6), 1e-6);
  EXPECT_NEAR(c.half_extent.x / c.half_extent.y, 0.75, 1e-6);
  // Mitsuba's default: a 50 mm lens on 36x24 mm film, measured along the diagonal.
  c = load_sensor("<sensor type=\"perspective\">" + film(48, 48) + "</sensor>")
          .buffers.globals.camera;
  EXPECT_NEAR(c.half_extent.x, std::sqrt(36.0 * 36 + 24 * 24) / 100.0 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(c.rfilter, RFILTER_GAUSSIAN);  // Mitsuba's default reconstruction filter
  EXPECT_NEAR(c.filter_radius, 2.0, 1e-6);
}

TEST(SceneValues, CameraDefaultsAndThinlens) {
  Scene s = load_sensor(
      "<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0.1\"/>"
      "<float name=\"far_clip\" value=\"50\"/>"
      "<sampler type=\"independent\"><integer name=\"sample_count\" value=\"7\"/>"
      "<integer name=\"seed\" value=\"3\"/></sampler></sensor>");
  const Camera& c = s.buffers.globals.camera;
  EXPECT_EQ(c.type, SENSOR_THINLENS);
  EXPECT_EQ(c.width, 768u);  // Mitsuba's default film
  EXPECT_EQ(c.height, 576u);
  EXPECT_FLOAT_EQ(c.aperture_radius, 0.1f);
  EXPECT_FLOAT_EQ(c.focus_distance, 50.0f);  // defaults to far_clip
  EXPECT_FLOAT_EQ(c.near_clip, 0.01f);
  EXPECT_EQ(s.spp, 7u);
  EXPECT_EQ(s.seed, 3u);
  EXPECT_EQ(s.integrator_name, "path");  // Mitsuba's default integrator
  EXPECT_EQ(s.buffers.globals.integrator.max_depth, -1);
  EXPECT_EQ(s.buffers.globals.integrator.rr_depth, 5);
  EXPECT_EQ(s.buffers.globals.integrator.hide_emitters, 0u);
}

TEST(SceneValues, LookAtCamera) {
  Scene s = load_sensor(
      "<sensor type=\"perspective\"><transform name=\"to_world\">"
      "<lookat origin=\"1, 2, 3\" target=\"1, 2, 13\" up=\"0 1 0\"/></transform></sensor>");
  const Camera& c = s.buffers.globals.camera;
  expect_near(apply(c.to_world, glm::dvec3(0.0)), glm::dvec3(1, 2, 3), 1e-6);
  // Camera +z looks at the target, +y is up, +x is left = up x dir.
  expect_near(apply(c.to_world, glm::dvec3(0, 0, 1)), glm::dvec3(1, 2, 4), 1e-6);
  expect_near(apply(c.to_world, glm::dvec3(0, 1, 0)), glm::dvec3(1, 3, 3), 1e-6);
  expect_near(apply(c.to_world, glm::dvec3(1, 0, 0)), glm::dvec3(2, 2, 3), 1e-6);
}

// Mitsuba's <scene> reads embree_use_robust_intersections (a boolean) and marks its kd-tree's
// build parameters read in every build (src/render/scene.cpp).
TEST(SceneValues, SceneAccelerationParameters) {
  EXPECT_TRUE(load_text("").robust_intersections);
  EXPECT_FALSE(load_text("<boolean name=\"embree_use_robust_intersections\" value=\"false\"/>")
                   .robust_intersections);
  EXPECT_TRUE(load_text("<boolean name=\"embree_use_robust_intersections\" value=\"true\"/>")
                  .robust_intersections);
  Scene kd = load_text(
      "<float name=\"kd_intersection_cost\" value=\"20\"/>"
      "<float name=\"kd_traversal_cost\" value=\"15\"/>"
      "<float name=\"kd_empty_space_bonus\" value=\"0.9\"/>"
      "<integer name=\"kd_stop_prims\" value=\"8\"/>"
      "<integer name=\"kd_max_depth\" value=\"0\"/>"
      "<integer name=\"kd_min_max_bins\" value=\"128\"/>"
      "<boolean name=\"kd_clip\" value=\"true\"/>"
      "<integer name=\"kd_retract_bad_splits\" value=\"1\"/>"
      "<integer name=\"kd_exact_primitive_threshold\" value=\"65536\"/>");
  EXPECT_TRUE(kd.robust_intersections);
  // A checkpoint of one traversal mode does not resume in the other (render/checkpoint.h).
  Scene fast = load_text("<boolean name=\"embree_use_robust_intersections\" value=\"false\"/>");
  EXPECT_NE(scene_digest(fast), scene_digest(load_text("")));
  EXPECT_EQ(scene_digest(kd), scene_digest(load_text("")));
}

TEST(SceneValues, TransformsComposeInDocumentOrder) {
  Scene s = load_text(
      "<shape type=\"sphere\"><transform name=\"to_world\">"
      "<scale value=\"2\"/><rotate z=\"1\" angle=\"90\"/><translate x=\"1\"/>"
      "</transform></shape>"
      "<shape type=\"sphere\"><transform name=\"to_world\">"
      "<matrix value=\"1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1\"/></transform></shape>"
      "<shape type=\"sphere\"><point name=\"center\" value=\"1, 1, 1\"/>"
      "<float name=\"radius\" value=\"3\"/></shape>");
  const auto& shapes = s.buffers.shapes;
  ASSERT_EQ(shapes.size(), 3u);
  // scale 2, then rotate 90 degrees about z, then translate by x: (1,0,0) -> (2,0,0) -> (0,2,0)
  // -> (1,2,0).
  expect_near(apply(shapes[0].to_world, glm::dvec3(1, 0, 0)), glm::dvec3(1, 2, 0), 1e-6);
  expect_near(apply(shapes[0].to_object, glm::dvec3(1, 2, 0)), glm::dvec3(1, 0, 0), 1e-6);
  EXPECT_NEAR(shapes[0].area, 4 * M_PI * 4, 1e-4);
  expect_near(apply(shapes[1].to_world, glm::dvec3(0)), glm::dvec3(5, 6, 7), 1e-6);
  expect_near(apply(shapes[2].to_world, glm::dvec3(0, 0, 1)), glm::dvec3(1, 1, 4), 1e-6);
  EXPECT_NEAR(shapes[2].area, 4 * M_PI * 9, 1e-3);
}

TEST(SceneValues, AnalyticShapes) {
  Scene s = load_text(
      "<shape type=\"disk\"><transform name=\"to_world\"><scale x=\"2\" "
      "y=\"3\"/></transform></shape>"
      "<shape type=\"cylinder\"><point name=\"p0\" value=\"1 0 0\"/><point name=\"p1\" value=\"1 0 "
      "4\"/>"
      "<float name=\"radius\" value=\"0.5\"/></shape>");
  const auto& shapes = s.buffers.shapes;
  EXPECT_EQ(shapes[0].type, SHAPE_DISK);
  EXPECT_NEAR(shapes[0].area, M_PI * 6, 1e-4);
  EXPECT_EQ(shapes[1].type, SHAPE_CYLINDER);
  EXPECT_NEAR(shapes[1].area, 2 * M_PI * 0.5 * 4, 1e-4);
  expect_near(apply(shapes[1].to_world, glm::dvec3(0, 0, 1)), glm::dvec3(1, 0, 4), 1e-6);
  expect_near(apply(shapes[1].to_world, glm::dvec3(0, 0, 0)), glm::dvec3(1, 0, 0), 1e-6);
}

// An area emitter keeps copies of its shape's fields for light sampling (core/emitters/area.h):
// they must be its shape's, for meshes placed after others and for analytic shapes.
TEST(SceneValues, AreaEmittersCopyTheirShapesFields) {
  Scene s = load_text(
      "<shape type=\"cube\"/>"
      "<shape type=\"rectangle\"><boolean name=\"flip_normals\" value=\"true\"/>"
      "<transform name=\"to_world\"><scale value=\"3\"/></transform>"
      "<emitter type=\"area\"/></shape>"
      "<shape type=\"cube\"><emitter type=\"area\"/></shape>"
      "<shape type=\"sphere\"><float name=\"radius\" value=\"2\"/><emitter "
      "type=\"area\"/></shape>");
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.emitters.size(), 3u);
  int meshes = 0;
  for (const Emitter& e : b.emitters) {
    const Shape& shape = b.shapes[e.shape];
    EXPECT_EQ(e.shape_type, shape.type);
    EXPECT_EQ(e.shape_flags, shape.flags);
    EXPECT_EQ(e.first_index, shape.first_index);
    EXPECT_EQ(e.first_vertex, shape.first_vertex);
    EXPECT_EQ(e.area, shape.area);
    if (shape.type == SHAPE_MESH && shape.first_index > 0u) ++meshes;
  }
  EXPECT_EQ(meshes, 2);
}

// An emitting mesh of one triangle also carries the triangle's vertices and normals, as the
// buffers hold them, for its light samples (core/emitters/area.h, sample_mesh_area).
TEST(SceneValues, OneTriangleEmittersCarryTheirTriangle) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n");
  write_file(dir, "tri_n.obj",
             "v 0 0 0\nv 1 0 0\nv 0 2 1\nvn 0 0 1\nvn 0 1 1\nvn 1 0 1\nf 1//1 2//2 3//3\n");
  const std::string emitting = "<emitter type=\"area\"/></shape>";
  Scene s = load_scene(
      write_file(dir, "scene.xml",
                 scene_xml("<shape type=\"cube\"/>"
                           "<shape type=\"obj\"><string name=\"filename\" value=\"tri.obj\"/>"
                           "<boolean name=\"face_normals\" value=\"true\"/>"
                           "<transform name=\"to_world\"><translate x=\"3\"/></transform>" +
                           emitting +
                           "<shape type=\"obj\"><string name=\"filename\" value=\"tri_n.obj\"/>"
                           "<transform name=\"to_world\"><rotate y=\"1\" angle=\"30\"/>"
                           "</transform>" +
                           emitting)),
      {});
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.emitters.size(), 2u);
  uint with_normals = 0;
  for (const Emitter& e : b.emitters) {
    ASSERT_EQ(e.alias_count, 1u);
    const bool has_normals = (e.shape_flags & SHAPE_HAS_NORMALS) != 0u;
    with_normals += has_normals ? 1u : 0u;
    for (uint k = 0; k < 3; ++k) {
      const uint v = e.first_vertex + b.indices[e.first_index + k];
      EXPECT_EQ(vec3(e.to_world[k]), vec3(b.positions[v])) << "vertex " << k;
      if (has_normals) {
        EXPECT_EQ(vec3(e.to_local[k]), vec3(b.normals[v])) << "normal " << k;
      }
    }
  }
  EXPECT_EQ(with_normals, 1u);
}

TEST(SceneValues, DefaultsOverridesAndIncludes) {
  std::filesystem::path dir = fresh_dir();
  write_file(
      dir, "parts/materials.xml",
      "<scene version=\"3.0.0\"><default name=\"albedo\" value=\"0.25\"/>"
      "<bsdf type=\"diffuse\" id=\"mat\"><rgb name=\"reflectance\" value=\"$albedo\"/></bsdf>"
      "</scene>");
  write_file(dir, "meshes/quad.obj", QUAD_OBJ);
  std::string path = write_file(
      dir, "scene.xml",
      scene_xml("<default name=\"spp\" value=\"16\"/><default name=\"spp\" value=\"99\"/>"
                "<include filename=\"parts/materials.xml\"/>"
                "<shape type=\"obj\"><string name=\"filename\" value=\"meshes/quad.obj\"/>"
                "<ref id=\"mat\"/></shape>"
                "<integrator type=\"direct\"><integer name=\"emitter_samples\" "
                "value=\"$spp\"/></integrator>"));
  Scene s = load_scene(path, {});
  EXPECT_EQ(s.buffers.globals.integrator.emitter_samples, 16u);  // the first <default> wins
  EXPECT_EQ(s.buffers.globals.integrator.bsdf_samples, 1u);
  EXPECT_EQ(s.integrator_name, "direct");
  ASSERT_EQ(s.buffers.shapes.size(), 1u);
  EXPECT_FLOAT_EQ(
      s.buffers.materials[s.buffers.shapes[0].material].param[DIFFUSE_REFLECTANCE].value.y, 0.25f);
  LoadOptions o;
  o.defines["spp"] = "3";
  o.defines["albedo"] = "0.5";
  s = load_scene(path, o);
  EXPECT_EQ(s.buffers.globals.integrator.emitter_samples, 3u);
  EXPECT_FLOAT_EQ(
      s.buffers.materials[s.buffers.shapes[0].material].param[DIFFUSE_REFLECTANCE].value.x, 0.5f);
}

TEST(SceneValues, SearchPathsFindFiles) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "assets/meshes/quad.obj", QUAD_OBJ);
  std::string body =
      "<shape type=\"obj\"><string name=\"filename\" value=\"meshes/quad.obj\"/></shape>";
  std::string with_path = write_file(
      dir, "a/scene.xml",
      "<scene version=\"3.0.0\"><path value=\"../assets\"/>" + scene_xml(body).substr(23));
  EXPECT_EQ(load_scene(with_path, {}).buffers.shapes.size(), 1u);
  std::string without = write_file(dir, "b/scene.xml", scene_xml(body));
  EXPECT_THROW(load_scene(without, {}), SceneError);
  LoadOptions o;
  o.search_paths.push_back((dir / "assets").string());
  EXPECT_EQ(load_scene(without, o).buffers.shapes.size(), 1u);
}

TEST(SceneValues, ObjMeshesFollowMitsuba) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.obj", QUAD_OBJ);
  write_file(
      dir, "quad_n.obj",
      "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n");
  std::string path = write_file(
      dir, "scene.xml",
      scene_xml("<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>"
                "<transform name=\"to_world\"><scale z=\"-1\"/><rotate x=\"1\" angle=\"90\"/>"
                "<translate y=\"5\"/></transform></shape>"
                "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>"
                "<boolean name=\"face_normals\" value=\"true\"/>"
                "<boolean name=\"flip_normals\" value=\"true\"/></shape>"
                "<shape type=\"obj\"><string name=\"filename\" value=\"quad_n.obj\"/>"
                "<transform name=\"to_world\"><scale z=\"-1\"/><rotate x=\"1\" angle=\"90\"/>"
                "<translate y=\"5\"/></transform></shape>"));
  Scene s = load_scene(path, {});
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.shapes.size(), 3u);
  const Shape& a = b.shapes[0];
  EXPECT_EQ(a.flags, SHAPE_HAS_NORMALS | SHAPE_HAS_UVS);
  EXPECT_EQ(a.triangle_count, 2u);
  EXPECT_NEAR(a.area, 4.0, 1e-5);
  for (uint v = 0; v < a.vertex_count; ++v) {
    glm::vec4 p = b.positions[a.first_vertex + v];
    EXPECT_NEAR(p.y, 5.0, 1e-5);  // pre-transformed to world space
    // The file has no normals: Mitsuba computes them after to_world, from the world-space
    // faces; the z mirror leaves the flat quad as it is and the rotation turns its +z winding
    // normal into -y.
    glm::vec4 n = b.normals[a.first_vertex + v];
    EXPECT_NEAR(n.y, -1.0, 1e-5);
    // Normals given in the file transform by the inverse transpose instead: (0,0,1) -> +y.
    glm::vec4 nf = b.normals[b.shapes[2].first_vertex + v];
    EXPECT_NEAR(nf.y, 1.0, 1e-5);
    // OBJ texture coordinates are flipped vertically (Mitsuba flip_tex_coords default).
    glm::vec2 uv = b.uvs[a.first_vertex + v];
    glm::vec4 po = b.positions[b.shapes[1].first_vertex + v];
    EXPECT_NEAR(uv.x, 0.5 * (po.x + 1), 1e-6);
    EXPECT_NEAR(uv.y, 1.0 - 0.5 * (po.y + 1), 1e-6);
  }
  EXPECT_EQ(b.shapes[1].flags, SHAPE_HAS_UVS | SHAPE_FLIP_NORMALS);
}

TEST(SceneValues, BuiltInMeshes) {
  Scene s = load_text(
      "<shape type=\"rectangle\"><transform name=\"to_world\"><scale "
      "value=\"2\"/></transform></shape>"
      "<shape type=\"cube\"/>");
  const SceneBuffers& b = s.buffers;
  EXPECT_EQ(b.shapes[0].triangle_count, 2u);
  EXPECT_NEAR(b.shapes[0].area, 16.0, 1e-5);
  for (uint v = 0; v < 4; ++v) {
    glm::vec4 p = b.positions[v];
    EXPECT_NEAR(b.uvs[v].x, 0.5 * (p.x / 2 + 1), 1e-6);
    EXPECT_NEAR(b.uvs[v].y, 0.5 * (p.y / 2 + 1), 1e-6);
    EXPECT_NEAR(b.normals[v].z, 1.0, 1e-6);
  }
  EXPECT_EQ(b.shapes[1].triangle_count, 12u);
  EXPECT_EQ(b.shapes[1].vertex_count, 24u);
  EXPECT_NEAR(b.shapes[1].area, 24.0, 1e-5);
  // Every cube triangle's winding agrees with its vertex normals (outward faces).
  const Shape& cube = b.shapes[1];
  for (uint t = 0; t < cube.triangle_count; ++t) {
    uint i0 = cube.first_vertex + b.indices[cube.first_index + 3 * t];
    uint i1 = cube.first_vertex + b.indices[cube.first_index + 3 * t + 1];
    uint i2 = cube.first_vertex + b.indices[cube.first_index + 3 * t + 2];
    glm::vec3 ng = glm::cross(glm::vec3(b.positions[i1] - b.positions[i0]),
                              glm::vec3(b.positions[i2] - b.positions[i0]));
    EXPECT_GT(glm::dot(ng, glm::vec3(b.normals[i0])), 0.0f) << "triangle " << t;
  }
}

TEST(SceneValues, MaterialsAndDefaults) {
  Scene s = load_text(
      "<shape type=\"sphere\"/>"
      "<shape type=\"sphere\"><bsdf type=\"dielectric\"><string name=\"int_ior\" value=\"water\"/>"
      "</bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"roughconductor\"><string name=\"material\" "
      "value=\"Au\"/>"
      "<string name=\"distribution\" value=\"ggx\"/><float name=\"alpha_u\" value=\"0.1\"/>"
      "<float name=\"alpha_v\" value=\"0.3\"/></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"roughplastic\"><float name=\"int_ior\" value=\"1.6\"/>"
      "<boolean name=\"nonlinear\" value=\"true\"/></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"twosided\"><bsdf type=\"conductor\"/></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"principled\"><float name=\"eta\" value=\"1.5\"/>"
      "<float name=\"spec_trans\" value=\"0.5\"/><float name=\"flatness\" value=\"0.25\"/>"
      "</bsdf></shape>");
  const auto& m = s.buffers.materials;
  auto mat = [&](int shape) { return m[s.buffers.shapes[shape].material]; };
  EXPECT_EQ(mat(0).type, BSDF_DIFFUSE);  // Mitsuba: diffuse 0.5 when a shape has no BSDF
  EXPECT_FLOAT_EQ(mat(0).param[DIFFUSE_REFLECTANCE].value.x, 0.5f);
  EXPECT_NEAR(mat(1).eta, 1.3330 / 1.000277, 1e-6);  // ext_ior defaults to air
  EXPECT_FLOAT_EQ(mat(1).param[DIELECTRIC_SPECULAR_TRANSMITTANCE].value.z, 1.0f);
  EXPECT_EQ(mat(2).type, BSDF_ROUGHCONDUCTOR);
  EXPECT_EQ(mat(2).flags, MATERIAL_SAMPLE_VISIBLE);  // ggx: no BECKMANN bit
  EXPECT_FLOAT_EQ(mat(2).param[CONDUCTOR_ALPHA_U].value.x, 0.1f);
  EXPECT_FLOAT_EQ(mat(2).param[CONDUCTOR_ALPHA_V].value.x, 0.3f);
  EXPECT_NEAR(mat(2).param[CONDUCTOR_K].value.x, 3.98, 0.01);
  EXPECT_EQ(mat(3).flags, MATERIAL_BECKMANN | MATERIAL_SAMPLE_VISIBLE | MATERIAL_NONLINEAR);
  EXPECT_NEAR(mat(3).eta, 1.6 / 1.000277, 1e-6);
  EXPECT_FLOAT_EQ(mat(3).param[PLASTIC_ALPHA].value.x, 0.1f);
  EXPECT_FLOAT_EQ(mat(3).param[PLASTIC_DIFFUSE_REFLECTANCE].value.x, 0.5f);
  EXPECT_EQ(mat(4).type, BSDF_CONDUCTOR);
  EXPECT_EQ(mat(4).flags, MATERIAL_TWOSIDED);
  EXPECT_FLOAT_EQ(mat(4).param[CONDUCTOR_ETA].value.x, 0.0f);  // "none": a perfect mirror
  EXPECT_FLOAT_EQ(mat(4).param[CONDUCTOR_K].value.x, 1.0f);
  EXPECT_FLOAT_EQ(mat(5).eta, 1.5f);
  EXPECT_FLOAT_EQ(mat(5).param[PRINCIPLED_ROUGHNESS].value.x, 0.5f);
  EXPECT_FLOAT_EQ(mat(5).param[PRINCIPLED_FLATNESS].value.x, 0.25f);
}

// roughplastic's precomputed table (core/bsdf/roughplastic_table.h) is computed once per
// (distribution, alpha, eta): materials that differ only elsewhere share it, and its values are
// those of the core's functions.
TEST(SceneValues, RoughplasticTablesShared) {
  auto plastic = [](const char* alpha, const char* rgb) {
    return std::string(
               "<shape type=\"sphere\"><bsdf type=\"roughplastic\"><float name=\"alpha\" "
               "value=\"") +
           alpha + "\"/><rgb name=\"diffuse_reflectance\" value=\"" + rgb + "\"/></bsdf></shape>";
  };
  Scene s = load_text(plastic("0.2", "0.1 0.2 0.3") + plastic("0.2", "0.7 0.7 0.7") +
                      plastic("0.3", "0.1 0.2 0.3"));
  auto table = [&](int shape) {
    return s.buffers.materials[s.buffers.shapes[shape].material].param[ROUGHPLASTIC_TABLE];
  };
  EXPECT_NE(s.buffers.shapes[0].material, s.buffers.shapes[1].material);
  EXPECT_EQ(table(0).texture, table(1).texture);
  EXPECT_EQ(table(0).value.x, table(1).value.x);
  EXPECT_NE(table(0).texture, table(2).texture);
  for (int shape : {0, 2}) {
    const Material& m = s.buffers.materials[s.buffers.shapes[shape].material];
    const float alpha = m.param[PLASTIC_ALPHA].value.x;
    EXPECT_EQ(table(shape).value.x, roughplastic_internal_reflectance(true, alpha, m.eta));
    const Texture& t = s.buffers.textures[table(shape).texture];
    ASSERT_EQ(t.width, ROUGHPLASTIC_TABLE_RES);
    for (uint j = 0; j < ROUGHPLASTIC_TABLE_RES; j += 21)
      EXPECT_EQ(s.buffers.texels[t.texel_offset + j].x,
                roughplastic_external_transmittance(true, alpha, m.eta, roughplastic_table_mu(j)));
  }
}

// hdrfilm component_format: Mitsuba's default float16, float32 when asked.
TEST(SceneValues, FilmComponentFormat) {
  auto film = [](const std::string& inside) {
    return load_sensor("<sensor type=\"perspective\"><film type=\"hdrfilm\">" + inside +
                       "</film></sensor>");
  };
  EXPECT_TRUE(film("").film_half);
  EXPECT_TRUE(film("<string name=\"component_format\" value=\"float16\"/>").film_half);
  EXPECT_FALSE(film("<string name=\"component_format\" value=\"float32\"/>").film_half);
}

TEST(SceneValues, PrincipledSpecularToEta) {
  Scene s = load_text("<shape type=\"sphere\"><bsdf type=\"principled\"/></shape>");
  // Mitsuba: eta = 2 / (1 - sqrt(0.08 specular)) - 1 with specular = 0.5.
  EXPECT_NEAR(s.buffers.materials[0].eta, 2.0 / (1.0 - std::sqrt(0.04)) - 1.0, 1e-6);
}

TEST(SceneValues, TexturesForColorAndScalarParameters) {
  Scene s = load_text(
      "<texture type=\"checkerboard\" id=\"checks\"><rgb name=\"color0\" value=\"1 0 0\"/>"
      "<rgb name=\"color1\" value=\"0 0 0.6\"/><transform name=\"to_uv\"><scale x=\"4\" y=\"2\"/>"
      "<translate x=\"0.5\"/></transform></texture>"
      "<shape type=\"sphere\"><bsdf type=\"mask\"><ref name=\"opacity\" id=\"checks\"/>"
      "<bsdf type=\"diffuse\"><ref name=\"reflectance\" id=\"checks\"/></bsdf></bsdf></shape>");
  const SceneBuffers& b = s.buffers;
  const Material& m = b.materials[b.shapes[0].material];
  EXPECT_EQ(m.flags, MATERIAL_MASKED | MATERIAL_TEXTURED);
  uint color_tex = m.param[DIFFUSE_REFLECTANCE].texture, scalar_tex = m.opacity.texture;
  ASSERT_NE(color_tex, NO_INDEX);
  ASSERT_NE(scalar_tex, NO_INDEX);
  ASSERT_NE(color_tex, scalar_tex);
  const Texture& c = b.textures[color_tex];
  EXPECT_EQ(c.color0, vec4(1, 0, 0, 1));
  EXPECT_EQ(c.to_uv[0], vec4(4, 0, 0.5, 0));
  EXPECT_EQ(c.to_uv[1], vec4(0, 2, 0, 0));
  // Scalar reads (Mitsuba eval_1) see each constant color's channel mean (srgb::mean), with
  // color0/color1 swapped as Mitsuba's checkerboard eval_1 does.
  const Texture& t = b.textures[scalar_tex];
  EXPECT_NEAR(t.color0.x, 0.2, 1e-6);
  EXPECT_NEAR(t.color1.x, 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(t.color1.z, 1.0 / 3.0, 1e-6);
}

TEST(SceneValues, AreaEmitterAliasTableFollowsTriangleArea) {
  Scene s = load_text(
      "<shape type=\"cube\"><transform name=\"to_world\"><scale x=\"1\" y=\"2\" z=\"3\"/>"
      "</transform><emitter type=\"area\"><rgb name=\"radiance\" value=\"1 2 "
      "3\"/></emitter></shape>"
      "<shape type=\"sphere\"><emitter type=\"area\"/></shape>"
      "<emitter type=\"point\"><point name=\"position\" value=\"0 0 5\"/></emitter>"
      "<emitter type=\"directional\"><vector name=\"direction\" value=\"0 0 -2\"/></emitter>"
      "<emitter type=\"constant\"><rgb name=\"radiance\" value=\"0.5\"/></emitter>");
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.emitters.size(), 5u);
  const Emitter& cube = b.emitters[0];
  EXPECT_EQ(cube.type, EMITTER_AREA);
  EXPECT_EQ(b.shapes[cube.shape].emitter, 0u);
  ASSERT_EQ(cube.alias_count, 12u);
  double pmf_sum = 0.0;
  for (uint t = 0; t < 12; ++t) {
    // Faces of the 2x4x6 box: areas 8 (y-faces), 24 (x-faces), 12 (z-faces); two triangles each.
    const Shape& sh = b.shapes[0];
    glm::vec3 n = glm::vec3(b.normals[sh.first_vertex + b.indices[sh.first_index + 3 * t]]);
    double face_area = std::abs(n.x) > 0.5 ? 24 : std::abs(n.y) > 0.5 ? 12 : 8;
    EXPECT_NEAR(b.alias[cube.alias_offset + t].pmf, face_area / 2 / 88.0, 1e-6);
    pmf_sum += b.alias[cube.alias_offset + t].pmf;
  }
  EXPECT_NEAR(pmf_sum, 1.0, 1e-6);
  EXPECT_EQ(b.emitters[1].alias_count, 0u);  // analytic sphere: sampled by area analytically
  EXPECT_EQ(b.emitters[1].radiance, vec3(1.0f));
  EXPECT_EQ(b.emitters[2].position, vec3(0, 0, 5));
  EXPECT_EQ(b.emitters[3].direction, vec3(0, 0, -1));
  EXPECT_EQ(b.globals.environment, 4u);
  // Mitsuba 3 chooses emitters uniformly unless sampling weights are given.
  ASSERT_EQ(b.globals.emitter_count, 5u);
  for (uint i = 0; i < 5; ++i)
    EXPECT_NEAR(b.alias[b.globals.emitter_alias_offset + i].pmf, 0.2, 1e-6) << i;
}

TEST(SceneValues, EmitterChoiceFollowsSamplingWeights) {
  Scene s = load_text(
      "<shape type=\"sphere\"><emitter type=\"area\"><float name=\"sampling_weight\" "
      "value=\"3\"/></emitter></shape>"
      "<emitter type=\"point\"><float name=\"sampling_weight\" value=\"0\"/></emitter>"
      "<emitter type=\"constant\"/>");
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.globals.emitter_count, 3u);
  const double expected[] = {0.75, 0.0, 0.25};
  for (uint i = 0; i < 3; ++i)
    EXPECT_NEAR(b.alias[b.globals.emitter_alias_offset + i].pmf, expected[i], 1e-6) << i;
}

TEST(SceneValues, ConstantSpectrumInsideAnEmitter) {
  Scene s =
      load_text("<emitter type=\"constant\"><spectrum name=\"radiance\" value=\"1\"/></emitter>");
  EXPECT_NEAR(s.buffers.emitters[0].radiance.x, 1.204794, 1e-6);
  EXPECT_NEAR(s.buffers.emitters[0].radiance.y, 0.948291, 1e-6);
  EXPECT_NEAR(s.buffers.emitters[0].radiance.z, 0.908916, 1e-6);
}

TEST(SceneValues, EmitterPlacementFromTransforms) {
  Scene s = load_text(
      "<emitter type=\"point\"><transform name=\"to_world\"><translate value=\"1 2 3\"/>"
      "</transform><rgb name=\"intensity\" value=\"4\"/></emitter>"
      "<emitter type=\"directional\"><transform name=\"to_world\"><rotate y=\"1\" angle=\"90\"/>"
      "</transform></emitter>");
  const SceneBuffers& b = s.buffers;
  EXPECT_EQ(b.emitters[0].position, vec3(1, 2, 3));
  EXPECT_EQ(b.emitters[0].radiance, vec3(4));
  // Mitsuba: the direction is to_world applied to +z; rotating +z by 90 degrees about y gives +x.
  expect_near(glm::dvec3(b.emitters[1].direction), glm::dvec3(1, 0, 0), 1e-6);
  EXPECT_EQ(b.globals.environment, NO_INDEX);
}

TEST(SceneValues, EnvmapTexelAliasTable) {
  std::filesystem::path dir = fresh_dir();
  // 4 x 3 float image (Mitsuba's smallest environment map is 2 x 3), luminance-only values
  // (grey) so lum = value.
  const int W = 4, H = 3;
  const float lum[H][W] = {{1, 0, 0, 0}, {0, 0, 2, 0}, {0, 0, 0, 0.5f}};
  std::vector<float> rgb;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) rgb.insert(rgb.end(), {lum[j][i], lum[j][i], lum[j][i]});
  std::string exr = (dir / "env.exr").string();
  auto out = OIIO::ImageOutput::create(exr);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(exr, OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
  out->close();
  std::string xml =
      write_file(dir, "scene.xml",
                 scene_xml("<emitter type=\"envmap\"><string name=\"filename\" value=\"env.exr\"/>"
                           "<float name=\"scale\" value=\"2\"/><transform name=\"to_world\">"
                           "<rotate x=\"1\" angle=\"90\"/></transform></emitter>"));
  Scene s = load_scene(xml, {});
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.emitters.size(), 1u);
  const Emitter& e = b.emitters[0];
  EXPECT_EQ(e.type, EMITTER_ENVMAP);
  EXPECT_EQ(e.scale, 2.0f);
  EXPECT_EQ(b.globals.environment, 0u);
  const Texture& t = b.textures[e.texture];
  EXPECT_EQ(t.width, 4u);
  EXPECT_EQ(t.height, 3u);
  EXPECT_EQ(t.filter_mode, FILTER_BILINEAR);
  EXPECT_EQ(t.wrap_mode, WRAP_REPEAT);
  expect_near(apply(e.to_local, apply(e.to_world, glm::dvec3(0.3, 0.2, 0.1))),
              glm::dvec3(0.3, 0.2, 0.1), 1e-6);
  // weight(i, j) = sin(theta_j) (lum(i, j) + max lum over the 3x3 neighbourhood) / 2, u
  // wrapping, v clamped.
  ASSERT_EQ(e.alias_count, uint(W * H));
  std::vector<double> w;
  for (int j = 0; j < H; ++j) {
    double sin_theta = std::sin(M_PI * (j + 0.5) / H);
    for (int i = 0; i < W; ++i) {
      double m = 0.0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          m = std::max(m, double(lum[std::clamp(j + dj, 0, H - 1)][(i + di + W) % W]));
      w.push_back(sin_theta * (lum[j][i] + m) / 2);
    }
  }
  double total = std::accumulate(w.begin(), w.end(), 0.0);
  for (int k = 0; k < W * H; ++k)
    EXPECT_NEAR(b.alias[e.alias_offset + k].pmf, w[k] / total, 1e-6) << k;
}

TEST(SceneValues, SpectrumFilesAndAliases) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "flat.spd", "# wavelength value\n400 0.5\n700 0.5\n");
  std::string xml = write_file(
      dir, "scene.xml",
      scene_xml(
          "<bsdf type=\"diffuse\" id=\"a\"><spectrum name=\"reflectance\" filename=\"flat.spd\"/>"
          "</bsdf><alias id=\"a\" as=\"b\"/><shape type=\"sphere\"><ref id=\"b\"/></shape>"
          "<bsdf type=\"diffuse\" id=\"c\"><spectrum name=\"reflectance\" "
          "value=\"400:0.5, 700:0.5\"/></bsdf>"));
  Scene s = load_scene(xml, {});
  const auto& m = s.buffers.materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(s.buffers.shapes[0].material, 0u);
  EXPECT_EQ(m[0].param[DIFFUSE_REFLECTANCE].value, m[1].param[DIFFUSE_REFLECTANCE].value);
  EXPECT_NEAR(m[0].param[DIFFUSE_REFLECTANCE].value.y, 0.5, 0.01);
}

TEST(SceneValues, ShapegroupsAndInstances) {
  Scene s = load_text(
      "<shape type=\"sphere\"/>"
      "<shape type=\"shapegroup\" id=\"group\"><shape type=\"rectangle\"/>"
      "<shape type=\"sphere\"><point name=\"center\" value=\"0 0 1\"/></shape></shape>"
      "<shape type=\"instance\"><ref id=\"group\"/><transform name=\"to_world\">"
      "<translate x=\"10\"/></transform></shape>"
      "<shape type=\"instance\"><ref id=\"group\"/></shape>");
  const SceneBuffers& b = s.buffers;
  ASSERT_EQ(b.shapes.size(), 3u);
  ASSERT_EQ(b.instances.size(), 3u);
  EXPECT_EQ(b.globals.instance_count, 3u);
  EXPECT_EQ(b.instances[0].first_shape, 0u);
  EXPECT_EQ(b.instances[0].shape_count, 1u);
  // Instance 0 is the identity, exactly: core/interaction.h skips its transforms.
  expect_near(apply(b.instances[0].to_world, glm::dvec3(1, 2, 3)), glm::dvec3(1, 2, 3), 0);
  expect_near(apply(b.instances[0].to_object, glm::dvec3(1, 2, 3)), glm::dvec3(1, 2, 3), 0);
  EXPECT_EQ(b.instances[1].first_shape, 1u);
  EXPECT_EQ(b.instances[1].shape_count, 2u);
  expect_near(apply(b.instances[1].to_world, glm::dvec3(0)), glm::dvec3(10, 0, 0), 1e-6);
  expect_near(apply(b.instances[1].to_object, glm::dvec3(10, 0, 0)), glm::dvec3(0), 1e-6);
  EXPECT_EQ(b.instances[2].first_shape, 1u);
  // Group meshes stay in group space.
  EXPECT_NEAR(b.positions[b.shapes[1].first_vertex].x, -1.0, 1e-6);
}

TEST(SceneValues, CornellBoxLoads) {
  LoadOptions o;
  o.defines["width"] = "64";
  o.defines["spp"] = "8";
  Scene s = load_scene(
      std::string(TWINRAY_SOURCE_DIR) + "/examples/scenes/cornell-box/cornell_box.xml", o);
  EXPECT_EQ(s.buffers.globals.camera.width, 64u);
  EXPECT_EQ(s.buffers.globals.camera.height, 512u);
  EXPECT_EQ(s.spp, 8u);
  EXPECT_EQ(s.integrator_name, "path");
  EXPECT_EQ(s.buffers.globals.integrator.max_depth, 8);
  EXPECT_EQ(s.buffers.globals.emitter_count, 1u);
  bool mirror = false, glass = false;
  for (const Shape& sh : s.buffers.shapes) {
    mirror |= s.buffers.materials[sh.material].type == BSDF_CONDUCTOR;
    glass |= s.buffers.materials[sh.material].type == BSDF_DIELECTRIC;
  }
  EXPECT_TRUE(mirror);
  EXPECT_TRUE(glass);
}

}  // namespace
}  // namespace tr
