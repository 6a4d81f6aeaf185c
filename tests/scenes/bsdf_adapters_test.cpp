// Loading of Mitsuba 3.8's BSDF adapters (src/bsdfs/blendbsdf.cpp, normalmap.cpp, bumpmap.cpp): the
// records they build and the scenes Mitsuba refuses.
#include <gtest/gtest.h>

#include "core/bsdf/common.h"
#include "core/material_slots.h"
#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

Scene load_bsdf(const std::string& bsdf) {
  std::filesystem::path dir = fresh_dir();
  return load_scene(
      write_file(dir, "scene.xml", scene_xml("<shape type=\"sphere\">" + bsdf + "</shape>")), {});
}

std::string error_of(const std::string& bsdf) {
  try {
    load_bsdf(bsdf);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError for:\n" << bsdf;
  return "";
}

const Material& shape_material(const Scene& s) {
  return s.buffers.materials[s.buffers.shapes[0].material];
}

const Material& child(const Scene& s, const Material& blend, uint slot) {
  return s.buffers.materials[uint(blend.param[slot].value.x)];
}

const std::string kDiffuse = "<bsdf type=\"diffuse\"/>";
const std::string kConductor = "<bsdf type=\"conductor\"/>";

TEST(BlendBsdf, ChildrenInOrderAndScalarWeight) {
  Scene s = load_bsdf("<bsdf type=\"blendbsdf\"><rgb name=\"weight\" value=\"0.1, 0.2, 0.6\"/>" +
                      kDiffuse + kConductor + "</bsdf>");
  const Material& m = shape_material(s);
  ASSERT_EQ(m.type, BSDF_BLEND);
  EXPECT_EQ(child(s, m, BLEND_BSDF_0).type, BSDF_DIFFUSE);
  EXPECT_EQ(child(s, m, BLEND_BSDF_1).type, BSDF_CONDUCTOR);
  EXPECT_EQ(m.lobes, BSDF_DIFFUSE_REFLECTION | BSDF_DELTA_REFLECTION);
  // eval_1 of a constant color is its channel mean.
  EXPECT_FLOAT_EQ(m.param[BLEND_WEIGHT].value.x, 0.3f);
  EXPECT_EQ(m.param[BLEND_WEIGHT].texture, NO_INDEX);
}

TEST(BlendBsdf, TexturedWeightAndNesting) {
  Scene s = load_bsdf(
      "<bsdf type=\"twosided\"><bsdf type=\"blendbsdf\"><texture name=\"weight\" "
      "type=\"checkerboard\"/><bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.25\"/>" +
      kDiffuse + kConductor + "</bsdf>" + kDiffuse + "</bsdf></bsdf>");
  const Material& m = shape_material(s);
  ASSERT_EQ(m.type, BSDF_BLEND);
  EXPECT_NE(m.flags & MATERIAL_TWOSIDED, 0u);
  EXPECT_NE(m.param[BLEND_WEIGHT].texture, NO_INDEX);
  const Material& inner = child(s, m, BLEND_BSDF_0);
  ASSERT_EQ(inner.type, BSDF_BLEND);
  EXPECT_FLOAT_EQ(inner.param[BLEND_WEIGHT].value.x, 0.25f);
  EXPECT_EQ(child(s, inner, BLEND_BSDF_1).type, BSDF_CONDUCTOR);
  // Mitsuba's m_flags, whatever the weights: the union down the tree.
  EXPECT_EQ(inner.lobes, BSDF_DIFFUSE_REFLECTION | BSDF_DELTA_REFLECTION);
  EXPECT_EQ(m.lobes, BSDF_DIFFUSE_REFLECTION | BSDF_DELTA_REFLECTION);
}

TEST(BlendBsdf, LobesOfMaskedAndTransmittingLeaves) {
  Scene s = load_bsdf(
      "<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0\"/><bsdf type=\"mask\">" +
      kDiffuse + "</bsdf><bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"1\"/>" +
      kConductor + "<bsdf type=\"roughdielectric\"/></bsdf></bsdf>");
  EXPECT_EQ(shape_material(s).lobes, BSDF_DIFFUSE_REFLECTION | BSDF_NULL | BSDF_DELTA_REFLECTION |
                                         BSDF_GLOSSY_REFLECTION | BSDF_GLOSSY_TRANSMISSION);
}

TEST(BlendBsdf, MitsubaRefusals) {
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + kDiffuse +
                     "</bsdf>")
                .find("takes exactly two nested BSDFs (it has 1)"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + kDiffuse +
                     kDiffuse + kConductor + "</bsdf>")
                .find("takes exactly two nested BSDFs (it has 3)"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\">" + kDiffuse + kConductor + "</bsdf>")
                .find("needs a 'weight'"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>"
                     "<float name=\"wieght\" value=\"0.5\"/>" +
                     kDiffuse + kConductor + "</bsdf>")
                .find("wieght"),
            std::string::npos);
  // twosided refuses a transmitting child anywhere below it (Mitsuba: the blend's flags).
  EXPECT_NE(error_of("<bsdf type=\"twosided\"><bsdf type=\"blendbsdf\"><float name=\"weight\" "
                     "value=\"0.5\"/><bsdf type=\"dielectric\"/>" +
                     kDiffuse + "</bsdf></bsdf>")
                .find("allow_transmission"),
            std::string::npos);
}

