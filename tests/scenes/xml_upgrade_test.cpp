// Scenes below version 2.0.0 (Mitsuba 0.x) are upgraded on load as Mitsuba 3.8 upgrades them
// (scenes/xml_upgrade.h): each rename of its upgrade_from_v1 makes a 0.6.0 scene load into the
// scene of its 3.0.0 form (equal scene_digest), the same text as version 2.0.0 is refused (the
// old names are then unread), the file gets one warning, and malformed versions are refused.
#include "scenes/xml_upgrade.h"

#include <gtest/gtest.h>

#include "scene_test_files.h"
#include "scenes/scene_digest.h"
#include "scenes/xml_parser.h"

namespace tr {
namespace {

using namespace testing_files;

const std::string SOURCE = TWINRAY_SOURCE_DIR;

std::string scene_text(const std::string& version, const std::string& body) {
  return "<scene version=\"" + version +
         "\">\n"
         "  <sensor type=\"perspective\">\n"
         "    <film type=\"hdrfilm\"><integer name=\"width\" value=\"8\"/>"
         "<integer name=\"height\" value=\"8\"/></film>\n"
         "  </sensor>\n" +
         body + "\n</scene>\n";
}

std::string digest_of(const std::string& path) { return scene_digest(load_scene(path, {})); }

// The error of loading `path`, without the "path:" prefix; one line naming the file.
std::string error_of(const std::string& path) {
  try {
    load_scene(path, {});
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(m.rfind(path + ":", 0), 0u) << m;
    return m.substr(path.size());
  }
  ADD_FAILURE() << path << " loaded";
  return "";
}

// `old_body` in a 0.6.0 scene loads as `new_body` in a 3.0.0 one, and is refused as 2.0.0,
// whose names it no longer has (`unread` names the parameter the error must name).
void expect_upgrade(const std::string& old_body, const std::string& new_body,
                    const std::string& unread) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.obj", QUAD_OBJ);
  std::string old_scene = write_file(dir, "old.xml", scene_text("0.6.0", old_body));
  std::string new_scene = write_file(dir, "new.xml", scene_text("3.0.0", new_body));
  std::string v2_scene = write_file(dir, "v2.xml", scene_text("2.0.0", old_body));
  EXPECT_EQ(digest_of(old_scene), digest_of(new_scene));
  std::string e = error_of(v2_scene);
  EXPECT_NE(e.find("'" + unread + "'"), std::string::npos) << e;
}

ParsedScene parse_text(const std::string& version, const std::string& body) {
  std::string path = write_file(fresh_dir(), "scene.xml", scene_text(version, body));
  return parse_scene_xml(path, {});
}

Node& first_object(Node& node, const std::string& tag) {
  for (Property& p : node.props)
    if (p.kind == PropertyKind::Object && p.object->tag == tag) return *p.object;
  throw std::runtime_error("no <" + tag + ">");
}

TEST(XmlUpgrade, CamelToUnderscoreCase) {
  EXPECT_EQ(camel_to_underscore_case("maxDepth"), "max_depth");
  EXPECT_EQ(camel_to_underscore_case("toWorld"), "to_world");
  EXPECT_EQ(camel_to_underscore_case("intIOR"), "int_ior");
  EXPECT_EQ(camel_to_underscore_case("cropOffsetX"), "crop_offset_x");
  EXPECT_EQ(camel_to_underscore_case("specularSamplingWeight"), "specular_sampling_weight");
  // Only an upper-case letter after a lower-case one starts a word; the run of upper-case
  // letters after it joins that word, and the letter after the run is not compared.
  EXPECT_EQ(camel_to_underscore_case("xYZw"), "x_yzw");
  EXPECT_EQ(camel_to_underscore_case("xYzW"), "x_yz_w");
  EXPECT_EQ(camel_to_underscore_case("aBCdEF"), "a_bcd_ef");
  for (const char* same : {"", "B", "IOR", "Kd", "_arg_3", "max_depth", "fov", "u9V", "a_B"})
    EXPECT_EQ(camel_to_underscore_case(same), same);
}

TEST(XmlUpgrade, IntegratorSensorSamplerAndFilmParameters) {
  expect_upgrade(
      "<integrator type=\"path\"><integer name=\"maxDepth\" value=\"65\"/>"
      "<integer name=\"rrDepth\" value=\"3\"/><boolean name=\"hideEmitters\" value=\"true\"/>"
      "</integrator>",
      "<integrator type=\"path\"><integer name=\"max_depth\" value=\"65\"/>"
      "<integer name=\"rr_depth\" value=\"3\"/><boolean name=\"hide_emitters\" value=\"true\"/>"
      "</integrator>",
      "maxDepth");
  const std::string sensor =
      "<sensor type=\"thinlens\"><float name=\"fov\" value=\"40\"/>"
      "<string name=\"fovAxis\" value=\"smaller\"/><float name=\"nearClip\" value=\"0.5\"/>"
      "<float name=\"farClip\" value=\"50\"/><float name=\"apertureRadius\" value=\"0.1\"/>"
      "<float name=\"focusDistance\" value=\"4\"/>"
      "<transform name=\"toWorld\"><lookat origin=\"0 0 5\" target=\"0 0 0\" up=\"0 1 0\"/>"
      "</transform><sampler type=\"stratified\"><integer name=\"sampleCount\" value=\"9\"/>"
      "</sampler><film type=\"hdrfilm\"><integer name=\"width\" value=\"16\"/>"
      "<integer name=\"height\" value=\"12\"/><integer name=\"cropOffsetX\" value=\"2\"/>"
      "<integer name=\"cropWidth\" value=\"8\"/><boolean name=\"sampleBorder\" value=\"true\"/>"
      "<string name=\"fileFormat\" value=\"openexr\"/><string name=\"pixelFormat\" value=\"rgb\"/>"
      "<string name=\"componentFormat\" value=\"float32\"/><rfilter type=\"gaussian\"/></film>"
      "</sensor>";
  std::string upgraded = sensor;
  for (auto [from, to] : {std::pair<const char*, const char*>{"fovAxis", "fov_axis"},
                          {"nearClip", "near_clip"},
                          {"farClip", "far_clip"},
                          {"apertureRadius", "aperture_radius"},
                          {"focusDistance", "focus_distance"},
                          {"toWorld", "to_world"},
                          {"sampleCount", "sample_count"},
                          {"cropOffsetX", "crop_offset_x"},
                          {"cropWidth", "crop_width"},
                          {"sampleBorder", "sample_border"},
                          {"fileFormat", "file_format"},
                          {"pixelFormat", "pixel_format"},
                          {"componentFormat", "component_format"}})
    upgraded.replace(upgraded.find(from), std::string(from).size(), to);
  // scene_text's own sensor is replaced: a scene has one.
  std::filesystem::path dir = fresh_dir();
  auto whole = [](const std::string& version, const std::string& s) {
    return "<scene version=\"" + version + "\">" + s + "<emitter type=\"constant\"/></scene>";
  };
  std::string old_scene = write_file(dir, "old.xml", whole("0.6.0", sensor));
  std::string new_scene = write_file(dir, "new.xml", whole("3.0.0", upgraded));
  EXPECT_EQ(digest_of(old_scene), digest_of(new_scene));
  EXPECT_NE(error_of(write_file(dir, "v2.xml", whole("2.0.0", sensor))).find("'cropOffsetX'"),
            std::string::npos);
}

TEST(XmlUpgrade, ShapeBsdfAndEmitterParameters) {
  expect_upgrade(
      "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>"
      "<boolean name=\"faceNormals\" value=\"true\"/><boolean name=\"flipNormals\" value=\"true\"/>"
      "<boolean name=\"flipTexCoords\" value=\"false\"/>"
      "<transform name=\"toWorld\"><rotate x=\"1\" angle=\"30\"/></transform>"
      "<bsdf type=\"roughdielectric\"><float name=\"intIOR\" value=\"1.7\"/>"
      "<float name=\"extIOR\" value=\"1.1\"/><float name=\"alphaU\" value=\"0.1\"/>"
      "<float name=\"alphaV\" value=\"0.3\"/><string name=\"distribution\" value=\"ggx\"/>"
      "<boolean name=\"sampleVisible\" value=\"false\"/>"
      "<rgb name=\"specularReflectance\" value=\"0.9 0.8 0.7\"/>"
      "<rgb name=\"specularTransmittance\" value=\"0.7 0.8 0.9\"/></bsdf></shape>"
      "<shape type=\"sphere\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"2 2 2\"/>"
      "<float name=\"samplingWeight\" value=\"3\"/></emitter></shape>"
      "<emitter type=\"spot\"><float name=\"cutoffAngle\" value=\"30\"/>"
      "<float name=\"beamWidth\" value=\"10\"/><transform name=\"toWorld\">"
      "<translate z=\"4\"/></transform></emitter>",
      "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>"
      "<boolean name=\"face_normals\" value=\"true\"/>"
      "<boolean name=\"flip_normals\" value=\"true\"/>"
      "<boolean name=\"flip_tex_coords\" value=\"false\"/>"
      "<transform name=\"to_world\"><rotate x=\"1\" angle=\"30\"/></transform>"
      "<bsdf type=\"roughdielectric\"><float name=\"int_ior\" value=\"1.7\"/>"
      "<float name=\"ext_ior\" value=\"1.1\"/><float name=\"alpha_u\" value=\"0.1\"/>"
      "<float name=\"alpha_v\" value=\"0.3\"/><string name=\"distribution\" value=\"ggx\"/>"
      "<boolean name=\"sample_visible\" value=\"false\"/>"
      "<rgb name=\"specular_reflectance\" value=\"0.9 0.8 0.7\"/>"
      "<rgb name=\"specular_transmittance\" value=\"0.7 0.8 0.9\"/></bsdf></shape>"
      "<shape type=\"sphere\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"2 2 2\"/>"
      "<float name=\"sampling_weight\" value=\"3\"/></emitter></shape>"
      "<emitter type=\"spot\"><float name=\"cutoff_angle\" value=\"30\"/>"
      "<float name=\"beam_width\" value=\"10\"/><transform name=\"to_world\">"
      "<translate z=\"4\"/></transform></emitter>",
      "intIOR");
}

// The names of nested objects and of <ref>s are parameter names too; so are the <scene>'s own.
TEST(XmlUpgrade, ObjectReferenceAndSceneParameterNames) {
  expect_upgrade(
      "<boolean name=\"embreeUseRobustIntersections\" value=\"false\"/>"
      "<texture type=\"checkerboard\" id=\"c\"/>"
      "<shape type=\"sphere\"><bsdf type=\"conductor\">"
      "<ref name=\"specularReflectance\" id=\"c\"/></bsdf></shape>"
      "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>"
      "<bsdf type=\"plastic\"><texture name=\"diffuseReflectance\" type=\"checkerboard\"/>"
      "</bsdf></shape>",
      "<boolean name=\"embree_use_robust_intersections\" value=\"false\"/>"
      "<texture type=\"checkerboard\" id=\"c\"/>"
      "<shape type=\"sphere\"><bsdf type=\"conductor\">"
      "<ref name=\"specular_reflectance\" id=\"c\"/></bsdf></shape>"
      "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/>"
      "<bsdf type=\"plastic\"><texture name=\"diffuse_reflectance\" type=\"checkerboard\"/>"
      "</bsdf></shape>",
      "embreeUseRobustIntersections");
}

// upgrade_from_v1: a diffuse plugin's diffuse_reflectance becomes reflectance, whichever way it
// is spelled and whatever gives it; plastic's diffuse_reflectance (above) keeps its name.
TEST(XmlUpgrade, DiffuseReflectanceOfDiffuseBecomesReflectance) {
  expect_upgrade(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">"
      "<rgb name=\"diffuseReflectance\" value=\"0.2 0.4 0.6\"/></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">"
      "<texture name=\"diffuse_reflectance\" type=\"checkerboard\"/></bsdf></shape>",
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">"
      "<rgb name=\"reflectance\" value=\"0.2 0.4 0.6\"/></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"diffuse\">"
      "<texture name=\"reflectance\" type=\"checkerboard\"/></bsdf></shape>",
      "diffuseReflectance");
}

// upgrade_from_v1: uoffset, voffset, uscale, vscale (absent: 0, 0, 1, 1) become
// to_uv = scale(uscale, vscale, 1) * translate(uoffset, voffset, 0), on any object.
TEST(XmlUpgrade, UvOffsetAndScaleBecomeToUv) {
  ParsedScene parsed =
      parse_text("0.6.0",
                 "<texture type=\"checkerboard\" id=\"t\"><float name=\"uoffset\" value=\"0.25\"/>"
                 "<float name=\"vscale\" value=\"8\"/><integer name=\"uscale\" value=\"4\"/>"
                 "<float name=\"voffset\" value=\"-0.5\"/></texture>");
  Node& texture = first_object(*parsed.root, "texture");
  ASSERT_EQ(texture.props.size(), 1u);
  const Property& to_uv = texture.props[0];
  EXPECT_EQ(to_uv.name, "to_uv");
  EXPECT_EQ(to_uv.kind, PropertyKind::Transform);
  EXPECT_EQ(to_uv.loc.line, 5);
  glm::dmat4 expected(1.0);
  expected[0][0] = 4.0;
  expected[1][1] = 8.0;
  expected[3] = glm::dvec4(4.0 * 0.25, 8.0 * -0.5, 0.0, 1.0);
  EXPECT_EQ(to_uv.matrix, expected);

  expect_upgrade(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture type=\"checkerboard\" "
      "name=\"reflectance\"><float name=\"uoffset\" value=\"0.125\"/>"
      "<float name=\"voffset\" value=\"0.375\"/><float name=\"uscale\" value=\"3\"/>"
      "<float name=\"vscale\" value=\"5\"/></texture></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture type=\"checkerboard\" "
      "name=\"reflectance\"><integer name=\"vscale\" value=\"2\"/></texture></bsdf></shape>",
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture type=\"checkerboard\" "
      "name=\"reflectance\"><transform name=\"to_uv\"><translate x=\"0.125\" y=\"0.375\"/>"
      "<scale x=\"3\" y=\"5\"/></transform></texture></bsdf></shape>"
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture type=\"checkerboard\" "
      "name=\"reflectance\"><transform name=\"to_uv\"><scale y=\"2\"/></transform></texture>"
      "</bsdf></shape>",
      "uoffset");
}

TEST(XmlUpgrade, UvParametersOfWrongTypeOrBesideToUvAreRefused) {
  std::filesystem::path dir = fresh_dir();
  std::string path = write_file(dir, "wrong_type.xml",
                                scene_text("0.6.0",
                                           "<texture type=\"checkerboard\" id=\"t\">\n"
                                           "<string name=\"vscale\" value=\"2\"/></texture>"));
  std::string e = error_of(path);
  EXPECT_EQ(e.rfind(":6: ", 0), 0u) << e;
  EXPECT_NE(e.find("parameter 'vscale' of <texture type=\"checkerboard\"> must be a float"),
            std::string::npos)
      << e;
  path = write_file(dir, "twice.xml",
                    scene_text("0.6.0",
                               "<texture type=\"checkerboard\" id=\"t\">\n"
                               "<float name=\"uscale\" value=\"2\"/>\n"
                               "<transform name=\"toUV\"><scale x=\"2\"/></transform></texture>"));
  e = error_of(path);
  EXPECT_EQ(
      e.rfind(":7: parameter 'to_uv' of <texture type=\"checkerboard\"> is specified twice", 0), 0u)
      << e;
  EXPECT_NE(e.find("line 6"), std::string::npos) << e;
}

// Properties::rename_property leaves a parameter as it is when the new name is taken: the old
// name then stays unread, an error in twinray (Mitsuba warns).
TEST(XmlUpgrade, NoRenameOntoAGivenName) {
  std::filesystem::path dir = fresh_dir();
  std::string e = error_of(
      write_file(dir, "depth.xml",
                 scene_text("0.6.0",
                            "<integrator type=\"path\"><integer name=\"max_depth\" value=\"3\"/>\n"
                            "<integer name=\"maxDepth\" value=\"4\"/></integrator>")));
  EXPECT_NE(e.find("unused parameter 'maxDepth'"), std::string::npos) << e;
  e = error_of(
      write_file(dir, "diffuse.xml",
                 scene_text("0.6.0",
                            "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n"
                            "<rgb name=\"diffuseReflectance\" value=\"0.5 0.5 0.5\"/>"
                            "<rgb name=\"reflectance\" value=\"0.1 0.1 0.1\"/></bsdf></shape>")));
  EXPECT_NE(e.find("unused parameter 'diffuse_reflectance'"), std::string::npos) << e;
}

// Reflectance-like colours must lie in [0, 1], IOR- and roughness-like ones need not: judged by
// the name after the upgrade.
TEST(XmlUpgrade, ColourBoundsFollowTheUpgradedName) {
  const std::string body =
      "<bsdf type=\"roughconductor\" id=\"c\"><rgb name=\"alphaU\" value=\"0.5 1.5 0.5\"/>"
      "</bsdf>";
  ParsedScene parsed = parse_text("0.6.0", body);
  EXPECT_EQ(first_object(*parsed.root, "bsdf").props[0].name, "alpha_u");
  std::string path = write_file(fresh_dir(), "v3.xml", scene_text("3.0.0", body));
  EXPECT_THROW(parse_scene_xml(path, {}), SceneError);
}

// Mitsuba upgrades each file by its own version: an included 0.6.0 file is upgraded, a 3.0.0 file
// included by a 0.6.0 one is not (its objects' parameters keep their names).
TEST(XmlUpgrade, IncludedFilesByTheirOwnVersion) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "old_part.xml",
             "<scene version=\"0.6.0\">\n"
             "<integrator type=\"path\"><integer name=\"maxDepth\" value=\"2\"/></integrator>"
             "</scene>\n");
  write_file(dir, "new_part.xml",
             "<scene version=\"3.0.0\">\n"
             "<integrator type=\"path\"><integer name=\"maxDepth\" value=\"2\"/></integrator>"
             "</scene>\n");
  std::string includes_old = write_file(
      dir, "includes_old.xml", scene_text("3.0.0", "<include filename=\"old_part.xml\"/>"));
  std::string equivalent =
      write_file(dir, "equivalent.xml",
                 scene_text("3.0.0",
                            "<integrator type=\"path\"><integer name=\"max_depth\" value=\"2\"/>"
                            "</integrator>"));
  EXPECT_EQ(digest_of(includes_old), digest_of(equivalent));
  std::vector<std::string> warnings = parse_scene_xml(includes_old, {}).warnings;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind((dir / "old_part.xml").lexically_normal().string() + ":1: ", 0), 0u)
      << warnings[0];
  std::string includes_new = write_file(
      dir, "includes_new.xml", scene_text("0.6.0", "<include filename=\"new_part.xml\"/>"));
  try {
    load_scene(includes_new, {});
    ADD_FAILURE() << includes_new << " loaded";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "new_part.xml").lexically_normal().string() +
                  ":2: unused parameter 'maxDepth' (integer) in <integrator type=\"path\">: not a "
                  "parameter of this plugin");
  }
}

