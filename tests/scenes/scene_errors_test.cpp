// Bad input: every error is a SceneError whose message is one line, "file:line: ...", naming
// the line of the offending element.
#include <gtest/gtest.h>

#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

// Loads `xml` from a fresh folder (with a valid quad.obj beside it) and returns the error.
std::string error_of(const std::string& xml, const LoadOptions& options = {}) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.obj", QUAD_OBJ);
  std::string path = write_file(dir, "scene.xml", xml);
  try {
    load_scene(path, options);
  } catch (const SceneError& e) {
    std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path + ":", 0), 0u) << message;
    return message.substr(path.size());
  }
  ADD_FAILURE() << "no SceneError for:\n" << xml;
  return "";
}

// Line of the first occurrence of `marker` in the scene_xml(body) text.
int line_of(const std::string& body, const std::string& marker) {
  std::string xml = scene_xml(body);
  size_t at = xml.find(marker);
  return 1 + int(std::count(xml.begin(), xml.begin() + at, '\n'));
}

void expect_error(const std::string& body, const std::string& marker, const std::string& words,
                  const LoadOptions& options = {}) {
  std::string e = error_of(scene_xml(body), options);
  std::string prefix = ":" + std::to_string(line_of(body, marker)) + ": ";
  EXPECT_EQ(e.rfind(prefix, 0), 0u) << "expected line " << prefix << " in: " << e;
  EXPECT_NE(e.find(words), std::string::npos) << "expected \"" << words << "\" in: " << e;
}

TEST(SceneErrors, MalformedXml) {
  std::string e = error_of("<scene version=\"3.0.0\">\n  <shape type=\"sphere\">\n\n</scene>\n");
  EXPECT_NE(e.find("malformed XML"), std::string::npos) << e;
  EXPECT_EQ(e.rfind(":4: ", 0), 0u) << e;
  e = error_of("<scene version=\"3.0.0\">\n<float name=\"x\" value=\"1\"\n</scene>");
  EXPECT_NE(e.find("malformed XML"), std::string::npos) << e;
}

TEST(SceneErrors, UnknownPlugins) {
  expect_error("\n<shape type=\"teapot\"/>", "teapot",
               "<shape type=\"teapot\">: not supported by twinray: teapot (Mitsuba 3 has no such "
               "plugin)");
  expect_error("\n<shape type=\"sphere\">\n<bsdf type=\"velvet\"/></shape>", "velvet",
               "not supported by twinray: velvet (Mitsuba 3 has no such plugin)");
  expect_error("\n\n<integrator type=\"ptracer\"/>", "ptracer",
               "not supported by twinray: ptracer (not implemented by twinray)");
  expect_error("<integrator type=\"volpath\"/>", "volpath",
               "not supported by twinray: volpath (out of scope: participating media");
  expect_error(
      "\n<medium type=\"homogeneous\"/>", "medium",
      "<medium type=\"homogeneous\">: not supported by twinray: homogeneous (out of scope");
  expect_error("\n<bsdf type=\"null\"/>", "null",
               "not supported by twinray: null (not implemented by twinray)");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<texture name=\"reflectance\" "
      "type=\"noise\"/></bsdf></shape>",
      "noise", "not supported by twinray: noise");
}

TEST(SceneErrors, UnknownOrUnusedParameters) {
  expect_error(
      "<shape type=\"sphere\">\n<float name=\"radius\" value=\"1\"/>\n"
      "<float name=\"radiuss\" value=\"2\"/></shape>",
      "radiuss", "unused parameter 'radiuss'");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<float name=\"alpha\" "
      "value=\"0.1\"/></bsdf></shape>",
      "alpha", "unused parameter 'alpha'");
  expect_error("\n<shape type=\"sphere\" colour=\"red\"/>", "colour",
               "unexpected attribute 'colour'");
  expect_error("\n<float name=\"scale\" value=\"2\"/>", "scale", "cannot be set on <scene>");
  expect_error("\n<float name=\"kd_cost\" value=\"2\"/>", "kd_cost", "cannot be set on <scene>");
  expect_error("\n<string name=\"embree_use_robust_intersections\" value=\"yes\"/>", "embree",
               "must be a boolean");
}