TEST(BlendBsdf, LimitsOfTheRepresentation) {
  EXPECT_NE(error_of("<bsdf type=\"mask\"><bsdf type=\"blendbsdf\"><float name=\"weight\" "
                     "value=\"0.5\"/>" +
                     kDiffuse + kConductor + "</bsdf></bsdf>")
                .find("around a blendbsdf is not supported"),
            std::string::npos);
  auto nested = [](uint levels) {
    std::string xml = kDiffuse;
    for (uint i = 0; i < levels; ++i)
      xml = "<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + xml + kDiffuse +
            "</bsdf>";
    return xml;
  };
  EXPECT_EQ(load_bsdf(nested(BLEND_MAX_DEPTH)).buffers.materials.size(), 2u * BLEND_MAX_DEPTH + 1u);
  EXPECT_NE(error_of(nested(BLEND_MAX_DEPTH + 1u)).find("nested more than 7 deep"),
            std::string::npos);
}

const std::string kNormal = "<rgb name=\"normalmap\" value=\"0.6, 0.4, 0.9\"/>";

TEST(NormalMap, DefaultsAndOptions) {
  Scene d = load_bsdf("<bsdf type=\"normalmap\">" + kNormal + kDiffuse + "</bsdf>");
  const Material& m = shape_material(d);
  ASSERT_EQ(m.type, BSDF_NORMALMAP);
  EXPECT_EQ(child(d, m, NORMALMAP_BSDF).type, BSDF_DIFFUSE);
  // An RGB texture read by eval_3: the color itself, not its mean.
  EXPECT_FLOAT_EQ(m.param[NORMALMAP_NORMALMAP].value.x, 0.6f);
  EXPECT_FLOAT_EQ(m.param[NORMALMAP_NORMALMAP].value.z, 0.9f);
  // flip_invalid_normals and use_shadowing_function default to true (Mitsuba 3.8).
  EXPECT_EQ(m.param[NORMALMAP_OPTIONS].value.x, 1.0f);
  EXPECT_EQ(m.param[NORMALMAP_OPTIONS].value.y, 1.0f);
  Scene o = load_bsdf(
      "<bsdf type=\"normalmap\"><boolean name=\"flip_invalid_normals\" value=\"false\"/>"
      "<boolean name=\"use_shadowing_function\" value=\"false\"/>" +
      kNormal + kDiffuse + "</bsdf>");
  EXPECT_EQ(shape_material(o).param[NORMALMAP_OPTIONS].value.x, 0.0f);
  EXPECT_EQ(shape_material(o).param[NORMALMAP_OPTIONS].value.y, 0.0f);
  Scene t = load_bsdf("<bsdf type=\"twosided\"><bsdf type=\"normalmap\">" + kNormal +
                      "<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + kDiffuse +
                      kConductor + "</bsdf></bsdf></bsdf>");
  EXPECT_NE(shape_material(t).flags & MATERIAL_TWOSIDED, 0u);
  EXPECT_EQ(child(t, shape_material(t), NORMALMAP_BSDF).type, BSDF_BLEND);
}

TEST(NormalMap, RefusalsAndLimits) {
  EXPECT_NE(
      error_of("<bsdf type=\"normalmap\">" + kDiffuse + "</bsdf>").find("needs a 'normalmap'"),
      std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"normalmap\">" + kNormal + "</bsdf>")
                .find("takes exactly one nested BSDF (it has 0)"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"normalmap\">" + kNormal + kDiffuse + kConductor + "</bsdf>")
                .find("takes exactly one nested BSDF (it has 2)"),
            std::string::npos);
  const std::string normalmap = "<bsdf type=\"normalmap\">" + kNormal + kDiffuse + "</bsdf>";
  EXPECT_NE(error_of("<bsdf type=\"normalmap\">" + kNormal + normalmap + "</bsdf>")
                .find("a normalmap or bumpmap inside a normalmap is not supported"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + normalmap +
                     kDiffuse + "</bsdf>")
                .find("a normalmap inside a blendbsdf is not supported"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"mask\">" + normalmap + "</bsdf>")
                .find("around a normalmap is not supported"),
            std::string::npos);
}