TEST(XmlUpgrade, OneWarningNamingTheFileAndItsVersion) {
  std::filesystem::path dir = fresh_dir();
  std::string path =
      write_file(dir, "old.xml",
                 "<?xml version=\"1.0\"?>\n" +
                     scene_text("0.5.0", "<shape type=\"sphere\"/><shape type=\"sphere\"/>"));
  std::vector<std::string> warnings = parse_scene_xml(path, {}).warnings;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], path +
                             ":2: scene version 0.5.0 upgraded on load as Mitsuba 3 upgrades "
                             "Mitsuba 0.x scenes (camelCase parameter names to snake_case, "
                             "diffuse_reflectance to reflectance, uoffset/voffset/uscale/vscale "
                             "to to_uv)");
  for (const char* version : {"2.0.0", "3.0.0", "3.9.1"})
    EXPECT_TRUE(parse_text(version, "").warnings.empty()) << version;
}

TEST(XmlUpgrade, MalformedOrFutureVersionsAreRefused) {
  std::filesystem::path dir = fresh_dir();
  int n = 0;
  for (const char* version : {"", "banana", "0.6", "0.6.0.0", "0..6", ".0.6", "0.6.", "-1.0.0",
                              " 0.6.0", "0.6.0a", "0x1.0.0", "0.6.0 "}) {
    std::string path = write_file(dir, "bad" + std::to_string(n++) + ".xml",
                                  scene_text(version, "<shape type=\"sphere\"/>"));
    EXPECT_EQ(error_of(path), std::string(":1: <scene version=\"") + version +
                                  "\">: a version is three period-separated numbers");
  }
  for (const char* version : {"4.0.0", "10.0.0", "99999999999999999999999.0.0"}) {
    std::string path = write_file(dir, "future" + std::to_string(n++) + ".xml",
                                  scene_text(version, "<shape type=\"sphere\"/>"));
    EXPECT_EQ(error_of(path), std::string(":1: <scene version=\"") + version +
                                  "\">: a version after Mitsuba 3's (3.x.x), whose scene format "
                                  "twinray does not know");
  }
  std::string path = write_file(
      dir, "huge_minor.xml", scene_text("0.99999999999999999999999.0", "<shape type=\"sphere\"/>"));
  EXPECT_NO_THROW(load_scene(path, {}));
}