TEST(SceneErrors, WrongTypesAndValues) {
  expect_error("<shape type=\"sphere\">\n<string name=\"radius\" value=\"1\"/></shape>", "radius",
               "must be a float");
  expect_error("<shape type=\"sphere\">\n<float name=\"radius\" value=\"NaN\"/></shape>", "NaN",
               "not a finite number");
  expect_error("<shape type=\"sphere\">\n<float name=\"radius\" value=\"inf\"/></shape>", "inf",
               "not a finite number");
  expect_error("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1.0x\"/></shape>", "1.0x",
               "cannot parse");
  expect_error("<shape type=\"sphere\">\n<point name=\"center\" value=\"1 2\"/></shape>", "center",
               "expected 3 values");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<rgb name=\"reflectance\" "
      "value=\"0.5 nan 0.5\"/></bsdf></shape>",
      "reflectance", "not a finite number");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"dielectric\">\n<string name=\"int_ior\" "
      "value=\"glas\"/></bsdf></shape>",
      "glas", "unknown int_ior \"glas\"");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"conductor\">\n<string name=\"material\" "
      "value=\"Unobtainium\"/></bsdf></shape>",
      "Unobtainium", "unknown conductor material");
  expect_error(
      "<shape type=\"sphere\"><transform name=\"to_world\">\n<rotate angle=\"3\"/>"
      "</transform></shape>",
      "rotate", "axis is zero");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<spectrum name=\"reflectance\" "
      "value=\"500:1, 400:2\"/></bsdf></shape>",
      "spectrum", "strictly increasing");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<rgb name=\"reflectance\" "
      "value=\"1.5\"/></bsdf></shape>",
      "1.5", "must lie in [0, 1]");
  expect_error("<shape type=\"sphere\">\n<boolean name=\"flip_normals\" value=\"yes\"/></shape>",
               "yes", "expected \"true\" or \"false\"");
  expect_error("<emitter type=\"point\">\n<float name=\"sampling_weight\" value=\"-1\"/></emitter>",
               "sampling_weight", "sampling_weight must be finite and >= 0");
  expect_error(
      "<shape type=\"sphere\"><emitter type=\"area\">\n<float name=\"sampling_weight\" "
      "value=\"-2\"/></emitter></shape>",
      "sampling_weight", "sampling_weight must be finite and >= 0");
  expect_error(
      "<shape type=\"sphere\">\n<emitter type=\"area\"><float name=\"sampling_weight\" "
      "value=\"0\"/></emitter></shape>",
      "<emitter", "every emitter of the scene has sampling_weight 0");
}

// twinray computes no alpha channel: an rgba film is refused, not written as rgb.
TEST(SceneErrors, RgbaFilmIsRefused) {
  std::string e = error_of(
      "<scene version=\"3.0.0\"><sensor type=\"perspective\"><film type=\"hdrfilm\">\n"
      "<string name=\"pixel_format\" value=\"rgba\"/></film></sensor></scene>");
  EXPECT_EQ(e.rfind(":2: ", 0), 0u) << e;
  EXPECT_NE(e.find("pixel_format \"rgba\" is not supported"), std::string::npos) << e;
}

TEST(SceneErrors, MissingFiles) {
  expect_error("<shape type=\"obj\">\n<string name=\"filename\" value=\"missing.obj\"/></shape>",
               "missing.obj", "mesh file \"missing.obj\" not found");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture name=\"reflectance\" "
      "type=\"bitmap\">\n<string name=\"filename\" value=\"nope.png\"/></texture></bsdf></shape>",
      "nope.png", "image file \"nope.png\" not found");
  expect_error("\n<include filename=\"other.xml\"/>", "include", "file \"other.xml\" not found");
  expect_error("\n<path value=\"no/such/folder\"/>", "path", "not found");
  expect_error("<shape type=\"obj\">\n<string name=\"filename\" value=\"scene.xml\"/></shape>",
               "scene.xml", "the file contains no triangles");  // on the filename line
}

TEST(SceneErrors, References) {
  expect_error("<shape type=\"sphere\">\n<ref id=\"nothing\"/></shape>", "nothing",
               "no object in the scene has this id");
  expect_error("<bsdf type=\"diffuse\" id=\"a\"/>\n<bsdf id=\"a\" type=\"diffuse\"/>",
               "id=\"a\" type", "duplicate id \"a\"");
  expect_error("<shape type=\"sphere\">\n<float name=\"radius\" value=\"$r\"/></shape>", "$r",
               "undefined parameter $r");
  LoadOptions typo;
  typo.defines["sp"] = "4";
  std::string e = error_of(scene_xml("<default name=\"spp\" value=\"1\"/>"), typo);
  EXPECT_NE(e.find("-D sp=4 is not used"), std::string::npos) << e;
}