const std::string kHeight =
    "<texture name=\"any_name\" type=\"bitmap\"><string name=\"filename\" "
    "value=\"" TWINRAY_SOURCE_DIR
    "/validation/mitsuba/plugins/bumpmap_height.png\"/>"
    "<boolean name=\"raw\" value=\"true\"/></texture>";

TEST(BumpMap, DefaultsAndOptions) {
  Scene d = load_bsdf("<bsdf type=\"bumpmap\">" + kHeight + kDiffuse + "</bsdf>");
  const Material& m = shape_material(d);
  ASSERT_EQ(m.type, BSDF_BUMPMAP);
  EXPECT_EQ(child(d, m, BUMPMAP_BSDF).type, BSDF_DIFFUSE);
  ASSERT_NE(m.param[BUMPMAP_HEIGHT].texture, NO_INDEX);
  EXPECT_EQ(d.buffers.textures[m.param[BUMPMAP_HEIGHT].texture].width, 16u);
  // flip_invalid_normals, use_shadowing_function true and scale 1 (Mitsuba 3.8).
  EXPECT_EQ(m.param[BUMPMAP_OPTIONS].value, vec3(1.0f, 1.0f, 1.0f));
  Scene o = load_bsdf(
      "<bsdf type=\"twosided\"><bsdf type=\"bumpmap\"><float name=\"scale\" value=\"-0.25\"/>"
      "<boolean name=\"flip_invalid_normals\" value=\"false\"/>"
      "<boolean name=\"use_shadowing_function\" value=\"false\"/>" +
      kHeight + kConductor + "</bsdf></bsdf>");
  EXPECT_EQ(shape_material(o).param[BUMPMAP_OPTIONS].value, vec3(0.0f, 0.0f, -0.25f));
  EXPECT_NE(shape_material(o).flags & MATERIAL_TWOSIDED, 0u);
}

TEST(BumpMap, RefusalsAndLimits) {
  auto refused = [](const std::string& bsdf, const std::string& words) {
    std::string e = error_of(bsdf);
    EXPECT_NE(e.find(words), std::string::npos) << e;
  };
  refused("<bsdf type=\"bumpmap\">" + kDiffuse + "</bsdf>",
          "takes exactly one nested texture (it has 0)");
  const std::string second = "<texture name=\"second\" type=\"checkerboard\"/>";
  refused("<bsdf type=\"bumpmap\">" + kHeight + second + kDiffuse + "</bsdf>",
          "takes exactly one nested texture (it has 2)");
  refused("<bsdf type=\"bumpmap\">" + kHeight + "</bsdf>",
          "takes exactly one nested BSDF (it has 0)");
  refused("<bsdf type=\"bumpmap\">" + kHeight + kDiffuse + kConductor + "</bsdf>",
          "takes exactly one nested BSDF (it has 2)");
  // Mitsuba 3.8 implements eval_1_grad for bitmap only (checkerboard: NotImplementedError).
  refused("<bsdf type=\"bumpmap\"><texture type=\"checkerboard\"/>" + kDiffuse + "</bsdf>",
          "has no uv gradient");
  refused("<bsdf type=\"bumpmap\"><float name=\"height\" value=\"1\"/>" + kDiffuse + "</bsdf>",
          "takes exactly one nested texture (it has 0)");
  const std::string bumpmap = "<bsdf type=\"bumpmap\">" + kHeight + kDiffuse + "</bsdf>";
  refused("<bsdf type=\"bumpmap\">" + kHeight + bumpmap + "</bsdf>",
          "a normalmap or bumpmap inside a bumpmap is not supported");
  refused("<bsdf type=\"normalmap\">" + kNormal + bumpmap + "</bsdf>",
          "a normalmap or bumpmap inside a normalmap is not supported");
  refused("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + bumpmap + kDiffuse +
              "</bsdf>",
          "a bumpmap inside a blendbsdf is not supported");
  refused("<bsdf type=\"mask\">" + bumpmap + "</bsdf>", "around a bumpmap is not supported");
  refused(
      "<bsdf type=\"bumpmap\"><float name=\"scael\" value=\"2\"/>" + kHeight + kDiffuse + "</bsdf>",
      "unused parameter 'scael'");
}

}  // namespace
}  // namespace tr