// tests/scenes/mitsuba_0_6/: a 0.6.0 scene written as Bitterli's are (camelCase names, toWorld
// matrices, hdrfilm with fileFormat and banner, twosided diffuse, roughconductor with a material,
// dielectric and plastic with intIOR, obj/rectangle/cube/sphere, an area light) and its 3.0.0
// form load into the same scene.
TEST(XmlUpgrade, BitterliStyleScene) {
  std::filesystem::path dir = std::filesystem::path(SOURCE) / "tests" / "scenes" / "mitsuba_0_6";
  Scene old_scene = load_scene((dir / "bitterli_style.xml").string(), {});
  EXPECT_EQ(scene_digest(old_scene), digest_of((dir / "bitterli_style_3.0.0.xml").string()));
  EXPECT_EQ(old_scene.buffers.globals.camera.width, 32u);
}

// Beyond Mitsuba 3.8 (scenes/xml_upgrade_beyond.h): what Bitterli's 0.6 scenes use and Mitsuba
// 3.8 refuses, read by twinray in files below 2.0.0 only. A 0.6.0 scene with an ldrfilm, <lookAt>,
// strictNormals and a roughconductor's extEta loads into its 3.0.0 form (with strict_normals).
TEST(XmlUpgradeBeyond, LdrfilmLookAtScene) {
  std::filesystem::path dir = std::filesystem::path(SOURCE) / "tests" / "scenes" / "mitsuba_0_6";
  std::string path = (dir / "ldrfilm_lookat.xml").string();
  EXPECT_EQ(digest_of(path), digest_of((dir / "ldrfilm_lookat_3.0.0.xml").string()));
  std::vector<std::string> warnings = parse_scene_xml(path, {}).warnings;
  ASSERT_EQ(warnings.size(), 2u);  // the upgrade's and one naming what was not applied
  EXPECT_EQ(warnings[1], path +
                             ":24: beyond Mitsuba 3.8's upgrade of this 0.x file: <film "
                             "type=\"ldrfilm\"> read as an hdrfilm; not applied (they shape only "
                             "the image file; twinray writes linear EXR and an sRGB PNG preview): "
                             "file_format \"png\", pixel_format \"rgb\", tonemap_method \"gamma\", "
                             "gamma 2.2, exposure 0 (line 24)");
}