TEST(SceneErrors, StructuralRules) {
  expect_error(
      "<shape type=\"shapegroup\" id=\"g\"><shape type=\"sphere\">\n<emitter "
      "type=\"area\"/></shape></shape>",
      "emitter", "emitters inside a <shapegroup>");
  expect_error(
      "<emitter type=\"constant\"/>\n<emitter type=\"envmap\"><string name=\"filename\" "
      "value=\"x.exr\"/></emitter>",
      "envmap", "only one environment emitter");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"twosided\"><bsdf type=\"diffuse\"/>\n"
      "<bsdf type=\"conductor\"/></bsdf></shape>",
      "conductor", "different front and back BSDFs");
  expect_error("\n<emitter type=\"area\"/>", "area", "nothing refers to it");
  expect_error(
      "<integrator type=\"path\">\n<integer name=\"max_depth\" value=\"-2\"/></integrator>",
      "max_depth", "max_depth must be -1");
  expect_error("<integrator type=\"path\">\n<integer name=\"min_depth\" value=\"0\"/></integrator>",
               "min_depth", "min_depth must be >= 1 and <= max_depth");
  expect_error(
      "<integrator type=\"path\"><integer name=\"max_depth\" value=\"3\"/>\n"
      "<integer name=\"min_depth\" value=\"4\"/></integrator>",
      "min_depth", "min_depth must be >= 1 and <= max_depth");
  expect_error(
      "<integrator type=\"direct\">\n<integer name=\"min_depth\" value=\"2\"/></integrator>",
      "min_depth", "unused parameter 'min_depth'");
  expect_error(
      "<integrator type=\"ambientocclusion\">\n<float name=\"maxdistance\" value=\"0\"/>"
      "</integrator>",
      "maxdistance", "maxdistance must be positive");
  expect_error(
      "<integrator type=\"ambientocclusion\">\n<float name=\"maxdistance\" value=\"-1\"/>"
      "</integrator>",
      "maxdistance", "maxdistance must be positive");
  expect_error(
      "<integrator type=\"ambientocclusion\">\n<float name=\"cossample\" value=\"1\"/>"
      "</integrator>",
      "cossample", "a boolean");
  expect_error(
      "<integrator type=\"ambientocclusion\">\n<boolean name=\"hide_emitters\" "
      "value=\"true\"/></integrator>",
      "hide_emitters", "unused parameter 'hide_emitters'");
  expect_error(
      "<integrator type=\"ambientocclusion\">\n<integer name=\"max_depth\" value=\"2\"/>"
      "</integrator>",
      "max_depth", "unused parameter 'max_depth'");
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"principled\">\n<float name=\"eta\" value=\"1.5\"/>"
      "<float name=\"specular\" value=\"0.5\"/></bsdf></shape>",
      "eta", "either 'eta' or 'specular'");
  EXPECT_NE(
      error_of("<scene version=\"3.0.0\"><shape type=\"sphere\"/></scene>").find("no <sensor>"),
      std::string::npos);
  EXPECT_NE(error_of("<scene><shape type=\"sphere\"/></scene>").find("version"), std::string::npos);
}

// Never crash on bad input: every truncation and many single-character corruptions of a scene
// that uses most features either load or fail with a SceneError.
TEST(SceneErrors, AlphaTestRules) {
  const std::string quad = "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>\n";
  expect_error(quad + "<bsdf type=\"alphatest\"><bsdf type=\"diffuse\"/></bsdf></shape>",
               "alphatest", "needs an 'opacity'");
  expect_error(quad +
                   "<bsdf type=\"alphatest\"><float name=\"opacity\" value=\"1\"/>\n"
                   "<float name=\"cutoff\" value=\"1.5\"/><bsdf type=\"diffuse\"/></bsdf></shape>",
               "cutoff", "cutoff must lie in [0, 1]");
  expect_error(
      quad + "<bsdf type=\"alphatest\"><float name=\"opacity\" value=\"1\"/></bsdf></shape>",
      "alphatest", "exactly one nested BSDF");
  expect_error(
      "<shape type=\"sphere\">\n<bsdf type=\"alphatest\"><float name=\"opacity\" "
      "value=\"1\"/><bsdf type=\"diffuse\"/></bsdf></shape>",
      "alphatest", "needs a mesh");
  expect_error(quad +
                   "<bsdf type=\"alphatest\"><float name=\"opacity\" value=\"1\"/><bsdf "
                   "type=\"diffuse\"/></bsdf>\n<emitter type=\"area\"/></shape>",
               "emitter", "cannot emit");
  expect_error(quad +
                   "<bsdf type=\"alphatest\"><float name=\"opacity\" value=\"1\"/>\n<bsdf "
                   "type=\"mask\"><bsdf type=\"diffuse\"/></bsdf></bsdf></shape>",
               "type=\"mask", "around a mask is not supported");
}