// The sensor of scene_text with `film` (its contents) in place of its film.
std::string film_scene(const std::string& version, const std::string& film,
                       const std::string& integrator = "") {
  return "<scene version=\"" + version + "\">\n" + integrator + "<sensor type=\"perspective\">\n" +
         film + "\n</sensor>\n<shape type=\"sphere\"/>\n</scene>\n";
}

TEST(XmlUpgradeBeyond, LdrfilmIsAnHdrfilmWhoseOutputOnlyParametersAreDropped) {
  std::filesystem::path dir = fresh_dir();
  const std::string size =
      "<integer name=\"width\" value=\"8\"/><integer name=\"height\" value=\"6\"/>"
      "<integer name=\"cropOffsetX\" value=\"1\"/><integer name=\"cropWidth\" value=\"4\"/>"
      "<rfilter type=\"box\"/>";
  std::string old_path = write_file(
      dir, "ldr.xml",
      film_scene("0.5.0",
                 "<film type=\"ldrfilm\">" + size +
                     "<string name=\"fileFormat\" value=\"jpeg\"/>"
                     "<string name=\"pixelFormat\" value=\"luminanceAlpha\"/>"
                     "<string name=\"tonemapMethod\" value=\"reinhard\"/>"
                     "<float name=\"key\" value=\"0.3\"/><float name=\"burn\" value=\"1\"/>"
                     "<boolean name=\"banner\" value=\"true\"/></film>"));
  std::string new_path = write_file(
      dir, "hdr.xml",
      film_scene("3.0.0",
                 "<film type=\"hdrfilm\"><integer name=\"width\" value=\"8\"/><integer "
                 "name=\"height\" value=\"6\"/><integer name=\"crop_offset_x\" value=\"1\"/>"
                 "<integer name=\"crop_width\" value=\"4\"/><rfilter type=\"box\"/></film>"));
  EXPECT_EQ(digest_of(old_path), digest_of(new_path));
  Scene scene = load_scene(old_path, {});
  EXPECT_EQ(scene.buffers.globals.camera.width, 4u);
  std::vector<std::string> warnings = parse_scene_xml(old_path, {}).warnings;
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[1].find(":3: beyond Mitsuba 3.8's upgrade of this 0.x file: <film "
                             "type=\"ldrfilm\"> read as an hdrfilm; not applied"),
            std::string::npos)
      << warnings[1];
  EXPECT_NE(warnings[1].find("file_format \"jpeg\", pixel_format \"luminanceAlpha\", "
                             "tonemap_method \"reinhard\", key 0.3, burn 1, banner true (line 3)"),
            std::string::npos)
      << warnings[1];
  // From 2.0.0 on, as in Mitsuba 3.8, there is no ldrfilm.
  std::string v2 = write_file(dir, "v2.xml", film_scene("2.0.0", "\n<film type=\"ldrfilm\"/>"));
  EXPECT_EQ(error_of(v2),
            ":4: <film type=\"ldrfilm\">: not supported by twinray: ldrfilm (Mitsuba 3 has no such "
            "plugin)");
}

TEST(XmlUpgradeBeyond, HdrfilmOutputValuesTwinrayCannotWriteAreDropped) {
  std::filesystem::path dir = fresh_dir();
  std::string old_path = write_file(
      dir, "old.xml",
      film_scene("0.6.0",
                 "<film type=\"hdrfilm\"><string name=\"fileFormat\" value=\"rgbe\"/>"
                 "<string name=\"pixelFormat\" value=\"rgba\"/><string name=\"componentFormat\" "
                 "value=\"uint32\"/><boolean name=\"attachLog\" value=\"false\"/></film>"));
  std::string new_path =
      write_file(dir, "new.xml", film_scene("3.0.0", "<film type=\"hdrfilm\"/>"));
  EXPECT_EQ(digest_of(old_path), digest_of(new_path));
  std::vector<std::string> warnings = parse_scene_xml(old_path, {}).warnings;
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[1].find("file_format \"rgbe\", pixel_format \"rgba\", component_format "
                             "\"uint32\", attach_log false (line 3)"),
            std::string::npos)
      << warnings[1];
  // What twinray writes stays read, and gets no warning.
  std::string exr =
      write_file(dir, "exr.xml",
                 film_scene("0.6.0",
                            "<film type=\"hdrfilm\"><string name=\"fileFormat\" value=\"openexr\"/>"
                            "<string name=\"pixelFormat\" value=\"rgb\"/><string "
                            "name=\"componentFormat\" value=\"float32\"/></film>"));
  EXPECT_EQ(parse_scene_xml(exr, {}).warnings.size(), 1u);
  EXPECT_FALSE(load_scene(exr, {}).film_half);
  // 2.0.0: Mitsuba 3's hdrfilm, which twinray cannot write as rgbe.
  std::string v2 =
      write_file(dir, "v2.xml",
                 film_scene("2.0.0",
                            "<film type=\"hdrfilm\"><string name=\"file_format\" value=\"rgbe\"/>"
                            "</film>"));
  EXPECT_NE(error_of(v2).find("file_format \"rgbe\" is not supported"), std::string::npos);
}