// An area emitter's textured radiance (scenes/build_emitters.cpp, emitted_texture): uvs to place
// it on a mesh, a texture Mitsuba can sample, no negative emission.
TEST(SceneErrors, TexturedEmitterRules) {
  // Outside the folder error_of empties: an OBJ without vt lines.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "twinray_textured_emitter_rules";
  std::filesystem::create_directories(dir);
  const std::string flat = write_file(dir, "flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string checkerboard = "<texture type=\"checkerboard\" name=\"radiance\"/>";
  expect_error("<shape type=\"obj\"><string name=\"filename\" value=\"" + flat +
                   "\"/><emitter type=\"area\">\n" + checkerboard + "</emitter></shape>",
               "checkerboard", "a textured radiance needs a mesh with uv coordinates");
  expect_error(
      "<shape type=\"rectangle\"><emitter type=\"area\">\n<texture "
      "type=\"mesh_attribute\" name=\"radiance\"><string name=\"name\" "
      "value=\"vertex_color\"/></texture></emitter></shape>",
      "mesh_attribute", "cannot be a mesh_attribute texture");
  expect_error(
      "<shape type=\"sphere\"><emitter type=\"area\">\n<texture type=\"checkerboard\" "
      "name=\"radiance\"><float name=\"color1\" value=\"-1\"/></texture></emitter>"
      "</shape>",
      "color1", "a negative or NaN value in the 'radiance' texture");
}

// twinray's vertex_tangents (glTF's tangent frames): a PLY with both attributes, on a PLY only.
TEST(SceneErrors, VertexTangentsRules) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "twinray_tangent_frame_rules";
  std::filesystem::create_directories(dir);
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty float tangent_x\nproperty float tangent_y\n"
      "property float tangent_z\n";
  const std::string rest = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string no_bitangent =
      write_file(dir, "t.ply", header + rest + "0 0 0 1 0 0\n1 0 0 1 0 0\n0 1 0 1 0 0\n3 0 1 2\n");
  expect_error("<shape type=\"ply\"><string name=\"filename\" value=\"" + no_bitangent +
                   "\"/>\n<boolean name=\"vertex_tangents\" value=\"true\"/></shape>",
               "vertex_tangents", "needs the mesh attribute vertex_bitangent with 3 values");
  expect_error(
      "<shape type=\"rectangle\">\n<boolean name=\"vertex_tangents\" value=\"true\"/>"
      "</shape>",
      "vertex_tangents", "vertex_tangents");
}

TEST(SceneErrors, CorruptedScenesFailCleanly) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.obj", QUAD_OBJ);
  const std::string body =
      "<default name=\"spp\" value=\"4\"/>\n"
      "<integrator type=\"moment\"><integrator type=\"path\">"
      "<integer name=\"max_depth\" value=\"3\"/></integrator></integrator>\n"
      "<bsdf type=\"roughconductor\" id=\"metal\"><float name=\"alpha\" value=\"0.2\"/>"
      "<string name=\"material\" value=\"Cu\"/></bsdf>\n"
      "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/><ref id=\"metal\"/>"
      "<transform name=\"to_world\"><rotate x=\"1\" angle=\"30\"/><scale value=\"2\"/>"
      "</transform></shape>\n"
      "<shape type=\"sphere\"><bsdf type=\"principled\"><texture name=\"metallic\" "
      "type=\"checkerboard\"><float name=\"color0\" value=\"0.1\"/></texture></bsdf></shape>\n"
      "<shape type=\"rectangle\"><emitter type=\"area\"><spectrum name=\"radiance\" "
      "value=\"400:1, 700:2\"/></emitter></shape>\n"
      "<emitter type=\"point\"><point name=\"position\" x=\"1\" y=\"2\" z=\"3\"/></emitter>\n";
  const std::string xml = scene_xml(body);
  ASSERT_NO_THROW(load_scene(write_file(dir, "good.xml", xml), {}));
  int loaded = 0, rejected = 0;
  auto attempt = [&](const std::string& text) {
    ++(loads_or_fails_cleanly(write_file(dir, "bad.xml", text)) ? loaded : rejected);
  };
  for (size_t cut = 0; cut < xml.size(); cut += 7) attempt(xml.substr(0, cut));
  const char replacements[] = {'x', '"', '<', '>', '/', '-', '9', ' ', '$', ','};
  for (size_t i = 0; i < xml.size(); i += 5)
    attempt(xml.substr(0, i) + replacements[i % sizeof(replacements)] + xml.substr(i + 1));
  EXPECT_GT(rejected, 100);
  EXPECT_GT(loaded, 0);
}

}  // namespace
}  // namespace tr