TEST(XmlUpgradeBeyond, HighQualityEdgesIsSampleBorder) {
  std::filesystem::path dir = fresh_dir();
  std::string old_path =
      write_file(dir, "old.xml",
                 film_scene("0.6.0",
                            "<film type=\"hdrfilm\"><boolean name=\"highQualityEdges\" "
                            "value=\"true\"/></film>"));
  std::string new_path = write_file(
      dir, "new.xml",
      film_scene("3.0.0",
                 "<film type=\"hdrfilm\"><boolean name=\"sample_border\" value=\"true\"/></film>"));
  std::string plain = write_file(dir, "plain.xml", film_scene("3.0.0", "<film type=\"hdrfilm\"/>"));
  EXPECT_EQ(digest_of(old_path), digest_of(new_path));
  EXPECT_NE(digest_of(old_path), digest_of(plain));
  EXPECT_EQ(parse_scene_xml(old_path, {}).warnings.size(), 1u);  // exact: no warning
  std::string both =
      write_file(dir, "both.xml",
                 film_scene("0.6.0",
                            "<film type=\"hdrfilm\"><boolean name=\"highQualityEdges\" "
                            "value=\"true\"/>\n<boolean name=\"sample_border\" value=\"true\"/>"
                            "</film>"));
  EXPECT_EQ(error_of(both),
            ":4: parameter 'sample_border' of <film type=\"hdrfilm\"> is specified twice: "
            "highQualityEdges (line 3) is Mitsuba 3's sample_border");
  std::string v2 =
      write_file(dir, "v2.xml",
                 film_scene("2.0.0",
                            "<film type=\"hdrfilm\"><boolean name=\"high_quality_edges\" "
                            "value=\"true\"/></film>"));
  EXPECT_NE(error_of(v2).find("unused parameter 'high_quality_edges'"), std::string::npos);
}

TEST(XmlUpgradeBeyond, LookAtBelow2IsLookat) {
  const std::string look =
      "<transform name=\"toWorld\">\n<lookAt origin=\"1, 2, 3\" "
      "target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>";
  std::filesystem::path dir = fresh_dir();
  std::string old_path = write_file(dir, "old.xml", film_scene("0.6.0", look));
  std::string new_lookat = look;
  new_lookat.replace(new_lookat.find("toWorld"), 7, "to_world");
  new_lookat.replace(new_lookat.find("lookAt"), 6, "lookat");
  std::string new_path = write_file(dir, "new.xml", film_scene("3.0.0", new_lookat));
  EXPECT_EQ(digest_of(old_path), digest_of(new_path));
  EXPECT_EQ(parse_scene_xml(old_path, {}).warnings.size(), 1u);  // exact: no warning
  std::string v2 = write_file(dir, "v2.xml", film_scene("2.0.0", look));
  EXPECT_EQ(error_of(v2), ":4: unknown transform operation <lookAt>");
}

// strictNormals is twinray's strict_normals of path and direct (Mitsuba 3.8's upgrade renames
// it), exactly and without a warning, whatever the shapes' shading normals; core/integrator.h
// applies it (tests/cpu/strict_normals_test.cpp).
TEST(XmlUpgradeBeyond, StrictNormals) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "quad.obj", QUAD_OBJ);
  auto scene = [&](const std::string& name, const std::string& version, const std::string& type,
                   const std::string& param, const std::string& value, const std::string& shape) {
    std::string integrator = value.empty()
                                 ? "<integrator type=\"" + type + "\"/>\n"
                                 : "<integrator type=\"" + type + "\">\n<boolean name=\"" + param +
                                       "\" value=\"" + value + "\"/></integrator>\n";
    std::string text = film_scene(version, "", integrator);
    text.replace(text.find("<shape type=\"sphere\"/>"), 22, shape);
    return write_file(dir, name, text);
  };
  const std::string smooth =
      "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/></shape>"
      "<shape type=\"sphere\"/>";
  for (const std::string type : {"path", "direct"}) {
    // false is the default (Mitsuba 3's behaviour).
    std::string off = scene(type + "_off.xml", "0.6.0", type, "strictNormals", "false", smooth);
    EXPECT_EQ(digest_of(off), digest_of(scene(type + "_none.xml", "0.6.0", type, "", "", smooth)));
    EXPECT_EQ(load_scene(off, {}).buffers.globals.integrator.strict_normals, 0u) << type;
    // true: strict_normals, on meshes with interpolated normals too; no warning beyond the
    // upgrade's own.
    std::string on = scene(type + "_on.xml", "0.6.0", type, "strictNormals", "true", smooth);
    EXPECT_EQ(parse_scene_xml(on, {}).warnings.size(), 1u) << type;
    Scene loaded = load_scene(on, {});
    EXPECT_EQ(loaded.buffers.globals.integrator.strict_normals, 1u) << type;
    EXPECT_EQ(scene_digest(loaded),
              digest_of(scene(type + "_3.xml", "3.0.0", type, "strict_normals", "true", smooth)));
    EXPECT_NE(scene_digest(loaded), digest_of(off));
  }
  // 2.0.0: no Mitsuba 3 integrator reads strictNormals; strict_normals is twinray's, for path
  // and direct only.
  std::string v2 = scene("v2.xml", "2.0.0", "path", "strictNormals", "false", smooth);
  EXPECT_NE(error_of(v2).find("unused parameter 'strictNormals'"), std::string::npos);
  std::string ao = scene("ao.xml", "3.0.0", "ambientocclusion", "strict_normals", "true", smooth);
  EXPECT_NE(error_of(ao).find("unused parameter 'strict_normals'"), std::string::npos);
}

// Rule 6: Mitsuba 0.6's filterType in any case; its MIP-map filters trilinear and ewa (with
// maxAnisotropy) as bilinear, warned; Bitterli's 0.5 scenes set trilinear on every bitmap.
TEST(XmlUpgradeBeyond, MipMapFiltersAreBilinear) {
  auto bitmap = [](const std::string& params) {
    return "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture type=\"bitmap\" "
           "name=\"reflectance\"><string name=\"filename\" value=\"" TWINRAY_SOURCE_DIR
           "/tests/fuzz/corpus/checker_rgb8.png\"/>\n" +
           params + "</texture></bsdf></shape>";
  };
  const std::string bilinear = "<string name=\"filter_type\" value=\"bilinear\"/>";
  expect_upgrade(bitmap("<string name=\"filterType\" value=\"trilinear\"/>"), bitmap(bilinear),
                 "filterType");
  expect_upgrade(bitmap("<string name=\"filterType\" value=\"EWA\"/>"
                        "<float name=\"maxAnisotropy\" value=\"20\"/>"),
                 bitmap(""), "filterType");
  expect_upgrade(bitmap("<string name=\"filterType\" value=\"Nearest\"/>"),
                 bitmap("<string name=\"filter_type\" value=\"nearest\"/>"), "filterType");
  std::string trilinear = bitmap(
      "<string name=\"filterType\" value=\"trilinear\"/><float name=\"maxAnisotropy\" "
      "value=\"8\"/>");
  std::string path =
      write_file(fresh_dir(), "trilinear.xml", scene_text("0.5.0", trilinear + "\n" + trilinear));
  std::vector<std::string> warnings = parse_scene_xml(path, {}).warnings;
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[1].find("beyond Mitsuba 3.8's upgrade of this 0.x file: filter_type "
                             "\"trilinear\" read as \"bilinear\" (lines 6, 8); max_anisotropy 8 "
                             "dropped (only ewa reads it) (lines 6, 8)"),
            std::string::npos)
      << warnings[1];
}

TEST(XmlUpgradeBeyond, ConductorExtEta) {
  auto conductor = [](const std::string& ext, double eta, double k) {
    return "<shape type=\"sphere\"><bsdf type=\"roughconductor\">" + ext +
           "<rgb name=\"eta\" value=\"" + std::to_string(eta) + "\"/><rgb name=\"k\" value=\"" +
           std::to_string(k) + "\"/></bsdf></shape>";
  };
  expect_upgrade(conductor("<float name=\"extEta\" value=\"1\"/>", 0.2, 3.0),
                 conductor("", 0.2, 3.0), "extEta");
  expect_upgrade(conductor("<float name=\"extEta\" value=\"2\"/>", 0.5, 3.0),
                 conductor("", 0.25, 1.5), "extEta");
  std::filesystem::path dir = fresh_dir();
  std::string named =
      write_file(dir, "named.xml",
                 scene_text("0.6.0",
                            "<shape type=\"sphere\"><bsdf type=\"conductor\">\n<float "
                            "name=\"extEta\" value=\"1.5\"/><string name=\"material\" "
                            "value=\"Au\"/></bsdf></shape>"));
  EXPECT_EQ(error_of(named),
            ":6: extEta 1.5 of <bsdf type=\"conductor\"> is not supported: Mitsuba 0.6 divides eta "
            "and k by it, which twinray does only for a positive extEta with eta and k given as "
            "numbers or colours");
}

}  // namespace
}  // namespace tr
